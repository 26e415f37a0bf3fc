// fieldPresetWithLaps: a copy of config/sim/field.yaml with fewer laps (its nav file's path made
// absolute for the copy), for command-line tests that want a short field drive.
#pragma once

#include <fstream>
#include <string>

#include "temp_dir.h"

namespace giocal::test {

inline std::string fieldPresetWithLaps(const TempDir& dir, int laps) {
  std::string preset;
  std::ifstream in(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml");
  for (std::string line; std::getline(in, line);) {
    if (line.find("  laps: 10") == 0) line = "  laps: " + std::to_string(laps);
    const size_t rel = line.find("../../data/");
    if (rel != std::string::npos) line.replace(rel, 11, std::string(GIOCAL_SOURCE_DIR) + "/data/");
    preset += line + "\n";
  }
  const std::string path = dir.file("field_" + std::to_string(laps) + "_laps.yaml");
  std::ofstream(path) << preset;
  return path;
}

}  // namespace giocal::test
