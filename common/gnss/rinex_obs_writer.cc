#include "common/gnss/rinex_obs_writer.h"

#include <cmath>
#include <cstdio>

#include "common/gnss/rinex_fields.h"
#include "common/io/atomic_file.h"
#include "common/time/gps_time.h"

namespace giocal {

namespace {

using rinex::headerLine;

double valueOf(const SignalObs& s, char type) {
  switch (type) {
    case 'C':
      return s.P;
    case 'L':
      return s.L;
    case 'D':
      return s.D;
    case 'S':
      return s.S;
  }
  return std::nan("");
}

}  // namespace

void writeRinexObs(const std::string& path, const RinexObsHeader& h,
                   const std::vector<ObsEpoch>& epochs) {
  AtomicFile file(path);
  auto& out = file.stream();
  char buf[128];
  out << headerLine("     3.04           OBSERVATION DATA    M", "RINEX VERSION / TYPE");
  out << headerLine(h.program, "PGM / RUN BY / DATE");
  out << headerLine(h.marker, "MARKER NAME");
  out << headerLine("", "OBSERVER / AGENCY");
  out << headerLine(std::string(20, ' ') + h.receiver.substr(0, 20), "REC # / TYPE / VERS");
  out << headerLine(std::string(20, ' ') + h.antenna.substr(0, 20), "ANT # / TYPE");
  std::snprintf(buf, sizeof(buf), "%14.4f%14.4f%14.4f", h.approx_position.x(),
                h.approx_position.y(), h.approx_position.z());
  out << headerLine(buf, "APPROX POSITION XYZ");
  out << headerLine("        0.0000        0.0000        0.0000", "ANTENNA: DELTA H/E/N");
  for (const auto& [sys, types] : h.obs_types) {
    for (size_t k = 0; k < types.size(); k += 13) {
      std::string line = k == 0 ? std::string(1, sys) : " ";
      std::snprintf(buf, sizeof(buf), "  %3d", static_cast<int>(types.size()));
      line += k == 0 ? std::string(buf) : std::string(5, ' ');
      for (size_t j = k; j < std::min(types.size(), k + 13); ++j) line += " " + types[j];
      out << headerLine(line, "SYS / # / OBS TYPES");
    }
  }
  for (const auto& [sys, types] : h.obs_types) {
    for (const auto& t : types) {
      if (t[0] != 'L') continue;
      const auto shift = h.phase_shift.find({sys, t});
      std::snprintf(buf, sizeof(buf), "%c %s %8.5f", sys, t.c_str(),
                    shift == h.phase_shift.end() ? 0.0 : shift->second);
      out << headerLine(buf, "SYS / PHASE SHIFT");
    }
  }
  std::snprintf(buf, sizeof(buf), "%10.3f", h.interval);
  out << headerLine(buf, "INTERVAL");
  if (!epochs.empty()) {
    const CalendarTime c = calendarFromGpsSeconds(epochs.front().t);
    std::snprintf(buf, sizeof(buf), "  %4d    %2d    %2d    %2d    %2d   %10.7f     GPS", c.year,
                  c.month, c.day, c.hour, c.minute, c.second);
    out << headerLine(buf, "TIME OF FIRST OBS");
  }
  out << headerLine("", "END OF HEADER");
  for (const ObsEpoch& e : epochs) {
    // A time in GPS seconds carries about 0.2 us near 2025; round to the microsecond once, so
    // that 39.748 does not print as 39.7479999 nor 59.99999999 as 60.
    const double t = std::round(e.t * 1e6) / 1e6;
    const CalendarTime c = calendarFromGpsSeconds(t);
    std::snprintf(buf, sizeof(buf), "> %4d %02d %02d %02d %02d%11.7f  %d%3d", c.year, c.month,
                  c.day, c.hour, c.minute, c.second, e.flag, static_cast<int>(e.sats.size()));
    out << buf << "\n";
    for (const SatObs& so : e.sats) {
      out << so.sat.str();
      const auto& types = h.obs_types.at(static_cast<char>(so.sat.sys));
      for (const auto& code : types) {
        const SignalObs* sig = nullptr;
        for (const auto& s : so.signals) {
          if (s.band == code[1] && s.attr == code[2]) sig = &s;
        }
        const double v = sig ? valueOf(*sig, code[0]) : std::nan("");
        if (std::isnan(v)) {
          out << std::string(16, ' ');
        } else {
          std::snprintf(buf, sizeof(buf), "%14.3f%c ", v,
                        code[0] == 'L' && sig->lli ? static_cast<char>('0' + sig->lli) : ' ');
          out << buf;
        }
      }
      out << "\n";
    }
  }
  file.commit();
}

}  // namespace giocal
