// GNSS observations for the rover antenna and a static base: pseudo-range, carrier phase (an
// integer ambiguity per satellite and band), Doppler and C/N0 from broadcast orbits, with receiver
// clocks as random processes, troposphere and ionosphere with a realistic rover-base differential,
// and elevation-dependent noise. The atmosphere models here are the simulator's own, not the
// estimators', so that a modelling error in one is not hidden by the same error in the other.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/observation.h"
#include "sim/multipath.h"

namespace giocal::sim {

/// A stretch of the trajectory (by time from the start) with its own sky and signal conditions.
struct SceneSpec {
  std::string type = "open_sky";   // open_sky | few_trees | more_trees | building
  double start = 0.0, end = 1e9;   // [s] from the start of the dataset
  double block_probability = 0.0;  // chance per epoch that a satellite is shadowed, at the horizon
                                   // (falling linearly to zero at the zenith)
  std::string building_side;       // "left" or "right" of the direction of travel: that half of the
                                   // sky below `building_elevation_deg` is blocked
  double building_elevation_deg = 60.0;
  double outlier_probability = 0.0;  // NLOS/multipath pseudo-range errors, per satellite and epoch
  double outlier_m = 0.0;            // their size: uniform in [0.3, 1] times this, positive [m]
  double extra_phase_sigma = 0.0;    // added phase noise [m]
  double slip_probability = 0.0;     // cycle slips per satellite, band and epoch (half flagged LLI)
};

/// The defaults of a scene type (the four scenes of the reference paper's field test).
SceneSpec sceneDefaults(const std::string& type);

/// A signal a receiver tracks: its band and attribute, the phase-shift correction RINEX 3.01+
/// records for it (the quarter cycles its raw phase sits from the band's reference signal, added
/// to align it), and the elevation below which it is not tracked (a semi-codeless L2W low down).
struct SignalSpec {
  GnssSystem sys = GnssSystem::kGps;
  char band = '1', attr = 'C';
  double shift_cycles = 0.0;
  double min_elevation_deg = 0.0;
};

struct GnssSimSpec {
  bool enabled = false;  // set when the config has a gnss section
  std::string nav_file;  // broadcast orbits (RINEX nav), resolved to an absolute path
  std::string systems = "GEC";
  bool beidou_meo_only = false;  // drop BeiDou GEO and IGSO satellites (PRN 1-18, 31, 38-40, 56-63)
  double rate_hz = 1.0;
  double elevation_mask_deg = 10.0;
  double code_sigma = 0.3;      // at zenith; sigma(el) = s sqrt(1 + 1/sin el) [m]
  double phase_sigma = 0.003;   // [m]
  double doppler_sigma = 0.03;  // [m/s]
  MultipathSpec multipath;      // slow code and phase errors on both receivers (none by default)
  Eigen::Vector3d base_offset_enu{3000.0, 2600.0, 5.0};  // base from the origin [m] (~4 km)
  double clock_offset_sd = 1e-6;     // initial receiver clock offset, 1-sigma [s]
  double clock_drift_sd = 1e-9;      // receiver clock drift, 1-sigma [s/s]
  double clock_random_walk = 1e-11;  // [s/sqrt(s)]
  double zenith_wet_sd = 0.01;       // per-receiver zenith wet delay difference [m]
  double vtec_tecu = 15.0;           // vertical TEC at the origin [TECU]
  double vtec_gradient = 5e-7;       // relative VTEC change per metre (0.5 ppm/m: 4 km -> 0.2 %)
  std::vector<SceneSpec> scenes;     // the rover's scenes; open sky where none applies
  // gnss.base_signals: a base of another make, tracking these signals of each system it lists
  // (several on one band share the band's integer); the rover's signals where none is listed.
  std::vector<SignalSpec> base_signals;
  // gnss.base_phase_aligned: the base's file holds phases aligned to each band's reference and
  // records the corrections (SYS / PHASE SHIFT), as RINEX 3.01+ requires; 0: its raw phases, each
  // signal off by its correction, and no record (a converter that does not align).
  bool base_phase_aligned = true;
  // gnss.base: none: a rover alone, no base receiver written. Then what a single receiver meets
  // and a base would cancel is on by default (gnss_sim_config's defaults; 0 turns one off):
  bool base = true;
  double orbit_error_m = 0.0;           // broadcast orbit error per axis, 1-sigma [m]
  double orbit_error_rate = 0.0;        // its change, 1-sigma per axis [m/s]
  double sat_clock_error_m = 0.0;       // broadcast satellite clock error, 1-sigma [m]
  double sat_clock_random_walk = 0.0;   // its random walk [m/sqrt(s)]
  double sat_clock_rate_sd = 0.0;       // its short-term rate, first-order Gauss-Markov,
  double sat_clock_rate_tau_s = 10.0;   // 1-sigma [m/s] with this correlation time [s]
  double vtec_random_walk = 0.0;        // vertical TEC random walk [TECU/sqrt(s)]
  double zenith_wet_random_walk = 0.0;  // zenith wet delay random walk [m/sqrt(s)]
  double clock_step_s = 0.0;            // the receiver steps its clock by this when it is
                                        // half of it off (u-blox: 1 ms) [s]
  double half_cycle_share = 0.0;        // share of the scenes' slips that are half cycles,
                                        // flagged LLI bit 1 at the epoch
};

/// What a rover alone meets (gnss.base: none): broadcast orbit and clock errors, ionosphere,
/// troposphere and satellite clocks that drift, a u-blox-like receiver clock that steps by 1 ms,
/// and half-cycle slips. Sizes from the broadcast-ephemeris and TDCP literature; docs/design.md.
void setSingleReceiverDefaults(GnssSimSpec& spec);

/// The true antenna trajectory: ECEF position and velocity at GPS time t.
using AntennaTruth = std::function<void(double t, Eigen::Vector3d& p_e, Eigen::Vector3d& v_e)>;

struct SimulatedGnss {
  std::vector<ObsEpoch> rover, base;
  Eigen::Vector3d base_e = Eigen::Vector3d::Zero();
  /// The integer ambiguity of each (receiver 0 rover / 1 base, satellite, band) [cycles].
  std::map<std::tuple<int, SatId, char>, double> ambiguity;
  int slips = 0;        // cycle slips put into the rover's phases by scenes
  int half_cycles = 0;  // of them half-cycle slips
  int clock_steps = 0;  // receiver clock steps (clock_step_s)
  /// The signals each receiver's file holds (0 rover, 1 base), in the order it writes them.
  std::vector<SignalSpec> signals[2];
  bool base_phase_aligned = true;
};

/// Observations at t0, t0 + 1/rate, ... up to t1 (receiver time tags at whole steps).
SimulatedGnss simulateGnss(const GnssSimSpec& spec, const BroadcastOrbits& orbits,
                           const AntennaTruth& rover, const Eigen::Vector3d& base_e, double t0,
                           double t1, std::mt19937_64& rng);

/// Signals simulated per system for the rover (and a base of the same make): (band, attribute).
std::vector<std::pair<char, char>> simulatedSignals(GnssSystem sys);

/// The signals a receiver (0 rover, 1 base) tracks of system `sys`.
std::vector<SignalSpec> receiverSignals(const GnssSimSpec& spec, int receiver, GnssSystem sys);

}  // namespace giocal::sim
