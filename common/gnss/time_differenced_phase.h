// Time-differenced carrier phase (TDCP) of one receiver: each satellite's phase change between
// two consecutive epochs, with the satellite seen at both (one ephemeris for the pair), and the
// differences between satellites of one system and band that cancel the receiver clock's change.
// Needs no base station and no integer ambiguity: the ambiguity cancels while the phase is locked.
#pragma once

#include <Eigen/Core>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/cycle_slip.h"
#include "common/gnss/dd_epoch.h"
#include "common/gnss/ionosphere_rate.h"
#include "common/gnss/observation.h"
#include "common/gnss/weighting.h"

namespace giocal {

struct TdcpOptions {
  double elevation_mask_deg = 15.0;
  int frequencies = 2;  // bands per system, as ddBands()
  std::vector<GnssSystem> systems = defaultGnssSystems();
  // One epoch's phase noise [m]; a time difference has twice its variance. Multipath changes
  // little between epochs a second apart, so this is the thermal noise plus a margin.
  ElevationNoise phase{0.003};
  double max_interval_s = 1.5;  // a longer step between epochs starts again
  // A satellite whose phase slips in this many pairs in a row is broken (a receiver that cannot
  // track it, a multipath trap): left out from then on, and named once.
  int max_slips_in_a_row = 10;
  CycleSlipOptions slips;
  // The ionosphere's change taken out of each pair of satellites seen on two bands: its rate
  // fitted to the geometry-free phase over this span (0: not taken out), once the satellite's
  // two-band phase has run unbroken for the shorter one (IonosphereRate).
  double ionosphere_window_s = 120.0;
  double ionosphere_min_span_s = 60.0;
  // The scheme's single point positions from the ionosphere-free code where a satellite has two
  // bands (SppOptions::ionosphere_free; sppOnSkyOf).
  bool spp_ionosphere_free = true;
};

/// One satellite's phase on one band at the pair's two epochs.
struct TdcpSignal {
  SatId sat;
  char band = '1';
  double lambda = 0.0;                               // [m]
  Eigen::Vector3d sat0_e = Eigen::Vector3d::Zero();  // at the first epoch (Sagnac to its reception)
  Eigen::Vector3d sat1_e = Eigen::Vector3d::Zero();  // at the second epoch
  double sat_clock_change_m = 0.0;                   // c (dts1 - dts0)
  double tropo_change_m = 0.0;                       // modelled troposphere, second minus first
  double phase_change_m = 0.0;                       // lambda (L1 - L0)
  double variance = 0.0;                             // of phase_change_m [m^2]
  double el = 0.0;                                   // at the second epoch [rad]
};

/// One observation: signal minus the reference of its system and band (indices into signals).
struct TdcpRow {
  int signal = -1;
  int ref = -1;
};

/// Signals left out of a pair, by reason.
struct TdcpCounts {
  long long slipped = 0;     // loss of lock, geometry-free, Melbourne-Wuebbena or Doppler test
  long long half_cycle = 0;  // half-cycle ambiguity not resolved at either epoch (LLI bit 1)
  long long low = 0;         // below the elevation mask
  long long no_orbit = 0;    // no ephemeris
  long long alone = 0;       // the only signal of its system and band: nothing to difference
  long long ephemeris_changes = 0;  // kept: both epochs computed with the second's ephemeris
  long long gaps = 0;               // epoch steps longer than max_interval_s (no pair formed)
  long long clock_jumps = 0;        // receiver clock steps seen in the code (cancelled by rows)
  long long screened = 0;           // disagreed with the displacement the IMU and odometer predict
  long long broken = 0;             // phases of satellites left out for slipping in every pair
  void add(const TdcpCounts& o);
};

struct TdcpPair {
  double t0 = 0.0, t1 = 0.0;
  std::vector<TdcpSignal> signals;
  std::vector<TdcpRow> rows;
  TdcpCounts left_out;
  std::vector<SatId> slipped;  // satellites with a slipped band in this pair, named once each
};

/// The observed value of a row [m]: phase change of the signal minus that of the reference.
double tdcpObserved(const TdcpPair& pair, const TdcpRow& row);
/// The predicted value of a row [m] for antenna positions p0_e, p1_e (ECEF) at the two epochs,
/// with its gradients with respect to them. The receiver clock's change is not in it (it cancels).
double tdcpPredict(const TdcpPair& pair, const TdcpRow& row, const Eigen::Vector3d& p0_e,
                   const Eigen::Vector3d& p1_e, Eigen::RowVector3d* d_p0, Eigen::RowVector3d* d_p1);
/// Covariance of the rows: each row's own variance plus its reference's, shared by the rows
/// with that reference.
Eigen::MatrixXd tdcpCovariance(const TdcpPair& pair);

/// (Re)forms a pair's rows from its signals: a reference per system and band (the highest),
/// the others differenced against it. Returns the number of groups with a single signal.
int formRows(TdcpPair& pair);

/// Leaves out the signal of row `row` (a gate's worst) and re-forms the rows; with fewer than
/// three rows left the pair keeps none (too few to tell a bad one).
void dropRowSignal(TdcpPair& pair, long row);

/// Leaves out the signals whose phase change disagrees with the range change the antenna
/// positions p0_e, p1_e (an estimator's prediction, with `predicted_sigma_m` the uncertainty of
/// its displacement) give, after the clock change common to the signal's system and band (their
/// median) is taken out: more than `gate` times the combined sigma. Re-forms the rows; returns
/// the number left out (counted in left_out.screened). A slip the loss-of-lock flag and the
/// combinations missed is caught here, in this pair only.
int screenTdcp(TdcpPair& pair, const Eigen::Vector3d& p0_e, const Eigen::Vector3d& p1_e,
               double predicted_sigma_m, double gate);

/// The warning naming a satellite left out for good (TdcpBuilder::takeNewlyBroken) at time t.
std::string brokenSatelliteWarning(const SatId& sat, int slips_in_a_row, double t);

/// Forms the pair of each epoch with the one before it.
class TdcpBuilder {
 public:
  TdcpBuilder(const BroadcastOrbits& orbits, const TdcpOptions& options = {});
  /// The pair of `epoch` with the previous epoch (no rows for the first epoch and after a gap).
  /// rover_e: the antenna's approximate ECEF position at `epoch` (metres are enough: an error of
  /// 10 m changes a row by about 1 mm over one second).
  TdcpPair add(const ObsEpoch& epoch, const Eigen::Vector3d& rover_e);
  const TdcpCounts& totals() const { return totals_; }
  /// Satellites left out for good (max_slips_in_a_row) since the last call, to be named once.
  std::vector<SatId> takeNewlyBroken();

 private:
  const BroadcastOrbits& orbits_;
  TdcpOptions options_;
  CycleSlipDetector slips_;
  IonosphereRate ionosphere_;
  ObsEpoch previous_;
  Eigen::Vector3d previous_e_ = Eigen::Vector3d::Zero();
  bool has_previous_ = false;
  TdcpCounts totals_;
  std::map<SatId, int> slips_in_a_row_;
  std::set<SatId> broken_;
  std::vector<SatId> newly_broken_;
};

}  // namespace giocal
