// Writer of RINEX 3.04 navigation files (GPS, QZSS, Galileo and BeiDou broadcast ephemerides), the
// inverse of readRinexNav.
#pragma once

#include <string>

#include "common/gnss/rinex_nav.h"

namespace giocal {

/// Writes `nav` atomically; `program` goes into the PGM / RUN BY / DATE line.
void writeRinexNav(const std::string& path, const NavData& nav, const std::string& program);

}  // namespace giocal
