// libFuzzer harness: the RINEX observation reader, epoch by epoch.
#include "common/gnss/rinex_obs.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = giocal::fuzz::asFile(data, size, "rover.obs");
  giocal::fuzz::expectNoCrash([&] {
    giocal::RinexObsReader reader(path);
    giocal::ObsEpoch e;
    while (reader.next(e)) {
    }
  });
  return 0;
}
