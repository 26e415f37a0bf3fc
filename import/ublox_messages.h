// ublox_msgs/RxmRAWX and RxmSFRBX (the u-blox ROS driver's messages, ROS 1 camelCase or ROS 2
// snake_case field names) packed back into the UBX payloads they were made from, so that a bag's
// raw GNSS goes through the same decoder as a UBX log.
#pragma once

#include "import/ros_message.h"
#include "import/ubx_stream.h"

namespace giocal::import {

/// True for the message types read here ("ublox_msgs/RxmRAWX", "ublox_msgs/msg/RxmRAWX", ...).
bool isUbloxRawx(const std::string& type);
bool isUbloxSfrbx(const std::string& type);

/// The UBX-RXM-RAWX (0x02 0x15) frame of a message; throws std::runtime_error naming a missing
/// field.
UbxFrame rawxFrame(const RosMessage& m);
/// The UBX-RXM-SFRBX (0x02 0x13) frame of a message.
UbxFrame sfrbxFrame(const RosMessage& m);

}  // namespace giocal::import
