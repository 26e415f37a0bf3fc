#include "common/gnss/rinex_nav_writer.h"

#include <array>
#include <cmath>
#include <cstdio>

#include "common/gnss/rinex_fields.h"
#include "common/io/atomic_file.h"
#include "common/time/gps_time.h"

namespace giocal {

namespace {

using rinex::headerLine;

// BDT began at GPS week 1356 and runs 14 s behind GPS time.
constexpr int kBdtWeekOffset = 1356;
constexpr double kBdtMinusGps = -14.0;
// RINEX 3.04 Table A4: transmission time not known.
constexpr double kUnknownTransmission = 0.9999e9;

std::string d19(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%19.12E", v);
  return buf;
}

// The 28 numbers of broadcast orbit lines 1-7 (RINEX 3.04 Tables A4, A8, A14).
std::array<double, 28> orbitOf(const Ephemeris& e, double toe_sow, int week) {
  std::array<double, 28> o{};
  o[0] = e.iode;
  o[1] = e.crs;
  o[2] = e.delta_n;
  o[3] = e.m0;
  o[4] = e.cuc;
  o[5] = e.e;
  o[6] = e.cus;
  o[7] = e.sqrt_a;
  o[8] = toe_sow;
  o[9] = e.cic;
  o[10] = e.omega0;
  o[11] = e.cis;
  o[12] = e.i0;
  o[13] = e.crc;
  o[14] = e.omega;
  o[15] = e.omega_dot;
  o[16] = e.idot;
  o[18] = week;
  o[20] = e.accuracy;
  o[21] = e.health;
  o[24] = kUnknownTransmission;
  switch (e.sat.sys) {
    case GnssSystem::kGalileo:
      o[17] = e.data_source;
      o[22] = e.tgd2;  // BGD E5a/E1
      o[23] = e.tgd;   // BGD E5b/E1
      break;
    case GnssSystem::kBeidou:
      o[22] = e.tgd;
      o[23] = e.tgd2;
      break;
    default:
      o[22] = e.tgd;
      o[23] = e.iodc;
      o[25] = 4.0;  // fit interval [h]
  }
  return o;
}

}  // namespace

void writeRinexNav(const std::string& path, const NavData& nav, const std::string& program) {
  AtomicFile file(path);
  auto& out = file.stream();
  out << headerLine("     3.04           N: GNSS NAV DATA    M: Mixed", "RINEX VERSION / TYPE");
  out << headerLine(program, "PGM / RUN BY / DATE");
  if (nav.has_gps_iono) {
    for (int part = 0; part < 2; ++part) {
      std::string line = part == 0 ? "GPSA " : "GPSB ";
      for (int k = 0; k < 4; ++k) {
        char buf[16];
        std::snprintf(buf, sizeof(buf), "%12.4E",
                      nav.gps_iono[static_cast<std::size_t>(4 * part + k)]);
        line += buf;
      }
      out << headerLine(line, "IONOSPHERIC CORR");
    }
  }
  out << headerLine("", "END OF HEADER");
  for (const Ephemeris& e : nav.ephemerides) {
    const bool bds = e.sat.sys == GnssSystem::kBeidou;
    const double shift = bds ? kBdtMinusGps : 0.0;
    // Round the clock epoch to the second it is given in, so 59.9999999 does not print as 60.
    const CalendarTime toc = calendarFromGpsSeconds(std::round(e.toc + shift));
    GpsWeekTime toe = weekTimeFromGpsSeconds(e.toe + shift);
    if (bds) toe.week -= kBdtWeekOffset;
    char buf[64];
    std::snprintf(buf, sizeof(buf), "%s %04d %02d %02d %02d %02d %02d", e.sat.str().c_str(),
                  toc.year, toc.month, toc.day, toc.hour, toc.minute, static_cast<int>(toc.second));
    out << buf << d19(e.af0) << d19(e.af1) << d19(e.af2) << "\n";
    const auto o = orbitOf(e, std::round(toe.tow * 1e3) / 1e3, toe.week);
    for (int line = 0; line < 7; ++line) {
      out << "    ";
      const int n = line == 6 ? 2 : 4;
      for (int k = 0; k < n; ++k) out << d19(o[static_cast<std::size_t>(4 * line + k)]);
      out << "\n";
    }
  }
  file.commit();
}

}  // namespace giocal
