// libFuzzer harness: imu.csv, odom.csv and truth.csv readers (the first byte picks which), the
// .pos reader of the LC scheme, the scenes.csv reader and the i2Nav text readers.
#include "common/gnss/pos_reader.h"
#include "common/io/scenes_csv.h"
#include "common/io/sensor_logs.h"
#include "fuzz/fuzz_input.h"
#include "import/i2nav_text.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string path = giocal::fuzz::asFile(data + 1, size - 1, "log.csv");
  giocal::fuzz::expectNoCrash([&] {
    std::vector<std::string> warnings;
    switch (data[0] % 8) {
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
      case 5:
        giocal::import::readI2navImu(path, 2300, 0.05);
        break;
      case 6:
        giocal::import::readI2navPos(path, 2300, &warnings);
        break;
      case 7:
        giocal::import::readI2navNav(path, &warnings);
        break;
      default:
        giocal::readScenesCsv(path);
    }
  });
  return 0;
}
