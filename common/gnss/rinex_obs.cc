#include "common/gnss/rinex_obs.h"

#include <cmath>
#include <fstream>

#include "common/gnss/rinex_fields.h"
#include "common/io/data_error.h"
#include "common/time/gps_time.h"

namespace giocal {

namespace {

using rinex::field;

class Reader {
 public:
  explicit Reader(const std::string& path) : in_(path), path_(path) {
    if (!in_) throw DataError(path, 0, "cannot open file");
  }
  bool next(std::string& line) {
    if (!std::getline(in_, line)) return false;
    cut_ = in_.eof();  // the file ends without the line's newline: a write cut short
    ++line_no_;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
  }
  void need(std::string& line, const std::string& what) {
    if (!next(line)) throw CutShort(path_, line_no_, "file ends inside " + what + " (truncated)");
  }
  // The end of the file inside a record: a recording cut short, recoverable for the last epoch.
  struct CutShort : DataError {
    using DataError::DataError;
  };
  [[noreturn]] void fail(const std::string& what) const { throw DataError(path_, line_no_, what); }
  double num(const std::string& line, int col, int width, const std::string& what,
             double blank = 0.0) {
    double v = 0.0;
    if (!rinex::number(field(line, col, width), blank, v)) {
      fail("bad " + what + ": '" + rinex::trim(field(line, col, width)) + "'");
    }
    return v;
  }
  /// A whole number within [min, max] (fields that become ints: dates, counts, flags).
  int integer(const std::string& line, int col, int width, const std::string& what, int min,
              int max) {
    int v = 0;
    if (!rinex::integer(num(line, col, width, what), min, max, v)) {
      fail("bad " + what + ": '" + rinex::trim(field(line, col, width)) +
           "' (a whole number from " + std::to_string(min) + " to " + std::to_string(max) + ")");
    }
    return v;
  }
  long lineNo() const { return line_no_; }
  const std::string& path() const { return path_; }
  bool lastLineCut() const { return cut_; }
  bool atEnd() { return in_.peek() == std::char_traits<char>::eof(); }

