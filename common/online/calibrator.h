// Calibrator: the online calibrator a robot feeds as data arrive (IMU, odometer, rover and base
// GNSS epochs, ephemerides, in any interleaving) and reads at any time (calibration with its
// covariance, navigation state, health). It puts the sensors back in time order, initializes,
// and hands events to one EstimatorCore (EKF or factor graph); memory stays bounded.
//
// Threading: a Calibrator is not thread-safe. Call all its functions from one thread; the
// estimation runs inside whichever add*() releases the data it waits for (usually addImu), and a
// RunSink's callbacks run on that thread too. A robot whose sensor callbacks run on several
// threads, or that must keep its IMU callback light, puts a CalibratorQueue in front of it
// (common/online/calibrator_queue.h: enqueue only, estimation on a thread of the robot's choice).
#pragma once

#include <array>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/calibration/calibration_inputs.h"
#include "common/calibration/calibration_options.h"
#include "common/calibration/calibration_run.h"
#include "common/calibration/initial_state.h"
#include "common/calibration/odometer_delay.h"
#include "common/containers/ring_queue.h"
#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/phase_alignment.h"
#include "common/gnss/tdcp_track.h"
#include "common/online/busy_timer.h"
#include "common/online/convergence.h"
#include "common/online/estimator_core.h"
#include "common/online/latency_histogram.h"
#include "common/online/reorder_buffer.h"
#include "common/online/run_sink.h"

namespace giocal {

/// Makes the estimator once an initial state is found (again after a divergence). `sensors`
/// holds the buffered IMU and odometer samples and the dataset description with the prior in
/// effect; it and `orbits` outlive the core.
using CoreFactory = std::function<std::unique_ptr<EstimatorCore>(
    const CalibrationInputs& sensors, const BroadcastOrbits& orbits, const InitialState& init)>;

enum class CalibratorState { kInitializing, kCalibrating, kConverged, kDiverged };
const char* stateName(CalibratorState s);

struct CalibratorHealth {
  CalibratorState state = CalibratorState::kInitializing;
  double t_data = 0.0;                 // newest datum received [s]
  std::vector<std::string> converged;  // parameters that have converged
  std::vector<std::string> weak;       // parameters the data have barely informed so far
  CounterMap counters;
  size_t buffered_samples = 0;  // IMU + odometer samples held
  size_t pending_epochs = 0;    // rover epochs waiting
};

class Calibrator {
 public:
  /// `dataset`: sensor noise, lever arm, the calibration prior; `base_e`: base position (ECEF).
  /// `sink` (may be null) receives estimates, trajectory samples and live events.
  Calibrator(std::string estimator, const DatasetDescription& dataset,
             const Eigen::Vector3d& base_e, const CalibrationOptions& options, CoreFactory factory,
             RunSink* sink);
  // The estimator cores hold references into the calibrator's buffers: neither copied nor moved
  // (hold it by std::unique_ptr, as makeCalibrator returns it).
  Calibrator(const Calibrator&) = delete;
  Calibrator& operator=(const Calibrator&) = delete;
  Calibrator(Calibrator&&) = delete;
  Calibrator& operator=(Calibrator&&) = delete;

  /// IMU, odometer and position times are moved by the dataset's time_offsets here (the one
  /// place they are applied, for a replay and a robot alike).
  void addImu(const ImuSample& s);
  void addOdometer(const OdomSample& s);
  void addRover(const ObsEpoch& e);
  void addBase(const ObsEpoch& e);
  /// An antenna position solution (the LC scheme, options.loosely_coupled): used at the rover
  /// epoch of the same time instead of that epoch's double differences.
  void addPosition(const PositionFix& p);
  void addEphemeris(const Ephemeris& e);
  /// A navigation file's worth: its ephemerides and ionosphere parameters.
  void addNavigation(const NavData& nav);
  /// No more data: drains the buffers, finishes the run (weak directions, timing). Throws
  /// std::runtime_error if no initial state was ever found (the message says why).
  void finish();

  std::optional<CalibrationEstimate> calibration() const { return run_.latest; }
  /// The navigation state in the local frame n: east-north-up at navOriginEcef(), which is set
  /// at each (re-)initialization; nullopt before the first.
  std::optional<NavState> navState() const;
  /// The origin of navState()'s frame n (ECEF, m); zero before the first initialization.
  Eigen::Vector3d navOriginEcef() const { return origin_e_; }
  CalibratorHealth health() const;
  const CalibrationRun& run() const { return run_; }

