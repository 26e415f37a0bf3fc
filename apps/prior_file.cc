#include "apps/prior_file.h"

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "apps/state_file.h"

namespace giocal {

PriorFile readPriorFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the prior");
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded()) {
    // A state file starts with its checksum (keys are written sorted): a robot's state cut by a
    // power loss starts the run cold; any other file that is not JSON is refused.
    const bool state = text.find("\"checksum\"") < 16;
    const std::string why = path + ": not JSON (cut by a power loss?)";
    if (state) throw DamagedPrior(why);
    throw std::runtime_error(why);
  }
  if (j.contains("format") && j["format"] != "giocal state 1") {
    throw std::runtime_error(path + ": a state file of another format (" + j["format"].dump() +
                             "); this giocal reads \"giocal state 1\"");
  }
  if (j.contains("checksum")) {  // a state file (--state-out): it says whether it is whole
    const std::string stated = j["checksum"].is_string() ? j["checksum"].get<std::string>() : "";
    j.erase("checksum");
    if (stateChecksum(j.dump()) != stated)
      throw DamagedPrior(path + ": its checksum does not match (damaged, or cut by a power loss)");
  }
  for (const char* key : {"final", "covariance_tangent", "t_final", "robot"}) {
    if (!j.contains(key) || j[key].is_null()) {
      throw std::runtime_error(path + ": no '" + key +
                               "' (a run that never initialized, or a summary.json older than "
                               "--prior; calibrate that drive again)");
    }
  }
  PriorFile p;
  try {
    const auto& f = j["final"];
    OdometerCalibration& m = p.calibration.mean;
    m.s_v = f["s_v"].get<double>();
    m.s_w = f["s_w"].get<double>();
    const auto pb = f["p_b_m"].get<std::vector<double>>();
    const auto q = f["q_b_m"].get<std::vector<double>>();
    if (pb.size() != 3 || q.size() != 4) throw std::runtime_error("sizes");
    m.p_b_m = Eigen::Vector3d(pb[0], pb[1], pb[2]);
    m.q_b_m = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized();
    Eigen::Matrix<double, 8, 8> cov;
    const auto C = j["covariance_tangent"].get<std::vector<std::vector<double>>>();
    if (C.size() != 8) throw std::runtime_error("sizes");
    for (int r = 0; r < 8; ++r) {
      if (C[static_cast<size_t>(r)].size() != 8) throw std::runtime_error("sizes");
      for (int c = 0; c < 8; ++c) cov(r, c) = C[static_cast<size_t>(r)][static_cast<size_t>(c)];
    }
    if (!cov.allFinite()) throw std::runtime_error("covariance not finite");
    p.calibration.covariance = cov;
    p.t_final = j["t_final"].get<double>();
    p.robot = j["robot"].get<std::map<std::string, double>>();
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": cannot read the prior (" + e.what() + ")");
  }
  return p;
}

}  // namespace giocal
