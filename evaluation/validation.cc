#include "evaluation/validation.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "common/calibration/calibration_run.h"
#include "common/io/csv_table.h"
#include "evaluation/calibration_source.h"
#include "evaluation/dead_reckoning.h"

namespace giocal {

namespace {

constexpr double kSettleS = 10.0;    // after the first calibration row, before a window starts
constexpr double kClearRatio = 0.1;  // a mean ratio within 10 % of 1 is "no better"
constexpr double kGapStepS = 0.5;    // how a window's start steps over a gap in the reference

/// The GPS time the run's calibration.csv@<seconds> counts from (summary.json's first rover
/// epoch), else the data's.
double runStart(const std::string& run, const CalibrationInputs& in) {
  std::ifstream summary(run + "/summary.json");
  if (summary) {
    const nlohmann::json j = nlohmann::json::parse(summary, nullptr, false);
    if (!j.is_discarded() && j.contains("t_first_rover_epoch") &&
        j["t_first_rover_epoch"].is_number())
      return j["t_first_rover_epoch"].get<double>();
  }
  return in.rover.epochs.front().t;
}

/// P(X >= k) for X ~ Binomial(n, 1/2): the sign test's one-sided p-value.
double signTestP(int k, int n) {
  double p = 0.0;
  for (int i = k; i <= n; ++i) {
    double c = 1.0;  // n choose i
    for (int j = 1; j <= i; ++j) c *= static_cast<double>(n - i + j) / j;
    p += c * std::pow(0.5, n);
  }
  return p;
}

std::string text(double v) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << v;
  return s.str();
}

}  // namespace

std::vector<double> validationWindowStarts(const CalibrationInputs& in,
                                           const ReferenceTrajectory& reference,
                                           double first_calibration_s, const ValidationJob& job) {
  const double t_rover = in.rover.epochs.front().t;
  const double first = std::max(first_calibration_s + kSettleS, reference.begin() + kSettleS);
  const double last = std::min(reference.end(), in.imu.back().t) - job.outage_s;
  if (last < first) {
    throw std::runtime_error("validate needs at least " + text(first - t_rover + job.outage_s) +
                             " s of drive with GNSS after the first rover epoch (a calibration " +
                             text(kSettleS) + " s old, then a " + text(job.outage_s) +
                             " s outage); this one has " +
                             text(std::min(reference.end(), in.imu.back().t) - t_rover) + " s");
  }
  // Windows do not overlap: as many as fit, up to job.windows, spread evenly. A window planned
  // where the reference has a gap (no RTK fix under trees) starts at the gap's end instead, and
  // one that no longer fits before the end is left out.
  const int fit = 1 + static_cast<int>(std::floor((last - first) / job.outage_s));
  const int n = std::max(1, std::min(job.windows, fit));
  std::vector<double> starts;
  double earliest = first;
  for (int k = 0; k < n; ++k) {
    double t = std::max(earliest, n == 1 ? first : first + (last - first) * k / (n - 1));
    while (t <= last && !reference.at(t)) t += kGapStepS;
    // A relative reference (one receiver's own track) compares only up to its next gap: the
    // window starts after the last gap inside it, so that it compares its whole length.
    for (double g = t; job.relative_to_start && t <= last && g <= t + job.outage_s;
         g += kGapStepS) {
      if (!reference.at(g)) t = g + kGapStepS;
    }
    if (t > last) break;
    starts.push_back(t);
    earliest = t + job.outage_s;
  }
  if (starts.empty()) {
    throw std::runtime_error(
        "validate: the GNSS reference has no solution where a window could "
        "start (from +" +
        text(first - t_rover) + " to +" + text(last - t_rover) + " s)");
  }
  return starts;
}

Validation validateCalibration(CalibrationInputs in, const ReferenceTrajectory& reference,
                               const ValidationJob& job) {
  const std::string csv = job.run + "/calibration.csv";
  if (!std::filesystem::exists(csv))
    throw std::runtime_error(csv + ": missing (--run names a calibrate output folder)");
  const CsvTable table = readCsvTable(csv, calibrationCsvHeader(), {});
  if (table.rows.empty()) throw std::runtime_error(csv + ": no calibration rows");
  const double t_run = runStart(job.run, in);
  const double t_rover = in.rover.epochs.front().t;
  const std::vector<double> starts =
      validationWindowStarts(in, reference, table.rows.front()[0], job);
  const std::vector<OdomSample> odom = in.odom;
  Validation v;
  for (size_t k = 0; k < starts.size(); ++k) {
    ValidationWindow w;
    w.start_s = starts[k] - t_rover;
    for (const bool calibrated : {true, false}) {
      std::ostringstream at;
      at << std::setprecision(15) << csv << "@" << starts[k] - t_run;
      const CalibrationSource source = readCalibrationSource(calibrated ? at.str() : "guess", in);
      // Only the odometer's stamps change with a source (its delay): they are put back for each
      // run instead of copying the whole inputs (ten copies of a field drive's IMU log were 60 MB).
      in.odom = odom;
      DeadReckoningJob dr;
      dr.options = job.options;
      dr.start_s = w.start_s;
      dr.duration_s = job.outage_s;
      dr.reference_has_attitude = job.reference_has_attitude;
      dr.relative_to_start = job.relative_to_start;
      applyCalibrationSource(source, dr, in.odom);
      const DeadReckoning r = deadReckon(in, reference, dr);
      (calibrated ? w.calibrated_m : w.guess_m) = r.horizontal_max_m;
      // Compared up to the end, or (a relative reference) up to its first gap.
      w.duration_s = (job.relative_to_start ? r.errors.back().t : r.t_end) - r.t_start;
      w.distance_m = r.distance_m;
    }
    v.better_windows += w.calibrated_m < w.guess_m;
    v.windows.push_back(w);
    if (job.progress) job.progress(static_cast<double>(k + 1) / static_cast<double>(starts.size()));
  }
  const double n = static_cast<double>(v.windows.size());
  for (const ValidationWindow& w : v.windows) {
    v.calibrated_m += w.calibrated_m / n;
    v.guess_m += w.guess_m / n;
  }
  v.ratio = v.guess_m > 0.0 ? v.calibrated_m / v.guess_m : 1.0;
  const int windows = static_cast<int>(v.windows.size());
  const int worse_windows = windows - v.better_windows;
  if (v.ratio < 1.0 - kClearRatio && 2 * v.better_windows > windows) {
    v.verdict = "better";
    v.confidence = 1.0 - signTestP(v.better_windows, windows);
  } else if (v.ratio > 1.0 + kClearRatio && 2 * worse_windows > windows) {
    v.verdict = "worse";
    v.confidence = 1.0 - signTestP(worse_windows, windows);
  } else {
    v.verdict = "no better";
  }
  return v;
}

}  // namespace giocal
