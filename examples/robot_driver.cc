// How a robot's driver code feeds giocal's online calibrator: each sensor callback pushes its
// sample as it arrives (in any interleaving; the calibrator puts them back in time order and moves
// each sensor's stamps by the description's time_offsets), and a timer (here every 10 s of data)
// reads the calibration, its sigma and the health. With --state <file> the node keeps its
// calibration across power cycles: it starts from the file when there is one (its covariance grown
// for the time since), and writes it atomically every 10 s of data and at shutdown, so a power cut
// loses at most 10 s. Here the "drivers" are played from a dataset folder:
// robot_driver_example <dataset dir> [ekf|fgo] [--state <file>]
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>

#include "apps/prior_file.h"
#include "apps/state_file.h"
#include "common/calibration/warm_start.h"
#include "common/gnss/rinex_obs.h"
#include "common/io/sensor_logs.h"
#include "replay/estimator_factory.h"

using namespace giocal;

/// What would live in the robot's node: one calibrator, one callback per sensor.
class CalibrationNode {
 public:
  /// `state`: the file the calibration is kept in across power cycles ("": none).
  CalibrationNode(const std::string& estimator, DatasetDescription robot,
                  const Eigen::Vector3d& base_ecef, const std::string& state, double t_start)
      : state_path_(state), fingerprint_(robotFingerprint(robot)) {
    if (!state.empty()) {
      resume(robot, t_start);
      saver_.emplace(nullptr, state, 10.0, fingerprint_);
    }
    calibrator_ = makeCalibrator(estimator, robot, base_ecef, CalibrationOptions{}, FgoOptions{},
                                 saver_ ? &*saver_ : nullptr);
  }

  void onImu(const ImuSample& s) { calibrator_->addImu(s); }
  void onWheelOdometry(const OdomSample& s) { calibrator_->addOdometer(s); }
  void onRoverEpoch(const ObsEpoch& e) { calibrator_->addRover(e); }
  void onBaseEpoch(const ObsEpoch& e) { calibrator_->addBase(e); }
  void onEphemeris(const Ephemeris& e) { calibrator_->addEphemeris(e); }
  /// A whole navigation file: its ephemerides and the ionosphere parameters of its header.
  void onNavigation(const NavData& nav) { calibrator_->addNavigation(nav); }

  void onTimer() {  // e.g. publish the calibration
    const CalibratorHealth h = calibrator_->health();
    const auto c = calibrator_->calibration();
    std::printf("t=%.0f %-12s", h.t_data, stateName(h.state));
    if (c) {
      const auto sd = c->sigma();
      std::printf(" s_v %+.4f (%.4f)  s_w %+.4f (%.4f)  p_b_m %+.3f %+.3f m (%.3f %.3f)",
                  c->calib.s_v, sd[0], c->calib.s_w, sd[1], c->calib.p_b_m.x(), c->calib.p_b_m.y(),
                  sd[2], sd[3]);
    }
    std::printf("  converged %zu, buffered %zu\n", h.converged.size(), h.buffered_samples);
  }
  void onShutdown() {
    calibrator_->finish();
    const auto c = calibrator_->calibration();
    if (c && !state_path_.empty()) writeStateFile(state_path_, *c, fingerprint_);
  }

 private:
  /// The last power cycle's calibration as this drive's prior, when the state file has one.
  void resume(DatasetDescription& robot, double t_start) {
    if (!std::filesystem::exists(state_path_)) {
      std::printf("no state in %s yet: cold start\n", state_path_.c_str());
      return;
    }
    try {
      const PriorFile p = readPriorFile(state_path_);
      const std::string differs = robotMismatch(p.robot, robotFingerprint(robot));
      if (!differs.empty()) {
        std::printf("%s is another robot's (%s): cold start\n", state_path_.c_str(),
                    differs.c_str());
        return;
      }
      const double dt = std::max(0.0, t_start - p.t_final);
      robot.initial_calibration = carriedPrior(p.calibration, dt, WarmStartOptions{});
      std::printf("resumed from %s (saved %.0f s of data earlier)\n", state_path_.c_str(), dt);
    } catch (const DamagedPrior& e) {  // cut by the power: start cold rather than not at all
      std::printf("%s: cold start\n", e.what());
    }
  }

  std::string state_path_;
  std::map<std::string, double> fingerprint_;
  std::optional<StateFileSink> saver_;  // writes the state every 10 s of data
  std::unique_ptr<Calibrator> calibrator_;
};

int main(int argc, char** argv) {
  std::string estimator = "ekf", state;
  for (int k = 2; k < argc; ++k) {
    if (std::strcmp(argv[k], "--state") == 0 && k + 1 < argc) {
      state = argv[++k];
    } else {
      estimator = argv[k];
    }
  }
  if (argc < 2 || (estimator != "ekf" && estimator != "fgo")) {
    std::fprintf(stderr, "usage: robot_driver_example <dataset dir> [ekf|fgo] [--state <file>]\n");
    return 2;
  }
  try {
    const DatasetDescription d = readDatasetDescription(argv[1]);
    RinexObsReader rover(d.pathOf(d.rover_obs)), base(d.pathOf(d.base_obs));
    const Eigen::Vector3d base_e =
        d.base_position_ecef ? *d.base_position_ecef : base.header().approx_position;
    if (base_e.norm() < 6.0e6) {  // not on the Earth's surface: no position in the header
      std::fprintf(stderr,
                   "robot_driver_example: %s has no APPROX POSITION XYZ; give "
                   "gnss.base_position_ecef in dataset.yaml\n",
                   d.pathOf(d.base_obs).c_str());
      return 1;
    }
    // The drivers: the IMU drives the clock; the GNSS epochs arrive a little after their time.
    ImuLogReader imu(d.pathOf(d.imu));
    OdomLogReader odom(d.pathOf(d.odom));
    ImuSample s;
    OdomSample o;
    ObsEpoch r, b;
    bool have_s = imu.next(s), have_o = odom.next(o), have_r = rover.next(r), have_b = base.next(b);
    CalibrationNode node(estimator, d, base_e, state, have_s ? s.t : 0.0);
    for (const std::string& n : d.nav) node.onNavigation(readRinexNav(d.pathOf(n)));
    double next_timer = -1.0;
    for (; have_s; have_s = imu.next(s)) {
      node.onImu(s);
      for (; have_o && o.t <= s.t; have_o = odom.next(o)) node.onWheelOdometry(o);
      for (; have_r && r.t + 0.2 <= s.t; have_r = rover.next(r)) node.onRoverEpoch(r);
      for (; have_b && b.t + 0.3 <= s.t; have_b = base.next(b)) node.onBaseEpoch(b);
      if (s.t >= next_timer) {
        if (next_timer > 0.0) node.onTimer();
        next_timer = s.t + (next_timer > 0.0 ? 10.0 : 0.0);
      }
    }
    node.onShutdown();
    node.onTimer();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "robot_driver_example: %s\n", e.what());
    return 1;
  }
  return 0;
}
