// Reader of RINEX navigation files: 2.x GPS and 3.x (mixed) GPS LNAV, Galileo I/NAV and F/NAV,
// BeiDou D1/D2, QZSS; GLONASS, SBAS and IRNSS records are skipped. Ionosphere parameters too.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "common/gnss/ephemeris.h"

namespace giocal {

struct NavData {
  std::vector<Ephemeris> ephemerides;
  std::array<double, 8> gps_iono{};  // Klobuchar alpha0-3, beta0-3 (0 when absent)
  bool has_gps_iono = false;
  int skipped_records = 0;  // records of unsupported systems
};

/// Throws DataError naming the file, the line and the problem; never reads past a bad record.
NavData readRinexNav(const std::string& path);

/// Merges several nav files (duplicates by satellite and toe are dropped).
NavData mergeNav(const std::vector<NavData>& parts);

}  // namespace giocal
