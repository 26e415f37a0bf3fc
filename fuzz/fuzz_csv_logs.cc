// libFuzzer harness: imu.csv, odom.csv and truth.csv readers (the first byte picks which), and
// the .pos reader of the LC scheme.
#include "common/gnss/pos_reader.h"
#include "common/io/sensor_logs.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string path = giocal::fuzz::asFile(data + 1, size - 1, "log.csv");
  giocal::fuzz::expectNoCrash([&] {
    switch (data[0] % 4) {
      case 0:
        giocal::readImuCsv(path);
        break;
      case 1:
        giocal::readOdomCsv(path);
        break;
      case 2:
        giocal::readTruthCsv(path);
        break;
      default:
        giocal::readPosFile(path);
    }
  });
  return 0;
}
