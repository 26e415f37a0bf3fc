#include "common/gnss/rinex_nav.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include "common/gnss/rinex_fields.h"
#include "common/io/data_error.h"
#include "common/time/gps_time.h"

namespace giocal {

namespace {

using rinex::field;

struct LineReader {
  std::ifstream in;
  std::string path;
  long line_no = 0;
  bool next(std::string& line) {
    if (!std::getline(in, line)) return false;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
  }
  [[noreturn]] void fail(const std::string& what) const { throw DataError(path, line_no, what); }
};

double num(LineReader& r, const std::string& line, int col, int width, const char* what) {
  double v = 0.0;
  if (!rinex::number(field(line, col, width), 0.0, v)) {
    r.fail(std::string("bad number for ") + what + ": '" + rinex::trim(field(line, col, width)) +
           "'");
  }
  return v;
}

int integer(LineReader& r, const std::string& line, int col, int width, const char* what, int min,
            int max) {
  int v = 0;
  if (!rinex::integer(num(r, line, col, width, what), min, max, v)) {
    r.fail(std::string("bad ") + what + ": '" + rinex::trim(field(line, col, width)) +
           "' (a whole number from " + std::to_string(min) + " to " + std::to_string(max) + ")");
  }
  return v;
}

// Number of lines in a record (including its first line) by system, RINEX 3.
int recordLines(char sys) {
  switch (sys) {
    case 'R':
    case 'S':
      return 4;
    default:
      return 8;
  }
}

// Fills the orbit from the 28 numbers after the clock line (broadcast orbit lines 1-7); returns
// what is wrong with them, empty when nothing is.
std::string fillOrbit(Ephemeris& e, const std::array<double, 28>& o, char sys) {
  int week_number = 0, health = 0, source = 0;
  if (!rinex::integer(o[18], 0, 9999, week_number)) return "week outside 0-9999";
  if (!(o[8] >= 0.0 && o[8] <= 604800.0)) return "time of ephemeris outside 0-604800 s";
  if (!rinex::integer(o[21], 0, 1 << 20, health)) return "health is not a whole number >= 0";
  if (sys == 'E' && !rinex::integer(o[17], 0, 65535, source)) return "bad Galileo data source";
  e.iode = o[0];
  e.crs = o[1];
  e.delta_n = o[2];
  e.m0 = o[3];
  e.cuc = o[4];
  e.e = o[5];
  e.cus = o[6];
  e.sqrt_a = o[7];
  const double toe_sow = o[8];
  e.cic = o[9];
  e.omega0 = o[10];
  e.cis = o[11];
  e.i0 = o[12];
  e.crc = o[13];
  e.omega = o[14];
  e.omega_dot = o[15];
  e.idot = o[16];
  const int week = week_number;
  e.accuracy = o[20];
  e.health = health;
  e.tgd = o[22];
  if (sys == 'E') {
    e.data_source = source;
    e.tgd = o[23];   // BGD E5b/E1, the one an E1 (I/NAV) single-frequency user applies
    e.tgd2 = o[22];  // BGD E5a/E1
  } else if (sys == 'C') {
    e.tgd2 = o[23];
  } else {
    e.iodc = o[23];
  }
  if (sys == 'C') {
    // BDT week 0 began at GPS week 1356 (+14 s); toe is kept in GPS seconds.
    e.toe = gpsSecondsFromWeekTime({week + 1356, toe_sow}) + 14.0;
  } else {
    // RINEX 3 gives GPS, QZSS and Galileo weeks on the continuous GPS count; RINEX 2 files written
    // with a week modulo 1024 are brought next to the clock time below.
    e.toe = gpsSecondsFromWeekTime({week, toe_sow});
  }
  // Keep toe within half a week of toc (week rollovers and mod-1024 weeks).
  e.toe -= kSecondsPerWeek * std::round((e.toe - e.toc) / kSecondsPerWeek);
  return "";
}

}  // namespace

NavData readRinexNav(const std::string& path) {
  LineReader r{std::ifstream(path), path};
  if (!r.in) throw DataError(path, 0, "cannot open file");
  NavData nav;
  std::string line;
  double version = 0.0;
  char file_sys = 'G';
  bool header_done = false;
  while (r.next(line)) {
    const std::string lab = rinex::label(line);
    if (lab == "RINEX VERSION / TYPE") {
      version = num(r, line, 1, 9, "RINEX version");
      const char type = field(line, 21, 1)[0];
      if (type != 'N' && type != 'G' && type != 'L' && type != 'H' && type != 'B') {
        r.fail("not a RINEX navigation file (type '" + std::string(1, type) + "')");
      }
      file_sys = version >= 3.0 ? field(line, 41, 1)[0] : (type == 'N' ? 'G' : type);
    } else if (lab == "ION ALPHA" || lab == "ION BETA") {
      const int o = lab == "ION ALPHA" ? 0 : 4;
      for (int k = 0; k < 4; ++k) nav.gps_iono[o + k] = num(r, line, 3 + 12 * k, 12, "ION");
      nav.has_gps_iono = true;
    } else if (lab == "IONOSPHERIC CORR") {
      const std::string kind = rinex::trim(field(line, 1, 4));
      if (kind == "GPSA" || kind == "GPSB") {
        const int o = kind == "GPSA" ? 0 : 4;
        for (int k = 0; k < 4; ++k)
          nav.gps_iono[o + k] = num(r, line, 6 + 12 * k, 12, "IONOSPHERIC CORR");
        nav.has_gps_iono = true;
      }
    } else if (lab == "END OF HEADER") {
      header_done = true;
      break;
    }
  }
  if (!header_done) r.fail("END OF HEADER not found");
  if (version < 2.0 || version >= 5.0) r.fail("unsupported RINEX version");
  const bool v3 = version >= 3.0;

  while (r.next(line)) {
    if (rinex::trim(line).empty()) continue;
    const long first_line = r.line_no;
    SatId sat;
    CalendarTime toc;
    int clock_col;
    if (v3) {
      if (!parseSatId(field(line, 1, 3), sat))
        r.fail("bad satellite id '" + field(line, 1, 3) + "'");
      toc.year = integer(r, line, 5, 4, "year", 1980, 2200);
      toc.month = integer(r, line, 10, 2, "month", 1, 12);
      toc.day = integer(r, line, 13, 2, "day", 1, 31);
      toc.hour = integer(r, line, 16, 2, "hour", 0, 24);
      toc.minute = integer(r, line, 19, 2, "minute", 0, 59);
      toc.second = num(r, line, 22, 2, "second");
      clock_col = 24;
    } else {
      const std::string id = field(line, 1, 2);
      if (!parseSatId(std::string(1, file_sys) + (id[0] == ' ' ? "0" + id.substr(1) : id), sat)) {
        r.fail("bad satellite number '" + id + "'");
      }
      const int yy = integer(r, line, 4, 2, "year", 0, 99);
      toc.year = yy < 80 ? 2000 + yy : 1900 + yy;
      toc.month = integer(r, line, 7, 2, "month", 1, 12);
      toc.day = integer(r, line, 10, 2, "day", 1, 31);
      toc.hour = integer(r, line, 13, 2, "hour", 0, 24);
      toc.minute = integer(r, line, 16, 2, "minute", 0, 59);
      toc.second = num(r, line, 18, 5, "second");
      clock_col = 23;
    }
    if (toc.month < 1 || toc.month > 12 || toc.day < 1 || toc.day > 31 || toc.hour > 24 ||
        toc.minute > 59 || toc.second >= 61.0) {
      r.fail("bad epoch of clock");
    }
    const char sys = static_cast<char>(sat.sys);
    const int lines = v3 ? recordLines(sys) : (file_sys == 'G' ? 8 : 4);
    Ephemeris e;
    e.sat = sat;
    e.af0 = num(r, line, clock_col, 19, "af0");
    e.af1 = num(r, line, clock_col + 19, 19, "af1");
    e.af2 = num(r, line, clock_col + 38, 19, "af2");
    std::array<double, 28> orbit{};
    const int start = v3 ? 5 : 4;
    for (int k = 1; k < lines; ++k) {
      if (!r.next(line)) {
        throw DataError(path, r.line_no,
                        "record of " + sat.str() + " from line " + std::to_string(first_line) +
                            " is truncated");
      }
      for (int j = 0; j < 4 && k <= 7; ++j) {
        const std::size_t idx = static_cast<std::size_t>((k - 1) * 4 + j);
        orbit[idx] = num(r, line, start + 19 * j, 19, "broadcast orbit");
      }
    }
    if (!isSupported(sat.sys) || lines != 8) {
      ++nav.skipped_records;
      continue;
    }
    e.toc = gpsSecondsFromCalendar(toc) + (sat.sys == GnssSystem::kBeidou ? 14.0 : 0.0);
    const std::string bad = fillOrbit(e, orbit, sys);
    if (!bad.empty()) throw DataError(path, first_line, "record of " + sat.str() + ": " + bad);
    if (!(e.sqrt_a > 1000.0) || e.e < 0.0 || e.e >= 1.0) {
      throw DataError(path, first_line, "implausible orbit for " + sat.str() + " (sqrt(A), e)");
    }
    nav.ephemerides.push_back(e);
  }
  return nav;
}

NavData mergeNav(const std::vector<NavData>& parts) {
  NavData out;
  for (const auto& p : parts) {
    if (p.has_gps_iono && !out.has_gps_iono) {
      out.gps_iono = p.gps_iono;
      out.has_gps_iono = true;
    }
    out.skipped_records += p.skipped_records;
    for (const auto& e : p.ephemerides) {
      const bool dup =
          std::any_of(out.ephemerides.begin(), out.ephemerides.end(), [&](const Ephemeris& o) {
            return o.sat == e.sat && o.toe == e.toe && o.data_source == e.data_source;
          });
      if (!dup) out.ephemerides.push_back(e);
    }
  }
  return out;
}

}  // namespace giocal
