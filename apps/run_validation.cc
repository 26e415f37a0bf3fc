#include "apps/run_validation.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "apps/dataset_rtk.h"
#include "evaluation/validation.h"

namespace giocal {

namespace {

// More than ReferenceTrajectory::at's largest step between samples (1 s): a gap.
constexpr double kStretchGapS = 1.001;

/// The fixed RTK solutions of the dataset's rover and base, written to `pos`.
std::vector<PositionFix> rtkFixes(const CalibrationInputs& in, const GiocalConfig& config,
                                  const std::string& pos, const StopRequest* stop) {
  const DatasetDescription& d = in.description;
  if (d.base_obs.empty())
    throw std::runtime_error(d.pathOf("dataset.yaml") +
                             ": no base observations; validate a rover-only dataset with --gnss "
                             "single, or --gnss lc --pos <file.pos>");
  std::vector<RtkSolution> solutions;
  runRtk(datasetRtkJob(d, config, pos, stop), &solutions);
  std::vector<PositionFix> fixes;
  for (const RtkSolution& s : solutions) {
    if (s.quality != 1) continue;
    PositionFix f;
    f.t = s.t;
    f.p_e = s.p_e;
    f.quality = 1;
    fixes.push_back(f);
  }
  return fixes;
}

/// One receiver's own track (addSingleReceiverTrack's, in in.positions), a new stretch (another
/// single point position's offset) kept only from more than a second after the last point of the
/// one before: a gap, so that no window's comparison crosses the jump.
std::vector<PositionFix> ownTrack(const CalibrationInputs& in) {
  std::vector<PositionFix> fixes;
  double skip_until = -INFINITY;
  auto restart = in.track_restarts.begin();
  for (size_t k = 0; k < in.positions.size(); ++k) {
    if (restart != in.track_restarts.end() && *restart == k) {
      ++restart;
      if (!fixes.empty()) skip_until = fixes.back().t + kStretchGapS;
    }
    if (in.positions[k].t > skip_until) fixes.push_back(in.positions[k]);
  }
  return fixes;
}

}  // namespace

ValidationReference validationReference(const CalibrationInputs& in, const GiocalConfig& config,
                                        const std::string& positions, const std::string& pos,
                                        const StopRequest* stop, bool single) {
  ValidationReference r;
  if (single) {
    r.fixes = ownTrack(in);
    r.name =
        "the rover's own track (single point positions joined by time-differenced phase; "
        "errors taken from each window's start)";
  } else if (positions.empty()) {
    r.fixes = rtkFixes(in, config, pos, stop);
    r.name = "RTK fixes of the dataset";
  } else {
    r.fixes = in.positions;
    r.name = positions;
  }
  if (r.fixes.size() < 2)
    throw std::runtime_error("validate needs a GNSS solution over the drive: " + r.name + " has " +
                             std::to_string(r.fixes.size()) + " rows");
  return r;
}

RunValidation validateAtEnd(const DatasetFolder& data, const GiocalConfig& config,
                            const CalibrationOptions& options, const std::string& positions,
                            const std::string& run_dir, const StopRequest* stop) {
  RunValidation out;
  const TempPosFile pos("validation");
  try {
    CalibrationInputs in = loadCalibrationInputs(data, positions);
    if (options.single_receiver) addSingleReceiverTrack(in, options.single);
    const ValidationReference ref =
        validationReference(in, config, positions, pos.path, stop, options.single_receiver);
    ValidationJob v;
    v.run = run_dir;
    v.options = options;
    v.relative_to_start = options.single_receiver;
    v.progress = [stop](double) { checkStop(stop); };
    const Validation r =
        validateCalibration(std::move(in), ReferenceTrajectory(positionRows(ref.fixes)), v);
    out.verdict = r.verdict;
    out.calibrated_m = r.calibrated_m;
    out.guess_m = r.guess_m;
    out.ratio = r.ratio;
    out.confidence = r.confidence;
    out.better_windows = r.better_windows;
    out.windows = static_cast<int>(r.windows.size());
    out.per_window = r.windows;
    out.reference = ref.name;
  } catch (const Interrupted&) {
    throw;
  } catch (const std::runtime_error& e) {
    out.why_not = e.what();
  }
  return out;
}

}  // namespace giocal
