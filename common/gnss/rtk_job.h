// RtkJob: kinematic RTK over whole rover and base RINEX files (base epochs matched by time) to an
// RTKLIB-compatible .pos file; what `giocal rtk` runs.
#pragma once

#include <Eigen/Core>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "common/gnss/rtk.h"
#include "common/io/stop_request.h"

namespace giocal {

struct RtkJob {
  std::string rover, base, out;
  std::vector<std::string> nav;
  std::optional<Eigen::Vector3d> base_pos;  // ECEF; else the base header's APPROX POSITION XYZ
  RtkOptions options;
  const StopRequest* stop = nullptr;  // when requested, runRtk throws Interrupted, writing nothing
};

struct RtkSummary {
  int epochs = 0, fixed = 0, floats = 0, single = 0;
  double wall_s = 0.0, data_s = 0.0;
  std::vector<std::string> warnings;  // the readers' repairs and drops (rover, then base)
};

RtkSummary runRtk(const RtkJob& job, std::vector<RtkSolution>* solutions = nullptr);

/// Parses "x,y,z" (metres, ECEF) given with `flag`; throws std::invalid_argument naming it.
Eigen::Vector3d parseBasePosition(const std::string& text, const std::string& flag = "--base-pos");

}  // namespace giocal
