// libFuzzer harness: imu.csv, odom.csv and truth.csv readers (the first byte picks which), the
// .pos reader of the LC scheme and the scenes.csv reader.
#include "common/gnss/pos_reader.h"
#include "common/io/scenes_csv.h"
#include "common/io/sensor_logs.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string path = giocal::fuzz::asFile(data + 1, size - 1, "log.csv");
  giocal::fuzz::expectNoCrash([&] {
    switch (data[0] % 5) {
      case 0:
        giocal::readImuCsv(path);
        break;
      case 1:
        giocal::readOdomCsv(path);
        break;
      case 2:
        giocal::readTruthCsv(path);
        break;
      case 3:
        giocal::readPosFile(path);
        break;
      default:
        giocal::readScenesCsv(path);
    }
  });
  return 0;
}
