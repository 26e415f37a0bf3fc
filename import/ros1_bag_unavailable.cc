// openRos1Bag in a build without Debian's rosbag_storage (-DGIOCAL_ROS1_BAGS=OFF, as the 64-bit
// ARM cross-build, whose Debian has no arm64 pluginlib): says so instead of failing to link.
#include <stdexcept>

#include "import/bag_source.h"

namespace giocal::import {

std::unique_ptr<BagSource> openRos1Bag(const std::string& path) {
  throw std::runtime_error(path +
                           ": this giocal was built without ROS 1 bags (-DGIOCAL_ROS1_BAGS=OFF); "
                           "import it with a full build, or convert it to a ROS 2 bag (.db3)");
}

}  // namespace giocal::import
