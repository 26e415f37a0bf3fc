// Writer of RTKLIB-compatible solution files (.pos): '%' header lines, then one line per epoch
// "yyyy/mm/dd hh:mm:ss.sss lat lon height Q ns sdn sde sdu sdne sdeu sdun age ratio" in GPST.
#pragma once

#include <string>
#include <vector>

#include "common/gnss/rtk.h"

namespace giocal {

struct PosHeader {
  std::string program = "giocal rtk";
  std::vector<std::string> inputs;
  Eigen::Vector3d base_e = Eigen::Vector3d::Zero();
};

/// Written atomically.
void writePosFile(const std::string& path, const PosHeader& header,
                  const std::vector<RtkSolution>& solutions);

}  // namespace giocal
