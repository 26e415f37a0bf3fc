#include "evaluation/observability.h"

#include <cmath>
#include <stdexcept>

#include "common/calibration/calibration_run.h"
#include "common/calibration/initial_state.h"
#include "common/calibration/weak_directions.h"
#include "common/gnss/fixed_phase_covariance.h"
#include "common/io/text.h"
#include "common/math/rotation.h"
#include "common/models/state_block.h"
#include "ekf/calibration_filter.h"
#include "ekf/imu_propagation.h"
#include "ekf/single_receiver_update.h"
#include "evaluation/ideal_imu.h"

namespace giocal {
namespace {

using Vec8 = Eigen::Matrix<double, 8, 1>;

/// One run of the covariance recursion along the drive.
struct Pass {
  std::vector<CalibrationEstimate> at_window_end;
  CalibrationEstimate final;
  Vec8 heading_correlation = Vec8::Zero();  // of each calibration tangent with the IMU heading
  double t_first = 0.0;                     // first rover epoch
};

/// Holds the filter's linearization point on the reference and the calibration on linearize_at:
/// the covariance is then the one of a filter that knew them (the information the drive holds),
/// not of one linearized at its own errors.
void pinToReference(CalibrationFilter& f, const ObservabilityJob& job) {
  const std::optional<TruthSample> ref = job.reference->at(f.time());
  if (!ref) return;
  const NavState x = navStateFromRow(f.frame(), *ref);
  f.movePose(x.p_n_b, x.v_n_b, x.q_n_b);
  StateRegistry& s = f.state();
  const OdometerCalibration& c = job.linearize_at;
  s.value(state::kSv)[0] = c.s_v;
  s.value(state::kSw)[0] = c.s_w;
  s.value(state::kPbm) = c.p_b_m;
  s.value(state::kQbm) << c.q_b_m.w(), c.q_b_m.x(), c.q_b_m.y(), c.q_b_m.z();
}

Vec8 headingCorrelation(const CalibrationFilter& f) {
  const StateRegistry& s = f.state();
  const Eigen::MatrixXd& P = s.covariance();
  // The heading error (about n's vertical) of a right-multiplied attitude error dtheta_b.
  Eigen::RowVectorXd h = Eigen::RowVectorXd::Zero(s.dim());
  h.segment<3>(s.offset(state::kQ)) = f.nav().q_n_b.toRotationMatrix().row(2);
  const std::array<int, 8> idx = {s.offset(state::kSv),      s.offset(state::kSw),
                                  s.offset(state::kPbm),     s.offset(state::kPbm) + 1,
                                  s.offset(state::kPbm) + 2, s.offset(state::kQbm),
                                  s.offset(state::kQbm) + 1, s.offset(state::kQbm) + 2};
  const Eigen::VectorXd Ph = P * h.transpose();
  const double var_h = h.dot(Ph);
  Vec8 r = Vec8::Zero();
  for (int k = 0; k < 8; ++k) {
    const double d = std::sqrt(var_h * P(idx[k], idx[k]));
    r[k] = d > 0.0 ? Ph[idx[k]] / d : 0.0;
  }
  return r;
}

Pass runPass(const CalibrationInputs& in, const ObservabilityJob& job,
             const CalibrationOptions& options) {
  DatasetDescription description = in.description;
  description.initial_calibration.mean = job.linearize_at;
  std::string why;
  const std::optional<InitialState> init = findInitialState(
      in, options, description.initial_calibration, in.rover.epochs.front().t, &why);
  if (!init) throw std::runtime_error("observability: no initial state: " + why);
  CalibrationFilter filter(options, description, in.imu, *init);
  const BroadcastOrbits orbits(in.nav);
  SingleReceiverUpdate single(orbits, options);
  Pass pass;
  pass.t_first = in.rover.epochs.front().t;
  double next_end = pass.t_first + job.window_s;
  const auto step = [&] {
    if (job.reference) pinToReference(filter, job);
    for (; next_end <= filter.time(); next_end += job.window_s) {
      pass.at_window_end.push_back(filter.calibration());
    }
  };
  size_t k = 0, j = 0;
  while (k < in.odom.size() || j < in.rover.epochs.size()) {
    const double t_odo = k < in.odom.size() ? in.odom[k].t : INFINITY;
    const double t_gnss = j < in.rover.epochs.size() ? in.rover.epochs[j].t : INFINITY;
    if (t_odo <= t_gnss) {
      if (t_odo > filter.time()) filter.updateOdometer(in.odom[k]);
      ++k;
    } else if (options.single_receiver) {
      if (t_gnss >= filter.time()) single.process(filter, in.rover.epochs[j]);
      ++j;
    } else {
      const PositionFix* fix = fixAt(in.positions, t_gnss, kPositionTolerance);
      if (fix && t_gnss >= filter.time()) filter.updatePosition(*fix);
      ++j;
    }
    step();
  }
  if (pass.at_window_end.empty() || filter.time() > pass.at_window_end.back().t + 1e-6) {
    pass.at_window_end.push_back(filter.calibration());
  }
  pass.final = filter.calibration();
  pass.heading_correlation = headingCorrelation(filter);
  return pass;
}

/// From 1 s means of the odometer: sample by sample its noise would add up.
DriveMotion motionBetween(const std::vector<OdomSample>& odom, double t0, double t1) {
  DriveMotion m;
  m.duration_s = t1 - t0;
  double sum_v = 0.0, sum_w = 0.0, last_v = NAN, bin_end = t0 + 1.0;
  int n = 0;
  const auto closeBin = [&] {
    if (n == 0) return;
    const double v = sum_v / n, w = sum_w / n;
    m.distance_m += std::abs(v);
    (w > 0.0 ? m.turned_left_deg : m.turned_right_deg) += std::abs(w) * kRadToDeg;
    if (!std::isnan(last_v)) m.speed_change_m_s += std::abs(v - last_v);
    if (std::abs(v) < 0.02 && std::abs(w) < 0.02) m.still_s += 1.0;
    last_v = v, sum_v = sum_w = 0.0, n = 0;
  };
  for (const OdomSample& o : odom) {
    if (o.t < t0 || o.t >= t1) continue;
    for (; o.t >= bin_end; bin_end += 1.0) closeBin();
    sum_v += o.v, sum_w += o.w, ++n;
  }
  closeBin();
  return m;
}

/// Calibration states whose tangent correlation exceeds `threshold`, named.
std::vector<std::string> couplingsOf(const Pass& p, double threshold) {
  std::vector<std::string> out;
  const Eigen::Matrix<double, 8, 8>& C = p.final.cov;
  for (int a = 0; a < 8; ++a) {
    if (std::abs(p.heading_correlation[a]) >= threshold) {
      out.push_back(std::string(calibrationStateName(a)) + " vs IMU heading (correlation " +
                    fixedText(p.heading_correlation[a], 2) + ")");
    }
    for (int b = a + 1; b < 8; ++b) {
      const double d = std::sqrt(C(a, a) * C(b, b));
      const double r = d > 0.0 ? C(a, b) / d : 0.0;
      if (std::abs(r) >= threshold) {
        out.push_back(std::string(calibrationStateName(a)) + " vs " + calibrationStateName(b) +
                      " (correlation " + fixedText(r, 2) + ")");
      }
    }
  }
  return out;
}

std::vector<std::string> adviceFor(const ObservabilityReport& r) {
  std::vector<std::string> advice;
  for (int k : r.weak) {
    if (*motionThatInforms(k))
      advice.push_back(std::string(calibrationStateName(k)) + ": " + motionThatInforms(k));
  }
  if (r.p_b_m_z_assessed && !r.p_b_m_z_observable) {
    advice.push_back(std::string(calibrationStateName(r.vertical_state)) +
                     " (along the vehicle's vertical): unobservable on this drive (planar "
                     "motion: the vehicle neither rolls nor pitches enough); slopes and ramps "
                     "would inform it, otherwise it stays at the guess "
                     "(calibration.hold_p_b_m_z)");
  }
  const DriveMotion& m = r.total;
  const double turned = m.turned_left_deg + m.turned_right_deg;
  if (!r.weak.empty() && turned > 90.0 &&
      std::min(m.turned_left_deg, m.turned_right_deg) < 0.1 * turned) {
    advice.push_back("the drive turns " +
                     std::string(m.turned_left_deg > m.turned_right_deg ? "left" : "right") +
                     " only: turns the other way separate the lever arm from the yaw-rate scale");
  }
  if (!r.weak.empty() && m.still_s < 5.0) {
    advice.push_back("the drive has no stop of 5 s or more: stops pin the gyro bias");
  }
  return advice;
}

}  // namespace

namespace {

/// The antenna on the reference at t (ECEF), with the rotation from ENU there to ECEF.
std::optional<std::pair<Eigen::Vector3d, Eigen::Matrix3d>> antennaAt(
    const ReferenceTrajectory& reference, const Eigen::Vector3d& p_b_g, double t) {
  const std::optional<TruthSample> s = reference.at(t);
  if (!s) return std::nullopt;
  const double lat = s->lat_deg * kDegToRad, lon = s->lon_deg * kDegToRad;
  const Eigen::Matrix3d R_e_n = rotationEcefFromEnu(lat, lon);
  return std::make_pair(ecefFromGeodetic({lat, lon, s->h}) + R_e_n * (s->q_n_b * p_b_g), R_e_n);
}

PositionFix fixedAntenna(double t, const Eigen::Vector3d& p_e, const Eigen::Matrix3d& cov_enu) {
  PositionFix f;
  f.t = t;
  f.p_e = p_e;
  f.cov_enu = cov_enu;
  f.quality = 1;
  return f;
}

}  // namespace

std::vector<PositionFix> antennaPositionsAlong(const ReferenceTrajectory& reference,
                                               const Eigen::Vector3d& p_b_g,
                                               const std::vector<double>& times, double sigma_m) {
  std::vector<PositionFix> fixes;
  for (double t : times) {
    const auto a = antennaAt(reference, p_b_g, t);
    if (a)
      fixes.push_back(fixedAntenna(t, a->first, Eigen::Matrix3d::Identity() * sigma_m * sigma_m));
  }
  return fixes;
}

std::vector<PositionFix> antennaPositionsFromPhase(const ReferenceTrajectory& reference,
                                                   const Eigen::Vector3d& p_b_g,
                                                   const CalibrationInputs& in,
                                                   const CalibrationOptions& options) {
  const BroadcastOrbits orbits(in.nav);
  DdEpochBuilder builder(orbits, in.base_e, options.dd);
  BaseEpochMatcher base(in.base.epochs, options.max_base_offset);
  std::vector<PositionFix> fixes;
  for (const ObsEpoch& rover : in.rover.epochs) {
    const auto a = antennaAt(reference, p_b_g, rover.t);
    const ObsEpoch* nearest = base.nearest(rover.t);
    if (!a || !nearest) continue;
    const std::optional<Eigen::Matrix3d> cov_e =
        fixedPhasePositionCovariance(builder.build(rover, *nearest, a->first), a->first);
    if (cov_e)
      fixes.push_back(fixedAntenna(rover.t, a->first, a->second.transpose() * *cov_e * a->second));
  }
  return fixes;
}

ObservabilityReport analyzeObservability(const CalibrationInputs& in, const ObservabilityJob& job) {
  if (in.rover.epochs.empty()) throw std::runtime_error("observability: no GNSS epochs");
  if (!(job.window_s > 0.0)) throw std::runtime_error("observability: the window must be > 0 s");
  CalibrationOptions options = job.options;
  options.loosely_coupled = !options.single_receiver;  // else the positions of in.positions
  options.hold_calibration = false;
  // Along a reference, the IMU is the reference's own motion: the recorded samples' noise in the
  // propagation's Jacobians makes the near-unobservable heading split look observable (paper
  // preset: extrinsic yaw sigma 2.8 deg where noise-free data give 4.7 deg to the advisor and
  // both estimators alike, and the Monte Carlo's errors imply 4.6 deg; docs/results.md).
  std::optional<CalibrationInputs> ideal;
  if (job.reference) {
    ideal = in;
    ideal->imu = idealImuAlong(*job.reference, in.imu);
  }
  const CalibrationInputs& used = ideal ? *ideal : in;
  const Pass pass = runPass(used, job, options);
  CalibrationOptions free_z = options;
  free_z.hold_p_b_m_z = false;
  const Pass pass_z = runPass(used, job, free_z);

  ObservabilityReport r;
  r.linearized_at_reference = job.reference.has_value();
  const CalibrationPrior& prior = in.description.initial_calibration;
  CalibrationEstimate p0;
  p0.calib = prior.mean;
  p0.cov = priorCalibrationCovariance(prior);
  r.prior_sigma = p0.sigma();
  r.vertical_state = verticalLeverState(prior);
  r.expected_sigma = pass.final.sigma();
  // Along the vehicle's vertical (m's z in b), the direction planar motion leaves unobservable.
  const Eigen::Vector3d up_b = job.linearize_at.q_b_m * Eigen::Vector3d::UnitZ();
  r.p_b_m_z_sigma_free =
      std::sqrt(up_b.dot(pass_z.final.cov.block<3, 3>(calib_index::kP, calib_index::kP) * up_b));
  r.p_b_m_z_assessed = r.linearized_at_reference;
  r.p_b_m_z_observable = r.p_b_m_z_assessed && r.p_b_m_z_sigma_free < 0.3 * r.prior_sigma[4];
  const auto information = [](const Vec8& s) { return s.cwiseProduct(s).cwiseInverse(); };
  Vec8 before = r.prior_sigma;
  double t0 = 0.0;
  for (const CalibrationEstimate& e : pass.at_window_end) {
    ObservabilityWindow w;
    w.t0 = t0;
    w.t1 = std::min(e.t - pass.t_first, t0 + job.window_s);
    w.motion = motionBetween(in.odom, pass.t_first + w.t0, pass.t_first + w.t1);
    w.sigma = e.sigma();
    w.information =
        (information(w.sigma) - information(before)).cwiseQuotient(information(r.prior_sigma));
    r.windows.push_back(w);
    before = w.sigma;
    t0 = w.t1;
  }
  r.total = motionBetween(in.odom, in.odom.front().t, in.odom.back().t);
  // A speed-only odometer says nothing of s_w: not a weakness of the drive.
  r.weak = weakStates(pass.final, prior, heldStates(options, in.description));
  r.couplings = couplingsOf(pass, 0.7);
  r.advice = adviceFor(r);
  return r;
}

}  // namespace giocal
