// libFuzzer harness: ROS message definitions and messages read through them (ROS 1 and CDR), as
// `giocal import --bag` reads each bag connection, then handed to the raw-GNSS decoders a bag's
// messages go to (gnss_comm GnssMeasMsg / GnssEphemMsg, ublox_msgs RxmRAWX / RxmSFRBX): the
// input is "<flags><definition>\0<message bytes>".
#include <cstring>

#include "fuzz/fuzz_input.h"
#include "import/gnss_comm_messages.h"
#include "import/ros_message.h"
#include "import/ros_schema.h"
#include "import/ublox_messages.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace giocal::import;
  const auto* split = static_cast<const uint8_t*>(std::memchr(data, 0, size));
  if (!split || split == data) return 0;
  const std::string definition(reinterpret_cast<const char*>(data + 1),
                               static_cast<std::size_t>(split - data - 1));
  const uint8_t* bytes = split + 1;
  const std::size_t n = size - static_cast<std::size_t>(bytes - data);
  giocal::fuzz::expectNoCrash([&] {
    const RosSchema schema("fuzz/Message", definition);
    const RosMessage m =
        RosMessage::decode(schema, data[0] & 1 ? RosEncoding::kCdr : RosEncoding::kRos1, bytes, n);
    switch ((data[0] >> 1) & 3) {
      case 1: {
        GnssCommDecoder d("fuzz");
        d.addMeasurements(m, "message 1");
        d.addEphemeris(m, "message 2");
        d.finish();
        break;
      }
      case 2: {
        UbxDecoder d("fuzz");
        d.add(rawxFrame(m), "message 1");
        d.add(sfrbxFrame(m), "message 2");
        d.finish();
        break;
      }
      default:
        break;
    }
  });
  return 0;
}
