#include "sim/multipath.h"

#include <algorithm>
#include <cmath>

namespace giocal::sim {

MultipathError Multipath::at(int receiver, const SatId& sat, char band, double t, double factor) {
  if (!spec_.enabled()) return {};
  std::normal_distribution<double> g(0.0, 1.0);
  const auto key = std::make_tuple(receiver, sat, band);
  auto it = states_.find(key);
  if (it == states_.end()) {
    it = states_.emplace(key, State{t, g(rng_), g(rng_)}).first;
  } else {
    State& s = it->second;
    const double rho = std::exp(-(t - s.t) / spec_.tau_s);
    const double kick = std::sqrt(std::max(0.0, 1.0 - rho * rho));
    s.code = rho * s.code + kick * g(rng_);
    s.phase = rho * s.phase + kick * g(rng_);
    s.t = t;
  }
  return {spec_.code_sigma * factor * it->second.code,
          spec_.phase_sigma * factor * it->second.phase};
}

}  // namespace giocal::sim