 private:
  std::ifstream in_;
  std::string path_;
  long line_no_ = 0;
  bool cut_ = false;
};

// RINEX 2 observation types mapped onto RINEX 3 codes.
std::string codeFromV2(const std::string& t) {
  if (t.size() != 2) return "";
  const char type = t[0], band = t[1];
  if (type == 'P') return std::string("C") + band + "W";
  if (type == 'C') return std::string("C") + band + (band == '1' ? 'C' : band == '2' ? 'C' : 'X');
  if (type == 'L' || type == 'D' || type == 'S') {
    return std::string(1, type) + band + (band == '1' ? 'C' : band == '2' ? 'W' : 'X');
  }
  return "";
}

// Stores one observation value into the satellite's signal list.
void store(SatObs& so, const std::string& code, double value, int lli) {
  if (code.size() != 3 || std::isnan(value)) return;
  const char type = code[0], band = code[1], attr = code[2];
  if (type != 'C' && type != 'L' && type != 'D' && type != 'S') return;
  SignalObs* sig = nullptr;
  for (auto& s : so.signals) {
    if (s.band == band && s.attr == attr) sig = &s;
  }
  if (!sig) {
    so.signals.push_back({});
    sig = &so.signals.back();
    sig->band = band;
    sig->attr = attr;
  }
  switch (type) {
    case 'C':
      sig->P = value;
      break;
    case 'L':
      sig->L = value;
      sig->lli = lli;
      break;
    case 'D':
      sig->D = value;
      break;
    case 'S':
      sig->S = value;
      break;
  }
}

// Reads one value field (F14.3, LLI, SSI) of 16 characters at `col`.
void readValue(Reader& r, const std::string& line, int col, double& value, int& lli) {
  const std::string text = field(line, col, 14);
  if (rinex::trim(text).empty()) {
    value = std::nan("");
    lli = 0;
    return;
  }
  value = r.num(line, col, 14, "observation value");
  const char l = field(line, col + 14, 1)[0];
  lli = (l >= '0' && l <= '9') ? l - '0' : 0;
}

double epochTime(Reader& r, const std::string& line, bool v3, double time_offset) {
  CalendarTime c;
  if (v3) {
    c.year = r.integer(line, 3, 4, "epoch year", 1980, 2200);
    c.month = r.integer(line, 8, 2, "epoch month", 1, 12);
    c.day = r.integer(line, 11, 2, "epoch day", 1, 31);
    c.hour = r.integer(line, 14, 2, "epoch hour", 0, 24);
    c.minute = r.integer(line, 17, 2, "epoch minute", 0, 59);
    c.second = r.num(line, 19, 11, "epoch second");
  } else {
    const int yy = r.integer(line, 2, 2, "epoch year", 0, 99);
    c.year = yy < 80 ? 2000 + yy : 1900 + yy;
    c.month = r.integer(line, 5, 2, "epoch month", 1, 12);
    c.day = r.integer(line, 8, 2, "epoch day", 1, 31);
    c.hour = r.integer(line, 11, 2, "epoch hour", 0, 24);
    c.minute = r.integer(line, 14, 2, "epoch minute", 0, 59);
    c.second = r.num(line, 16, 11, "epoch second");
  }
  if (c.month < 1 || c.month > 12 || c.day < 1 || c.day > 31 || c.hour > 23 || c.minute > 59 ||
      c.second < 0.0 || c.second >= 61.0) {
    r.fail("bad epoch date/time");
  }
  return gpsSecondsFromCalendar(c) + time_offset;
}

}  // namespace

struct RinexObsReader::State {
  explicit State(const std::string& path) : r(path) {}
  Reader r;
  ObsHeader h;
  bool v3 = false;
  char file_sys = 'G';
  std::vector<std::string> v2_types;
  double time_offset = 0.0;  // added to epoch times to get GPS time
  double last_t = -1e300;
  int skipped = 0;
  PhaseAlignment alignment;
  // Recoverable damage dropped: epochs repeating or going back in time, a cut last epoch.
  long out_of_order = 0, first_out_of_order = 0, bad_run = 0;
  long cut_epoch_line = 0;
  long epoch_line = 0;  // line of the epoch record being read
};

constexpr long kMaxBadEpochRun = 10;

RinexObsReader::~RinexObsReader() = default;
const ObsHeader& RinexObsReader::header() const { return s_->h; }
int RinexObsReader::skippedSpecialRecords() const { return s_->skipped; }

std::vector<std::string> RinexObsReader::warnings() const {
  std::vector<std::string> out;
  const std::string& path = s_->r.path();
  if (s_->out_of_order > 0) {
    out.push_back(path + ":" + std::to_string(s_->first_out_of_order) + ": " +
                  std::to_string(s_->out_of_order) +
                  " epochs repeating the previous time or going backwards dropped (first here)");
  }
  if (s_->cut_epoch_line > 0) {
    out.push_back(path + ":" + std::to_string(s_->cut_epoch_line) +
                  ": the file ends inside this epoch (a recording cut short): epoch dropped");
  }
  const std::vector<std::string>& aligned = s_->alignment.warnings();
  out.insert(out.end(), aligned.begin(), aligned.end());
  return out;
}

RinexObsReader::RinexObsReader(const std::string& path, bool align)
    : s_(std::make_unique<State>(path)) {
  Reader& r = s_->r;
  ObsHeader& h = s_->h;
  char& file_sys = s_->file_sys;
  std::vector<std::string>& v2_types = s_->v2_types;
  double& time_offset = s_->time_offset;
  std::string line;
  bool header_done = false;
  char pending_sys = 0;  // SYS / # / OBS TYPES continuation state
  int pending_count = 0;
  int v2_count = 0;
  while (r.next(line)) {
    const std::string lab = rinex::label(line);
    if (lab == "RINEX VERSION / TYPE") {
      h.version = r.num(line, 1, 9, "RINEX version");
      if (field(line, 21, 1)[0] != 'O') r.fail("not a RINEX observation file");
      file_sys = field(line, 41, 1)[0] == ' ' ? 'G' : field(line, 41, 1)[0];
    } else if (lab == "MARKER NAME") {
      h.marker = rinex::trim(field(line, 1, 60));
    } else if (lab == "APPROX POSITION XYZ") {
      for (int k = 0; k < 3; ++k)
        h.approx_position[k] = r.num(line, 1 + 14 * k, 14, "approx position");
    } else if (lab == "ANTENNA: DELTA H/E/N") {
      for (int k = 0; k < 3; ++k)
        h.antenna_delta_hen[k] = r.num(line, 1 + 14 * k, 14, "antenna delta");
    } else if (lab == "INTERVAL") {
      h.interval = r.num(line, 1, 10, "interval");
    } else if (lab == "# / TYPES OF OBSERV") {
      if (rinex::trim(field(line, 1, 6)).size())
        v2_count = r.integer(line, 1, 6, "number of types", 0, 999);
      for (int k = 0; k < 9 && static_cast<int>(v2_types.size()) < v2_count; ++k) {
        v2_types.push_back(rinex::trim(field(line, 11 + 6 * k, 2)));
      }
    } else if (lab == "SYS / # / OBS TYPES") {
      if (field(line, 1, 1)[0] != ' ') {
        pending_sys = field(line, 1, 1)[0];
        pending_count = r.integer(line, 4, 3, "number of observation types", 0, 999);
        h.obs_types[pending_sys].clear();
      }
      if (!pending_sys) r.fail("observation types continuation without a system");
      auto& types = h.obs_types[pending_sys];
      for (int k = 0; k < 13 && static_cast<int>(types.size()) < pending_count; ++k) {
        types.push_back(field(line, 8 + 4 * k, 3));
      }
    } else if (lab == "SYS / PHASE SHIFT") {
      const char sys = field(line, 1, 1)[0];
      const std::string code = rinex::trim(field(line, 3, 3));
      double shift = 0.0;
      if (sys != ' ' && !code.empty() && rinex::number(field(line, 7, 8), 0.0, shift)) {
        h.phase_shift[{sys, code}] = shift;
      }
    } else if (lab == "TIME OF FIRST OBS") {
      const std::string ts = rinex::trim(field(line, 49, 3));
      if (ts == "BDT") time_offset = 14.0;
      if (ts == "GLO") r.fail("GLONASS (UTC) time tags are not supported; convert to GPS time");
    } else if (lab == "END OF HEADER") {
      header_done = true;
      break;
    }
  }
  if (!header_done) r.fail("END OF HEADER not found");
  if (h.version < 2.0 || h.version >= 5.0) r.fail("unsupported RINEX version");
  const bool v3 = s_->v3 = h.version >= 3.0;
  if (!v3) {
    if (v2_types.empty()) r.fail("no '# / TYPES OF OBSERV' in the header");
    auto& types = h.obs_types[file_sys == 'M' ? 'G' : file_sys];
    for (const auto& t : v2_types) types.push_back(codeFromV2(t));
  }
  if (align && hasSeveralPhasesOnABand(h)) {
    // A first pass for the alignment check; damage it meets is left to the reading to report.
    RinexObsReader scan(path, false);
    ObsEpoch e;
    try {
      while (scan.next(e)) s_->alignment.add(e);
    } catch (const DataError&) {
    }
    s_->alignment.decide(path);
  }
}

const std::vector<SignalOffset>& RinexObsReader::phaseOffsets() const {
  return s_->alignment.offsets();
}

bool RinexObsReader::next(ObsEpoch& out) {
  const long start = s_->r.lineNo() + 1;
  try {
    while (true) {
      if (!nextEpoch(out)) return false;
      if (out.t > s_->last_t) {
        s_->last_t = out.t;
        s_->bad_run = 0;
        s_->alignment.apply(out);
        return true;
      }
      // One epoch repeated or out of order is dropped; a run of them is a clock jump or a broken
      // file.
      if (s_->out_of_order++ == 0) s_->first_out_of_order = s_->epoch_line;
      if (++s_->bad_run > kMaxBadEpochRun) {
        throw DataError(
            s_->r.path(), s_->epoch_line,
            std::to_string(s_->bad_run) + " epochs in a row repeat the time or go backwards");
      }
    }
  } catch (const Reader::CutShort&) {
    s_->cut_epoch_line = std::max(start, s_->epoch_line);
    return false;
  }
}

bool RinexObsReader::nextEpoch(ObsEpoch& out) {
  Reader& r = s_->r;
  ObsHeader& h = s_->h;
  const bool v3 = s_->v3;
  const char file_sys = s_->file_sys;
  const std::vector<std::string>& v2_types = s_->v2_types;
  std::string line;
  while (r.next(line)) {
    if (rinex::trim(line).empty()) continue;
    s_->epoch_line = r.lineNo();
    if (v3 && line[0] != '>') r.fail("expected an epoch record starting with '>'");
    if (line.size() < (v3 ? 35u : 32u)) {
      if (r.atEnd()) throw Reader::CutShort(r.path(), r.lineNo(), "epoch line is truncated");
      r.fail("epoch line is truncated");
    }
    const int flag = r.integer(line, v3 ? 32 : 29, 1, "epoch flag", 0, 6);
    const int nsat = r.integer(line, v3 ? 33 : 30, 3, "number of satellites", 0, 999);
    if (flag < 0 || flag > 6 || nsat < 0) r.fail("bad epoch flag or satellite count");
    if (flag >= 2 && flag <= 6) {
      // Special records (2-5: header lines; 6: cycle-slip records) are skipped.
      int lines = nsat;
      if (flag == 6 && !v3) {
        // RINEX 2 slip records are observation records: satellites may continue the epoch line.
        lines = 0;
        for (int s = 0; s < nsat; ++s) {
          lines += (static_cast<int>(v2_types.size()) + 4) / 5;
        }
        for (int k = 12; k < nsat; k += 12) r.need(line, "satellite list");
      }
      for (int k = 0; k < lines; ++k)
        r.need(line, "special records of epoch flag " + std::to_string(flag));
      ++s_->skipped;
      continue;
    }
    ObsEpoch ep;
    ep.t = epochTime(r, line, v3, s_->time_offset);
    ep.flag = flag;
    if (v3) {
      ep.rx_clock_offset = r.num(line, 42, 15, "receiver clock offset");
      for (int s = 0; s < nsat; ++s) {
        r.need(line, "epoch record");
        SatObs so;
        if (!parseSatId(field(line, 1, 3), so.sat))
          r.fail("bad satellite id '" + field(line, 1, 3) + "'");
        const char sys = static_cast<char>(so.sat.sys);
        const auto it = h.obs_types.find(sys);
        if (it == h.obs_types.end())
          r.fail("satellite system " + std::string(1, sys) + " has no observation types");
        for (size_t k = 0; k < it->second.size(); ++k) {
          double v;
          int lli;
          readValue(r, line, 4 + 16 * static_cast<int>(k), v, lli);
          store(so, it->second[k], v, lli);
        }
        if (isSupported(so.sat.sys)) ep.sats.push_back(std::move(so));
      }
    } else {
      ep.rx_clock_offset = r.num(line, 69, 12, "receiver clock offset");
      std::vector<std::string> ids;
      std::string list_line = line;
      for (int s = 0; s < nsat; ++s) {
        if (s > 0 && s % 12 == 0) r.need(list_line, "satellite list");
        ids.push_back(field(list_line, 33 + 3 * (s % 12), 3));
      }
      const auto& types = h.obs_types[file_sys == 'M' ? 'G' : file_sys];
      for (const auto& id : ids) {
        SatObs so;
        if (!parseSatId(id, so.sat)) r.fail("bad satellite id '" + id + "'");
        for (size_t k = 0; k < types.size(); ++k) {
          if (k % 5 == 0) r.need(line, "observation record of " + so.sat.str());
          double v;
          int lli;
          readValue(r, line, 1 + 16 * static_cast<int>(k % 5), v, lli);
          store(so, types[k], v, lli);
        }
        if (isSupported(so.sat.sys)) ep.sats.push_back(std::move(so));
      }
    }
    if (r.lastLineCut()) throw Reader::CutShort(r.path(), r.lineNo(), "last line cut short");
    out = std::move(ep);
    return true;
  }
  return false;
}

ObsData readRinexObs(const std::string& path) {
  RinexObsReader reader(path);
  ObsData data;
  data.header = reader.header();
  ObsEpoch e;
  while (reader.next(e)) data.epochs.push_back(std::move(e));
  data.skipped_special_records = reader.skippedSpecialRecords();
  data.warnings = reader.warnings();
  return data;
}

}  // namespace giocal