 private:
  enum class Kind { kImu, kOdometer, kRover, kBase, kPosition };
  struct Datum {
    Kind kind;
    ImuSample imu;
    OdomSample odom;
    ObsEpoch obs;
    PositionFix position;
  };
  void push(double t, Datum d);
  /// A receiver's epoch into the buffer, its phases aligned first (PhaseAlignment::stream).
  void pushEpoch(Kind kind, const ObsEpoch& e);
  /// Into the reorder buffer (the datum's time is believed).
  void admit(double t, Datum d);
  void release(Datum& d);
  void acceptRover(ObsEpoch e);
  /// The LC scheme on a dataset without raw GNSS: the position solutions stand for the epochs.
  bool positionsOnly() const { return options_.loosely_coupled && dataset_.rover_obs.empty(); }
  void process();
  bool tryInitialize();
  bool ready(double t) const;
  void dispatchOdometer(const OdomSample& s);
  void dispatchRover(const ObsEpoch& rover);
  void onEstimate(const CalibrationEstimate& e);
  void trim();
  void say(double t, const std::string& text);
  /// Hands something to the sink (if any), its time counted apart from the calibrator's.
  template <class F>
  void toSink(F&& f) {
    if (!sink_) return;
    BusyTimer timer(sink_s_);
    f(*sink_);
  }
  void dropped(Counter c, double t, const std::string& what);
  /// Counts c and names the first occurrence in a warning (data kept, unlike dropped()).
  void noted(Counter c, const std::string& what);
  /// An IMU gap [t0, t1] too long to bridge: events before it are finished, the estimator ends,
  /// and initialization starts again at t1 with the calibration (and covariance) carried over.
  void restartAfterGap(double t0, double t1);
  /// A warning when more than a fifth of the GNSS epochs (LC: fixes) updated nothing.
  void warnAboutUnusedGnss();
  /// The single-receiver scheme: a kind of GNSS row the run never had is named.
  void warnAboutSingleReceiverRows();
  const ObsEpoch* nearestBase(double t) const;
  double rel(double t) const { return t - t_first_; }

  CalibrationOptions options_;
  DatasetDescription original_;  // as given: the prior the weak-direction check compares with
  DatasetDescription dataset_;   // with the prior in effect (re-initialization replaces it)
  Eigen::Vector3d origin_e_ = Eigen::Vector3d::Zero();  // of the core's local frame n
  CoreFactory factory_;
  RunSink* sink_;
  CalibrationRun run_;
  ReorderBuffer<Datum> reorder_;
  CalibrationInputs buf_;  // buffered samples and ephemerides (bounded)
  std::unique_ptr<BroadcastOrbits> orbits_;
  std::unique_ptr<TdcpTrack> track_;  // the single-receiver scheme's track for the initial state
  RingQueue<ObsEpoch> rover_;         // rover epochs not yet processed
  // Each receiver's phases of one band checked for alignment as they come (a file's reader has
  // done it for the whole file; a driver's raw epochs have not).
  PhaseAlignment rover_phases_, base_phases_;
  size_t rover_phases_said_ = 0, base_phases_said_ = 0;  // warnings already in the run's
  std::unique_ptr<EstimatorCore> core_;
  ConvergenceMonitor convergence_;
  std::optional<CalibrationEstimate> core_estimate_;  // the present core's previous estimate
  OdometerDelayEstimator odometer_delay_;  // checks the odometer's stamps against the IMU's
  bool diverged_ = false, finishing_ = false, done_said_ = false;
  double t_first_ = NAN, frontier_ = -INFINITY;
  double t_from_ = -INFINITY;          // initialization searches from here
  double last_init_try_ = -INFINITY;   // newest rover epoch time the last attempt could use
  double last_odo_event_ = -INFINITY;  // newest odometer sample handed to the core
  double imu_silent_since_ = NAN;      // warned once per silence
  double next_progress_ = NAN;
  std::string why_not_initialized_;
  InitialRtkCache init_cache_;           // RTK solutions between initialization attempts
  double skip_rover_until_ = -INFINITY;  // the epoch that diverged is not processed again
  double flush_until_ = -INFINITY;       // events up to here are processed whatever follows
  double t_imu_first_ = NAN, t_imu_last_ = NAN, t_rover_first_ = NAN, t_rover_last_ = NAN;
  double last_rover_t_ = -INFINITY;
  double rover_interval_ = INFINITY;  // the shortest interval between rover epochs so far [s]
  int rover_intervals_ = 0;           // intervals seen
  bool sparse_named_ = false;         // epochs further apart than gnss_gap_warning_s, named once
  LatencyHistogram latency_;
  double init_time_s_ = 0.0, busy_s_ = 0.0;
  double sink_s_ = 0.0;       // of busy_s_, spent in the sink
  std::set<Counter> warned_;  // bad-data kinds already named in a warning
  // Per sensor (Kind), a datum far ahead of all others, held until its sensor's next one.
  std::array<std::optional<std::pair<double, Datum>>, 5> ahead_;
  long released_ = 0;
};

}  // namespace giocal
