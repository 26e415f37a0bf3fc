#include "common/calibration/rejection_share.h"

#include "common/io/text.h"

namespace giocal {

namespace {

// The GNSS rows a run used: the positions' three per fix, else the double differences, else (a
// single receiver) the time-differenced phase rows.
long gnssRowsUsed(const CalibrationRun& run, bool positions_only) {
  if (positions_only) return 3L * run.gnss_epochs;
  return run.counter(Counter::kDdRows) + run.counter(Counter::kTdcpRows);
}

std::string gnssRowsName(const CalibrationRun& run, bool positions_only) {
  if (positions_only) return "GNSS position rows";
  return run.counter(Counter::kDdRows) == 0 && run.counter(Counter::kTdcpRows) > 0
             ? "time-differenced phase and Doppler rows"
             : "double-difference GNSS rows";
}

}  // namespace

std::vector<std::string> rejectionShareWarnings(const CalibrationRun& run, bool positions_only,
                                                double fraction) {
  std::vector<std::string> out;
  const auto share = [&](long rejected, long total, const std::string& what) {
    if (total <= 0 || static_cast<double>(rejected) <= fraction * static_cast<double>(total))
      return;
    out.push_back(std::to_string(rejected) + " of " + std::to_string(total) + " " + what +
                  " were rejected by the innovation gates (more than " +
                  fixedText(100.0 * fraction, 0) +
                  " %): the estimate no longer fits the data and is likely wrong (diverged, or a "
                  "wrong dataset.yaml: noise, time offsets, initial guess); check the trajectory "
                  "against the GNSS solution before using the calibration");
  };
  // odometer_intervals counts every interval, odometer_rejected those of them gated out;
  // dd_rows (a single receiver: tdcp_rows) counts the GNSS rows used and gnss_rows_rejected the
  // others, or with positions a rejected fix as three rows and gnss_epochs the fixes used.
  share(run.counter(Counter::kOdometerRejected), run.counter(Counter::kOdometerIntervals),
        "odometer intervals");
  const long rejected = run.counter(Counter::kGnssRowsRejected);
  share(rejected, gnssRowsUsed(run, positions_only) + rejected, gnssRowsName(run, positions_only));
  return out;
}

std::string suspectReason(const CalibrationRun& run, bool positions_only, bool loosely_coupled) {
  const auto over_half = [](long part, long total) { return total > 0 && 2 * part > total; };
  const auto of = [](long part, long total, const std::string& what) {
    return std::to_string(part) + " of " + std::to_string(total) + " " + what;
  };
  const long odo = run.counter(Counter::kOdometerIntervals);
  const long odo_rejected = run.counter(Counter::kOdometerRejected);
  if (over_half(odo_rejected, odo))
    return of(odo_rejected, odo, "odometer intervals rejected by the gates");
  const long used = gnssRowsUsed(run, positions_only);
  const long rejected = run.counter(Counter::kGnssRowsRejected);
  if (over_half(rejected, used + rejected))
    return of(rejected, used + rejected, gnssRowsName(run, positions_only) + " rejected by the gates");
  const long unused = run.counter(Counter::kGnssEpochsUnused);
  if (loosely_coupled && over_half(unused, unused + run.gnss_epochs))
    return of(unused, unused + run.gnss_epochs, "position fixes updated nothing");
  return "";
}

}  // namespace giocal
