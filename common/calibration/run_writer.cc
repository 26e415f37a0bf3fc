#include "common/calibration/run_writer.h"

#include <filesystem>
#include <iomanip>

namespace giocal {
namespace {

void writeRow(std::ostream& out, const std::vector<double>& row) {
  for (size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << row[i];
  out << '\n';
}

void writeHeader(std::ostream& out, const std::vector<std::string>& names) {
  for (size_t i = 0; i < names.size(); ++i) out << (i ? "," : "") << names[i];
  out << '\n' << std::setprecision(17);
}

}  // namespace

RunWriter::RunWriter(const std::string& folder) : folder_(folder) {
  std::filesystem::create_directories(folder);
  calibration_ = std::make_unique<AtomicFile>(folder + "/calibration.csv");
  trajectory_ = std::make_unique<AtomicFile>(folder + "/trajectory.csv");
  writeHeader(calibration_->stream(), calibrationCsvHeader());
  writeHeader(trajectory_->stream(), truthCsvHeader());
}

void RunWriter::estimate(const CalibrationEstimate& e) {
  writeRow(calibration_->stream(), calibrationCsvRow(e));
}

void RunWriter::trajectory(const TruthSample& s) {
  writeRow(trajectory_->stream(), truthCsvRow(s));
}

void RunWriter::commit(const CalibrationRun& run, const OdometerCalibration* truth) {
  AtomicFile summary(folder_ + "/summary.json");
  summary.stream() << summaryJson(run, truth);
  calibration_->commit();
  trajectory_->commit();
  summary.commit();
}

}  // namespace giocal
