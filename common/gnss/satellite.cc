#include "common/gnss/satellite.h"

#include <cctype>

namespace giocal {

std::string SatId::str() const {
  // By hand: the EKF names its ambiguity states with this many times per epoch, and snprintf
  // cost more than the lookups the names served.
  if (prn < 0 || prn > 99) return static_cast<char>(sys) + std::to_string(prn);
  return {static_cast<char>(sys), static_cast<char>('0' + prn / 10),
          static_cast<char>('0' + prn % 10)};
}

bool parseSatId(const std::string& text, SatId& out) {
  if (text.size() < 2 || text.size() > 3) return false;
  char c = text.size() == 3 ? text[0] : ' ';
  const std::string num = text.size() == 3 ? text.substr(1) : text;
  if (c == ' ') c = 'G';
  int prn = 0;
  for (char d : num) {
    if (d == ' ') continue;
    if (!std::isdigit(static_cast<unsigned char>(d))) return false;
    prn = prn * 10 + (d - '0');
  }
  switch (c) {
    case 'G':
    case 'R':
    case 'E':
    case 'C':
    case 'J':
    case 'S':
    case 'I':
      out.sys = static_cast<GnssSystem>(c);
      break;
    default:
      return false;
  }
  // RINEX 3 lists QZSS as J01..J10 (PRN 193..202) and SBAS as S20..S58 (PRN 120..158).
  out.prn = prn;
  return prn > 0;
}

bool isSupported(GnssSystem sys) {
  return sys == GnssSystem::kGps || sys == GnssSystem::kGalileo || sys == GnssSystem::kBeidou ||
         sys == GnssSystem::kQzss;
}

double carrierFrequency(GnssSystem sys, char band) {
  constexpr double f0 = 10.23e6;
  switch (sys) {
    case GnssSystem::kGps:
    case GnssSystem::kQzss:
      if (band == '1') return 154 * f0;                              // L1
      if (band == '2') return 120 * f0;                              // L2
      if (band == '5') return 115 * f0;                              // L5
      if (band == '6' && sys == GnssSystem::kQzss) return 125 * f0;  // LEX / L6
      return 0.0;
    case GnssSystem::kGalileo:
      if (band == '1') return 154 * f0;    // E1
      if (band == '5') return 115 * f0;    // E5a
      if (band == '7') return 118 * f0;    // E5b
      if (band == '8') return 116.5 * f0;  // E5 AltBOC
      if (band == '6') return 125 * f0;    // E6
      return 0.0;
    case GnssSystem::kBeidou:
      if (band == '2') return 1561.098e6;  // B1I
      if (band == '1') return 154 * f0;    // B1C
      if (band == '7') return 1207.14e6;   // B2I / B2b
      if (band == '5') return 115 * f0;    // B2a
      if (band == '6') return 1268.52e6;   // B3I
      return 0.0;
    default:
      return 0.0;
  }
}

bool isBeidouGeo(const SatId& sat) {
  return sat.sys == GnssSystem::kBeidou && (sat.prn <= 5 || (sat.prn >= 59 && sat.prn <= 63));
}

}  // namespace giocal
