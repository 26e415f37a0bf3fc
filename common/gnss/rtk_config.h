// Loads the "rtk" section of a giocal YAML config into RtkOptions (keys left out keep defaults).
#pragma once

#include <string>

#include "common/gnss/rtk.h"

namespace giocal {

class YamlFields;

/// Throws DataError naming the file, line and problem.
RtkOptions readRtkOptions(const std::string& path);
/// The same from a configuration already parsed (keys asked for are remembered, see
/// YamlFields::rejectUnknownKeys).
RtkOptions readRtkOptions(const YamlFields& y);

}  // namespace giocal
