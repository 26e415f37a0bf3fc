// libFuzzer harness: ROS message definitions and messages read through them (ROS 1 and CDR), as
// `giocal import --bag` reads each bag connection: the input is "<definition>\0<message bytes>".
#include <cstring>

#include "fuzz/fuzz_input.h"
#include "import/ros_message.h"
#include "import/ros_schema.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto* split = static_cast<const uint8_t*>(std::memchr(data, 0, size));
  if (!split || split == data) return 0;
  const std::string definition(reinterpret_cast<const char*>(data + 1),
                               static_cast<std::size_t>(split - data - 1));
  const uint8_t* bytes = split + 1;
  const std::size_t n = size - static_cast<std::size_t>(bytes - data);
  giocal::fuzz::expectNoCrash([&] {
    const giocal::import::RosSchema schema("fuzz/Message", definition);
    giocal::import::RosMessage::decode(
        schema,
        data[0] & 1 ? giocal::import::RosEncoding::kCdr : giocal::import::RosEncoding::kRos1, bytes,
        n);
  });
  return 0;
}
