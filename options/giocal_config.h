// GiocalConfig: giocal.yaml parsed once and handed to each options struct (calibration with its
// models and rtk sections, the factor graph); a key no reader knows is an error naming the file,
// the line and the nearest valid key, not a silently kept default.
#pragma once

#include <map>
#include <string>

#include "common/calibration/calibration_options.h"
#include "common/gnss/rtk_config.h"
#include "options/fgo_options.h"

namespace giocal {

struct GiocalConfig {
  CalibrationOptions calibration;
  FgoOptions fgo;
  RtkOptions rtk;
  std::map<std::string, std::string> in_effect;  // every option's key and value, defaults included
};

/// Defaults when `path` is empty. Throws DataError for syntax errors, values out of range and
/// unknown keys.
GiocalConfig readGiocalConfig(const std::string& path);

}  // namespace giocal
