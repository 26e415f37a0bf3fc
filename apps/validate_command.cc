#include "apps/validate_command.h"

#include <filesystem>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>
#include <utility>

#include "apps/run_validation.h"
#include "common/calibration/calibration_inputs.h"
#include "common/gnss/pos_reader.h"
#include "common/gnss/rtk_job.h"
#include "common/io/output_set.h"
#include "common/io/progress_line.h"
#include "evaluation/validation.h"
#include "options/giocal_config.h"
#include "replay/measured_heights.h"
#include "replay/run_preparation.h"

namespace giocal {

namespace {

const std::vector<std::string> kFiles{"summary.json", "gnss_reference.pos"};

}  // namespace

void runValidate(const ValidateJob& job, std::ostream& log) {
  if (!job.overwrite) {
    for (const std::string& f : kFiles) {
      if (std::filesystem::exists(job.out + "/" + f))
        throw std::runtime_error(job.out + "/" + f + " exists; give --overwrite to replace it");
    }
  }
  if (job.outage_s < 5.0 || job.windows < 1)
    throw std::runtime_error("--outage must be at least 5 s and --windows at least 1");
  const GiocalConfig config = readGiocalConfig(job.config);
  const DatasetFolder data = openDatasetFolder(job.data);  // once for the whole run
  CalibrationInputs in = loadCalibrationInputs(data, job.positions);
  // One receiver (asked, or a dataset without a base): aided by it, against its own track.
  const bool single = usesSingleReceiver(data.description, job.single, job.positions);
  if (single) addSingleReceiverTrack(in, config.calibration.single);
  const bool rtk = job.positions.empty() && !single;
  OutputSet outputs(job.out);
  // The RTK solution is one of the outputs; with --pos or one receiver none is written.
  const ValidationReference ref = validationReference(
      in, config, job.positions, rtk ? outputs.stagedPath("gnss_reference.pos") : std::string(),
      job.stop, single);
  const std::string reference = ref.name + (rtk ? " (gnss_reference.pos)" : "");
  const ReferenceTrajectory trajectory(positionRows(ref.fixes));
  ValidationJob v;
  v.run = job.run;
  v.outage_s = job.outage_s;
  v.windows = job.windows;
  v.options = config.calibration;
  v.options.loosely_coupled = !job.positions.empty();
  v.options.single_receiver = single;
  v.relative_to_start = single;
  // The GNSS-aided stretches weigh the solutions' heights as calibrate did.
  if (v.options.loosely_coupled) applyFixHeights(measureFixHeights(in), v.options);
  ProgressLine progress("validate", 0.0, 1.0, job.quiet, "of the windows");
  v.progress = [&](double share) {
    progress.update(share);
    checkStop(job.stop);
  };
  const Validation r = validateCalibration(std::move(in), trajectory, v);
  progress.clear();

  nlohmann::ordered_json j;
  if (rtk) j["files"] = {{"gnss_reference.pos", outputs.close("gnss_reference.pos")}};
  j["run"] = job.run;
  j["reference"] = reference;
  j["outage_s"] = job.outage_s;
  j["metric"] = "horizontal MAX error inside each window [m]";
  j["windows"] = validationWindowsJson(r.windows);
  j["calibrated"] = r.calibrated_m;
  j["guess"] = r.guess_m;
  j["ratio"] = r.ratio;
  j["better_windows"] = r.better_windows;
  j["verdict"] = r.verdict;
  j["confidence"] = r.confidence;
  outputs.open("summary.json", true) << std::setprecision(12) << j.dump(2) << "\n";
  outputs.commit();

  log << std::fixed << std::setprecision(1) << "giocal validate: " << job.run << " on " << job.data
      << " against " << reference << "\n";
  for (const ValidationWindow& w : r.windows) {
    log << "  window +" << w.start_s << " s, " << w.duration_s << " s, " << w.distance_m
        << " m driven: horizontal MAX " << std::setprecision(2) << w.calibrated_m
        << " m calibrated, " << w.guess_m << " m guess" << std::setprecision(1) << "\n";
  }
  log << "  outputs: " << job.out << "/{summary.json" << (rtk ? ", gnss_reference.pos" : "")
      << "}\n";
  log << std::setprecision(2) << "  verdict: " << r.verdict << " (mean " << r.calibrated_m
      << " m calibrated against " << r.guess_m << " m guess, ratio " << r.ratio << "; better in "
      << r.better_windows << " of " << r.windows.size() << " windows";
  if (r.verdict != "no better") log << ", confidence " << r.confidence;
  log << ")\n";
  log.unsetf(std::ios::fixed);
}

}  // namespace giocal
