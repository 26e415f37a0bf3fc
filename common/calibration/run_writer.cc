#include "common/calibration/run_writer.h"

#include <charconv>
#include <cmath>
#include <iomanip>

#include "common/math/rotation.h"

namespace giocal {
namespace {

void writeRow(std::ostream& out, const std::vector<double>& row) {
  // to_chars in the general format prints what the stream's %.17g does (writeHeader's
  // precision), without the stream's locale machinery: a tenth of the EKF's field budget went
  // into formatting the trajectory.
  char buf[32];
  for (size_t i = 0; i < row.size(); ++i) {
    if (i) out.put(',');
    const std::to_chars_result r =
        std::to_chars(buf, buf + sizeof(buf), row[i], std::chars_format::general, 17);
    out.write(buf, r.ptr - buf);
  }
  out.put('\n');
}

void writeHeader(std::ostream& out, const std::vector<std::string>& names) {
  for (size_t i = 0; i < names.size(); ++i) out << (i ? "," : "") << names[i];
  out << '\n' << std::setprecision(17);
}

}  // namespace

RunWriter::RunWriter(OutputSet& set, std::string prefix)
    : set_(set),
      prefix_(std::move(prefix)),
      calibration_(set.open(prefix_ + "calibration.csv")),
      trajectory_(set.open(prefix_ + "trajectory.csv")),
      gnss_(set.open(prefix_ + "gnss.csv")) {
  writeHeader(calibration_, calibrationCsvHeader());
  writeHeader(trajectory_, truthCsvHeader());
  writeHeader(gnss_, {"t", "satellites", "pdop", "used", "fixed"});
}

void RunWriter::gnssEpoch(const GnssEpochRecord& g) {
  writeRow(gnss_, {g.t, static_cast<double>(g.satellites), g.pdop, g.used ? 1.0 : 0.0,
                   g.fixed ? 1.0 : 0.0});
}

void RunWriter::estimate(const CalibrationEstimate& e) {
  writeRow(calibration_, calibrationCsvRow(e));
  // The delay and the tilt have files of their own: calibration.csv's columns are a fixed
  // contract (the brief).
  if (std::isfinite(e.odometer_delay_s)) {
    if (!delay_) {
      delay_ = &set_.open(prefix_ + "odometer_delay.csv");
      writeHeader(*delay_, odometerDelayCsvHeader());
    }
    writeRow(*delay_, {e.t, e.odometer_delay_s, e.odometer_delay_sd_s});
  }
  if (e.gyro_tilt.allFinite()) {
    if (!tilt_) {
      tilt_ = &set_.open(prefix_ + "gyro_tilt.csv");
      writeHeader(*tilt_, gyroTiltCsvHeader());
    }
    const Eigen::Vector2d deg = e.gyro_tilt * kRadToDeg, sd_deg = e.gyro_tilt_sd * kRadToDeg;
    writeRow(*tilt_, {e.t, deg.x(), deg.y(), sd_deg.x(), sd_deg.y()});
  }
}

void RunWriter::trajectory(const TruthSample& s) { writeRow(trajectory_, truthCsvRow(s)); }

void RunWriter::finish(const CalibrationRun& run, const OdometerCalibration* truth) {
  closeFiles();
  writeSummary(run, truth);
}

void RunWriter::closeFiles() {
  if (!closed_.empty()) return;
  for (const char* name : {"calibration.csv", "trajectory.csv", "gnss.csv"}) {
    closed_[name] = set_.close(prefix_ + name);
  }
  if (delay_) closed_["odometer_delay.csv"] = set_.close(prefix_ + "odometer_delay.csv");
  if (tilt_) closed_["gyro_tilt.csv"] = set_.close(prefix_ + "gyro_tilt.csv");
}

void RunWriter::writeSummary(const CalibrationRun& run, const OdometerCalibration* truth) {
  closeFiles();
  set_.open(prefix_ + "summary.json", true) << summaryJson(run, truth, closed_);
}

}  // namespace giocal
