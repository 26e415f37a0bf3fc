#include "apps/state_file.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace giocal {

std::string stateChecksum(const std::string& json_without_checksum) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a 64
  for (const unsigned char c : json_without_checksum) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

void writeStateFile(const std::string& path, const CalibrationEstimate& e,
                    const std::map<std::string, double>& robot) {
  const OdometerCalibration& c = e.calib;
  nlohmann::json j;
  j["format"] = "giocal state 1";
  j["final"] = {{"s_v", c.s_v},
                {"s_w", c.s_w},
                {"p_b_m", {c.p_b_m.x(), c.p_b_m.y(), c.p_b_m.z()}},
                {"q_b_m", {c.q_b_m.w(), c.q_b_m.x(), c.q_b_m.y(), c.q_b_m.z()}}};
  nlohmann::json cov = nlohmann::json::array();
  for (int r = 0; r < 8; ++r) {
    nlohmann::json row = nlohmann::json::array();
    for (int k = 0; k < 8; ++k) row.push_back(e.cov(r, k));
    cov.push_back(row);
  }
  j["covariance_tangent"] = cov;
  j["t_final"] = e.t;
  j["robot"] = robot;
  const std::string body = j.dump();
  j["checksum"] = stateChecksum(body);
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << j.dump(1) << "\n";
    out.flush();
    if (!out) throw std::runtime_error(tmp + ": cannot write the state file");
  }
  std::filesystem::rename(tmp, path);  // atomic on one file system
}

void StateFileSink::estimate(const CalibrationEstimate& e) {
  if (next_) next_->estimate(e);
  if (e.t - last_written_ < every_s_) return;
  if (!std::isfinite(last_written_)) {
    last_written_ = e.t;  // the first estimate starts the clock: it is still the guess
    return;
  }
  writeStateFile(path_, e, robot_);
  last_written_ = e.t;
  ++writes_;
}

}  // namespace giocal
