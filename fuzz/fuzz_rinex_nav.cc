// libFuzzer harness: the RINEX navigation reader and the orbits built from what it accepts.
#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/rinex_nav.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = giocal::fuzz::asFile(data, size, "nav.rnx");
  giocal::fuzz::expectNoCrash([&] {
    const giocal::NavData nav = giocal::readRinexNav(path);
    const giocal::BroadcastOrbits orbits(nav);
    for (const giocal::Ephemeris& e : nav.ephemerides) {
      // Orbit evaluation at each record's own time must neither hang nor crash (the 1e99 toe
      // once made `giocal rtk` hang here).
      orbits.atReception(e.sat, e.toe, 2.2e7, '1', Eigen::Vector3d(-3.9e6, 3.4e6, 3.6e6));
    }
  });
  return 0;
}
