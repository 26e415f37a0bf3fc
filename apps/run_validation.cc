#include "apps/run_validation.h"

#include <stdexcept>

#include "apps/dataset_rtk.h"
#include "evaluation/validation.h"

namespace giocal {

namespace {

/// The fixed RTK solutions of the dataset's rover and base, written to `pos`.
std::vector<PositionFix> rtkFixes(const CalibrationInputs& in, const GiocalConfig& config,
                                  const std::string& pos, const StopRequest* stop) {
  const DatasetDescription& d = in.description;
  if (d.base_obs.empty())
    throw std::runtime_error(d.pathOf("dataset.yaml") +
                             ": no base observations; validate a rover-only dataset with --gnss lc "
                             "--pos <file.pos>");
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

}  // namespace

ValidationReference validationReference(const CalibrationInputs& in, const GiocalConfig& config,
                                        const std::string& positions, const std::string& pos,
                                        const StopRequest* stop) {
  ValidationReference r;
  if (positions.empty()) {
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
  if (options.single_receiver) {
    out.why_not = "no validation for one receiver yet (its reference would be its own track)";
    return out;
  }
  const TempPosFile pos("validation");
  try {
    const CalibrationInputs in = loadCalibrationInputs(data, positions);
    const ValidationReference ref = validationReference(in, config, positions, pos.path, stop);
    ValidationJob v;
    v.run = run_dir;
    v.options = options;
    v.progress = [stop](double) { checkStop(stop); };
    const Validation r = validateCalibration(in, ReferenceTrajectory(positionRows(ref.fixes)), v);
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
