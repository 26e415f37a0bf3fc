// Loads the "rtk" section of a giocal YAML config into RtkOptions (keys left out keep defaults).
#pragma once

#include <string>

#include "common/gnss/rtk.h"

namespace giocal {

/// Throws DataError naming the file, line and problem.
RtkOptions readRtkOptions(const std::string& path);

}  // namespace giocal
