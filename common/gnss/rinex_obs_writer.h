// Writer of RINEX 3.04 observation files (the simulator's and import's output).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "common/gnss/observation.h"

namespace giocal {

struct RinexObsHeader {
  std::string program = "giocal simulate";
  std::string marker = "SIM";
  std::string receiver = "GIOCAL SIMULATOR";  // REC # / TYPE / VERS
  std::string antenna = "SIMULATED";          // ANT # / TYPE
  Eigen::Vector3d approx_position = Eigen::Vector3d::Zero();
  double interval = 1.0;
  std::map<char, std::vector<std::string>> obs_types;  // system -> codes ("C1C", "L1C", ...)
  // SYS / PHASE SHIFT: (system, phase code) -> the correction applied [cycles]; 0 where absent.
  std::map<std::pair<char, std::string>, double> phase_shift;
};

/// Writes `epochs` atomically; observations absent from a signal are left blank.
void writeRinexObs(const std::string& path, const RinexObsHeader& header,
                   const std::vector<ObsEpoch>& epochs);

}  // namespace giocal
