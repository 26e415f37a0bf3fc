#include "ekf/ekf_calibrator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "common/calibration/initial_state.h"
#include "common/calibration/weak_directions.h"
#include "common/gnss/broadcast_orbits.h"
#include "common/math/rotation.h"
#include "ekf/calibration_filter.h"
#include "ekf/gnss_update.h"

namespace giocal {
namespace {

constexpr size_t kMaxWarnings = 20;

void warn(CalibrationRun& run, const std::string& w) {
  if (run.warnings.size() < kMaxWarnings) run.warnings.push_back(w);
  if (run.warnings.size() == kMaxWarnings) run.warnings.push_back("(further warnings omitted)");
}

std::string at(double t) {
  std::ostringstream s;
  s.precision(10);
  s << t;
  return s.str();
}

/// The longest interval between consecutive IMU samples among those overlapping (t0, t1], and
/// where it starts.
std::pair<double, double> largestGap(const std::vector<ImuSample>& imu, double t0, double t1) {
  auto it = std::upper_bound(imu.begin(), imu.end(), t0,
                             [](double v, const ImuSample& s) { return v < s.t; });
  if (it != imu.begin()) --it;
  double gap = 0.0, start = t0;
  for (; it + 1 != imu.end() && it->t < t1; ++it) {
    if ((it + 1)->t - it->t > gap) {
      gap = (it + 1)->t - it->t;
      start = it->t;
    }
  }
  return {gap, start};
}

bool finiteState(const StateRegistry& s) {
  if (!s.covariance().allFinite()) return false;
  for (const std::string& n : s.names()) {
    if (!s.value(n).allFinite()) return false;
  }
  return true;
}

/// The dataset with its calibration prior replaced by an estimate (for a re-initialization).
DatasetDescription withPrior(DatasetDescription d, const CalibrationEstimate& e) {
  CalibrationPrior& p = d.initial_calibration;
  p.mean = e.calib;
  // Keep the prior's sigma where the estimate claims more (a diverged filter is not trusted).
  p.sd_s_v = std::max(p.sd_s_v, std::sqrt(e.cov(calib_index::kSv, calib_index::kSv)));
  p.sd_s_w = std::max(p.sd_s_w, std::sqrt(e.cov(calib_index::kSw, calib_index::kSw)));
  return d;
}

}  // namespace

CalibrationRun runEkfCalibration(const CalibrationInputs& in, const CalibrationOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  CalibrationRun run;
  run.estimator = "ekf";
  run.data_duration_s = in.dataDuration();
  run.p_b_m_z = options.hold_p_b_m_z
                    ? "held at the prior (consider state): planar motion leaves it unobservable"
                    : "estimated; unobservable under planar motion, its sigma stays near the prior";
  const BroadcastOrbits orbits(in.nav);
  DatasetDescription dataset = in.description;

  std::string why;
  const auto i0 = std::chrono::steady_clock::now();
  auto init = findInitialState(in, options, dataset.initial_calibration, in.imu.front().t, &why);
  if (!init) throw std::runtime_error("could not initialize: " + why);
  run.timing["initialization_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - i0).count();
  run.t_initialized = init->x.t;
  run.initialization = {{"static_window_s", init->static_window_s},
                        {"heading_baseline_m", init->heading_baseline_m},
                        {"heading_sigma_deg", init->heading_sigma * kRadToDeg},
                        {"b_g_z_deg_h", init->x.b_g.z() * kRadToDeg * 3600.0}};
  auto filter = std::make_unique<CalibrationFilter>(options, dataset, in.imu, *init);
  auto gnss = std::make_unique<GnssUpdate>(orbits, in.base_e, options);

  const double t_end = in.imu.back().t;
  size_t k_odo = 0, k_gnss = 0;
  BaseEpochMatcher matcher(in.base.epochs, options.max_base_offset);
  double next_output = init->x.t;
  double t_prev_event = init->x.t, last_gap_start = NAN;
  double gnss_time = 0.0;
  auto& counters = run.counters;
  for (const char* c : {"odometer_intervals", "odometer_rejected", "calibration_reopened",
                        "dd_rows", "gnss_rows_rejected", "code_outliers", "ambiguity_resets",
                        "gnss_without_base", "reinitializations", "imu_gaps"}) {
    counters[c] = 0;
  }

  while (true) {
    while (k_odo < in.odom.size() && in.odom[k_odo].t <= filter->time()) ++k_odo;
    while (k_gnss < in.rover.epochs.size() && in.rover.epochs[k_gnss].t < filter->time()) ++k_gnss;
    const double t_odo = k_odo < in.odom.size() ? in.odom[k_odo].t : INFINITY;
    const double t_gnss = k_gnss < in.rover.epochs.size() ? in.rover.epochs[k_gnss].t : INFINITY;
    const double t_next = std::min(t_odo, t_gnss);
    if (!(t_next <= t_end)) break;

    const auto [gap, gap_start] = largestGap(in.imu, t_prev_event, t_next);
    t_prev_event = t_next;
    if (gap > options.max_imu_gap_s && gap_start != last_gap_start) {
      last_gap_start = gap_start;
      ++counters["imu_gaps"];
      warn(run, "IMU gap of " + at(gap) + " s after t=" + at(gap_start) +
                    ": bridged by interpolation, the covariance grows with it");
    }
    if (t_odo <= t_gnss) {
      const OdometerStep step = filter->updateOdometer(in.odom[k_odo]);
      counters["odometer_intervals"] += step.interval;
      counters["odometer_rejected"] += step.rejected;
      if (step.reopened && counters["calibration_reopened"]++ == 0) {
        warn(run, std::to_string(options.max_odometer_rejections) +
                      " odometer intervals in a row rejected by the innovation gate before t=" +
                      at(t_odo) +
                      ": the filter was more certain of its calibration than the odometer allows "
                      "(a poor initial guess, wheel slip, wrong scale or time offset); the "
                      "covariance of p_b_m and q_b_m was increased by the prior's (counter "
                      "calibration_reopened)");
      }
      ++k_odo;
    } else {
      const ObsEpoch& rover = in.rover.epochs[k_gnss];
      const ObsEpoch* base = matcher.nearest(rover.t);
      ++k_gnss;
      if (!base) {
        ++counters["gnss_without_base"];
        continue;
      }
      const auto g0 = std::chrono::steady_clock::now();
      const GnssEpochReport rep = gnss->process(*filter, rover, *base);
      gnss_time += std::chrono::duration<double>(std::chrono::steady_clock::now() - g0).count();
      counters["dd_rows"] += rep.dd_rows;
      counters["gnss_rows_rejected"] += rep.rejected_rows;
      counters["code_outliers"] += rep.code_outliers;
      counters["ambiguity_resets"] += rep.ambiguity_resets;
      if (rep.diverged || !finiteState(filter->state())) {
        warn(run, "the filter diverged at t=" + at(rover.t) +
                      " (GNSS code far outside its predicted spread); re-initializing");
        ++counters["reinitializations"];
        const CalibrationEstimate last = filter->calibration();
        dataset = withPrior(in.description, last);
        init = findInitialState(in, options, dataset.initial_calibration, rover.t, &why);
        if (!init) {
          warn(run, "no re-initialization possible after t=" + at(rover.t) + ": " + why);
          break;
        }
        filter = std::make_unique<CalibrationFilter>(options, dataset, in.imu, *init);
        gnss = std::make_unique<GnssUpdate>(orbits, in.base_e, options);
        continue;
      }
      if (rep.used) {
        ++run.gnss_epochs;
        run.fixed_epochs += rep.fixed;
      }
      run.history.push_back(filter->calibration());
    }
    while (next_output <= t_next) {
      run.trajectory.push_back(filter->trajectorySample(std::max(next_output, filter->time())));
      next_output += 1.0 / options.output_rate_hz;
    }
  }
  if (run.history.empty() || run.history.back().t < filter->time()) {
    run.history.push_back(filter->calibration());
  }
  for (const std::string& w :
       weakDirections(run.history.back(), in.description.initial_calibration))
    warn(run, w);
  run.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.timing["gnss_updates_s"] = gnss_time;
  return run;
}

}  // namespace giocal
