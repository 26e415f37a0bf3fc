#include <filesystem>

#include "import/bag_source.h"

namespace giocal::import {

std::unique_ptr<BagSource> openBag(const std::string& path) {
  if (std::filesystem::is_directory(path) || std::filesystem::path(path).extension() == ".db3") {
    return openRos2Bag(path);
  }
  return openRos1Bag(path);
}

}  // namespace giocal::import
