// libFuzzer harness: dataset.yaml, the giocal configuration (calibration, RTK and factor-graph
// options) and simulator presets (the first byte picks which).
#include "common/calibration/calibration_options.h"
#include "common/gnss/rtk_config.h"
#include "common/io/dataset_description.h"
#include "fuzz/fuzz_input.h"
#include "options/fgo_options.h"
#include "sim/sim_config.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string path = giocal::fuzz::asFile(data + 1, size - 1, "dataset.yaml");
  giocal::fuzz::expectNoCrash([&] {
    switch (data[0] % 3) {
      case 0:
        giocal::readDatasetDescription(giocal::fuzz::folder());
        break;
      case 1:
        giocal::readCalibrationOptions(path);
        giocal::readRtkOptions(path);
        giocal::readFgoOptions(path);
        break;
      default:
        giocal::sim::readSimConfig(path);
    }
  });
  return 0;
}
