// Multipath: a slowly varying code and phase error per receiver, satellite and band, each a
// first-order Gauss-Markov process, so that residuals are correlated from epoch to epoch as real
// receivers' are (docs/results.md: real DD code residuals 0.55-0.94 correlated at 1 s).
#pragma once

#include <cstdint>
#include <map>
#include <random>
#include <tuple>

#include "common/gnss/satellite.h"

namespace giocal::sim {

struct MultipathSpec {
  double code_sigma = 0.0;   // stationary sigma at the zenith [m]; 0: none
  double phase_sigma = 0.0;  // [m]
  double tau_s = 30.0;       // correlation time [s]
  bool enabled() const { return code_sigma > 0.0 || phase_sigma > 0.0; }
};

struct MultipathError {
  double code = 0.0, phase = 0.0;  // [m]
};

class Multipath {
 public:
  /// `seed`: the processes draw from their own generator, so that turning them on leaves every
  /// other draw of a dataset as it was.
  Multipath(const MultipathSpec& spec, std::uint64_t seed) : spec_(spec), rng_(seed) {}
  /// The error of (receiver, satellite, band) at time t, the sigmas scaled by `factor` (the white
  /// noise's elevation factor). A signal first seen, or seen again after many correlation
  /// times, starts from the stationary distribution; otherwise the process moves on from where
  /// it was by exp(-dt / tau).
  MultipathError at(int receiver, const SatId& sat, char band, double t, double factor);

 private:
  struct State {
    double t = 0.0, code = 0.0, phase = 0.0;  // unit-variance processes
  };
  MultipathSpec spec_;
  std::mt19937_64 rng_;
  std::map<std::tuple<int, SatId, char>, State> states_;
};

}  // namespace giocal::sim
