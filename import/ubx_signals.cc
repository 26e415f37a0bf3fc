#include "import/ubx_signals.h"

namespace giocal::import {

bool ubxSatellite(int gnss_id, int sv_id, SatId& out) {
  switch (gnss_id) {
    case 0:
      out = {GnssSystem::kGps, sv_id};
      return sv_id >= 1 && sv_id <= 32;
    case 1:  // SBAS PRN 120-158 is RINEX S20-S58
      out = {GnssSystem::kSbas, sv_id - 100};
      return sv_id >= 120 && sv_id <= 158;
    case 2:
      out = {GnssSystem::kGalileo, sv_id};
      return sv_id >= 1 && sv_id <= 36;
    case 3:
      out = {GnssSystem::kBeidou, sv_id};
      return sv_id >= 1 && sv_id <= 63;
    case 5:
      out = {GnssSystem::kQzss, sv_id};
      return sv_id >= 1 && sv_id <= 10;
    default:
      return false;
  }
}

bool ubxSignal(GnssSystem sys, int sig_id, char& band, char& attr) {
  struct Code {
    int sig;
    char band, attr;
  };
  static constexpr Code kGps[] = {
      {0, '1', 'C'}, {3, '2', 'L'}, {4, '2', 'S'}, {6, '5', 'I'}, {7, '5', 'Q'}};
  static constexpr Code kSbas[] = {{0, '1', 'C'}};
  // E6 B and B3I are the X20's (the F9 has neither); their carrier frequencies in the real X20
  // log (data/real/ublox-f9p-walk) confirm the bands: phase / code = 1278.75 and 1268.52 MHz.
  static constexpr Code kGalileo[] = {{0, '1', 'C'}, {1, '1', 'B'}, {3, '5', 'I'}, {4, '5', 'Q'},
                                      {5, '7', 'I'}, {6, '7', 'Q'}, {8, '6', 'B'}};
  static constexpr Code kBeidou[] = {{0, '2', 'I'}, {1, '2', 'I'}, {2, '7', 'I'}, {3, '7', 'I'},
                                     {4, '6', 'I'}, {5, '1', 'P'}, {7, '5', 'P'}};
  static constexpr Code kQzss[] = {{0, '1', 'C'}, {1, '1', 'Z'}, {4, '2', 'S'},
                                   {5, '2', 'L'}, {8, '5', 'I'}, {9, '5', 'Q'}};
  auto find = [&](const auto& table) {
    for (const Code& c : table) {
      if (c.sig == sig_id) {
        band = c.band;
        attr = c.attr;
        return true;
      }
    }
    return false;
  };
  switch (sys) {
    case GnssSystem::kGps:
      return find(kGps);
    case GnssSystem::kSbas:
      return find(kSbas);
    case GnssSystem::kGalileo:
      return find(kGalileo);
    case GnssSystem::kBeidou:
      return find(kBeidou);
    case GnssSystem::kQzss:
      return find(kQzss);
    default:
      return false;
  }
}

}  // namespace giocal::import
