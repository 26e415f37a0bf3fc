#include "evaluation/dead_reckoning.h"

#include <cmath>
#include <stdexcept>

#include "common/calibration/calibration_run.h"
#include "common/calibration/initial_state.h"
#include "common/gnss/broadcast_orbits.h"
#include "common/io/text.h"
#include "common/math/rotation.h"
#include "ekf/calibration_filter.h"
#include "ekf/gnss_update.h"
#include "ekf/single_receiver_update.h"

namespace giocal {
namespace {

DeadReckoningError errorAt(const TruthSample& dr, const TruthSample& ref) {
  const auto ecef = [](const TruthSample& s) {
    return ecefFromGeodetic({s.lat_deg * kDegToRad, s.lon_deg * kDegToRad, s.h});
  };
  DeadReckoningError e;
  e.t = ref.t;
  e.enu = rotationEcefFromEnu(ref.lat_deg * kDegToRad, ref.lon_deg * kDegToRad).transpose() *
          (ecef(dr) - ecef(ref));
  return e;
}

}  // namespace

DeadReckoning deadReckon(const CalibrationInputs& in, const ReferenceTrajectory& reference,
                         const DeadReckoningJob& job) {
  if (in.rover.epochs.empty()) throw std::runtime_error("dead reckoning: no rover epochs");
  CalibrationOptions options = job.options;
  options.hold_calibration = true;
  DatasetDescription description = in.description;
  description.initial_calibration = job.calibration;
  DeadReckoning out;
  out.t_start = in.rover.epochs.front().t + job.start_s;
  out.t_end = std::min({out.t_start + job.duration_s, in.imu.back().t, reference.end()});
  if (!(out.t_end > out.t_start)) {
    throw std::runtime_error("dead reckoning: --start +" + fixedText(job.start_s, 1) +
                             " s is at or after the end of the data or of the reference");
  }
  const std::optional<TruthSample> ref_start = reference.at(out.t_start);
  if (!ref_start) {
    throw std::runtime_error("dead reckoning: the reference trajectory has no state at --start +" +
                             fixedText(job.start_s, 1) + " s");
  }
  std::string why;
  const std::optional<InitialState> init =
      findInitialState(in, options, job.calibration, in.rover.epochs.front().t, &why);
  if (!init || init->x.t > out.t_start) {
    throw std::runtime_error(
        "dead reckoning: the GNSS-aided start that estimates the IMU biases is not found before "
        "--start +" +
        fixedText(job.start_s, 1) + " s" + (init ? "" : " (" + why + ")") +
        (init ? "; it is found at +" + fixedText(init->x.t - in.rover.epochs.front().t, 1) +
                    " s: give a later --start"
              : ""));
  }
  out.aided_s = out.t_start - init->x.t;

  CalibrationFilter filter(options, description, in.imu, *init);
  const BroadcastOrbits orbits(in.nav);
  GnssUpdate gnss(orbits, in.base_e, options);
  SingleReceiverUpdate single(orbits, options);
  BaseEpochMatcher base(in.base.epochs, options.max_base_offset);
  size_t k = 0, j = 0;
  // GNSS-aided up to the start.
  while (true) {
    const double t_odo = k < in.odom.size() ? in.odom[k].t : INFINITY;
    const double t_gnss = j < in.rover.epochs.size() ? in.rover.epochs[j].t : INFINITY;
    const double t = std::min(t_odo, t_gnss);
    if (t > out.t_start) break;
    if (t_odo <= t_gnss) {
      if (job.progress) job.progress(t);
      if (t > filter.time()) filter.updateOdometer(in.odom[k]);
      ++k;
    } else {
      const ObsEpoch& rover = in.rover.epochs[j++];
      if (rover.t < filter.time()) continue;
      if (options.loosely_coupled) {  // the LC scheme: the position solution of the epoch
        const PositionFix* fix = fixAt(in.positions, rover.t, kPositionTolerance);
        if (fix) filter.updatePosition(*fix);
        continue;
      }
      const ObsEpoch* b = options.single_receiver ? &rover : base.nearest(rover.t);
      if (b && (options.single_receiver ? single.process(filter, rover)
                                        : gnss.process(filter, rover, *b))
                   .diverged) {
        throw std::runtime_error("dead reckoning: the GNSS-aided filter diverged at t=" +
                                 timeText(rover.t) + " before the start");
      }
    }
  }
  filter.propagateTo(out.t_start);
  if (job.reference_has_attitude) {
    const NavState x0 = navStateFromRow(filter.frame(), *ref_start);
    filter.movePose(x0.p_n_b, x0.v_n_b, x0.q_n_b);
  }

  // IMU and odometer alone.
  const double step = 1.0 / options.output_rate_hz;
  double next = out.t_start, sum_sq = 0.0;
  std::optional<TruthSample> last_ref;
  std::optional<Eigen::Vector3d> error_at_start;  // job.relative_to_start
  bool past_gap = false;
  const auto emitUpTo = [&](double t) {
    for (; next <= t + 1e-9 && next <= out.t_end + 1e-9; next += step) {
      const TruthSample dr = filter.trajectorySample(std::max(next, filter.time()));
      const std::optional<TruthSample> ref = reference.at(next);
      out.trajectory.push_back(dr);
      // A relative reference's next stretch has another offset: nothing after a gap compares.
      past_gap = past_gap || (job.relative_to_start && !ref && !out.errors.empty());
      if (!ref || past_gap) continue;
      if (last_ref) out.distance_m += errorAt(*ref, *last_ref).enu.head<2>().norm();
      last_ref = ref;
      DeadReckoningError e = errorAt(dr, *ref);
      if (job.relative_to_start) {
        if (!error_at_start) error_at_start = e.enu;
        e.enu -= *error_at_start;
      }
      e.elapsed = next - out.t_start;
      e.distance = out.distance_m;
      out.errors.push_back(e);
      out.horizontal_max_m = std::max(out.horizontal_max_m, e.horizontal());
      sum_sq += e.horizontal() * e.horizontal();
    }
  };
  for (; k < in.odom.size() && in.odom[k].t <= out.t_end; ++k) {
    emitUpTo(in.odom[k].t);
    if (job.progress) job.progress(in.odom[k].t);
    if (in.odom[k].t > filter.time()) filter.updateOdometer(in.odom[k]);
  }
  filter.propagateTo(out.t_end);
  emitUpTo(out.t_end);
  if (out.errors.empty()) throw std::runtime_error("dead reckoning: no reference in the outage");
  out.horizontal_rmse_m = std::sqrt(sum_sq / static_cast<double>(out.errors.size()));
  out.final_error_m = out.errors.back().horizontal();
  out.final_error_percent_of_distance =
      out.distance_m > 0.0 ? 100.0 * out.final_error_m / out.distance_m : NAN;
  return out;
}

}  // namespace giocal
