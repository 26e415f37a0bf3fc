// libFuzzer harness: the u-blox UBX reader (frames, RXM-RAWX, RXM-SFRBX with GPS LNAV and Galileo
// I/NAV), as `giocal import --ubx` reads a log.
#include "fuzz/fuzz_input.h"
#include "import/ubx_log.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = giocal::fuzz::asFile(data, size, "log.ubx");
  giocal::fuzz::expectNoCrash([&] { giocal::import::readUbxLog(path); });
  return 0;
}
