#include "import/gnss_comm_messages.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "import/observation_log.h"

namespace giocal::import {

namespace {

constexpr double kWeek = 604800.0;
constexpr long kGps = 32, kGlonass = 27, kGalileo = 38, kBeidou = 63;

bool isType(const std::string& type, const std::string& name) {
  return type == "gnss_comm/" + name || type == "gnss_comm/msg/" + name;
}

// A message's integer field as int; -1 for values no int holds (a bag's definition may say float).
int whole(double v) { return std::isfinite(v) && std::abs(v) < 2e9 ? static_cast<int>(v) : -1; }

// RTKLIB's observation code numbers, which gnss_comm's `code` carries, as RINEX 3 band and
// attribute ("1C" is code 1).
const std::array<const char*, 44> kCodes = {
    "",   "1C", "1P", "1W", "1Y", "1M", "1N", "1S", "1L", "1E", "1A", "1B", "1X", "1Z", "2C",
    "2D", "2S", "2L", "2X", "2P", "2W", "2Y", "2M", "2N", "5I", "5Q", "5X", "7I", "7Q", "7X",
    "6A", "6B", "6C", "6X", "6Z", "6S", "6L", "8L", "8Q", "8X", "2I", "2Q", "6I", "6Q"};

// The band of a carrier frequency for a system, 0 when it is none giocal knows.
char bandOf(GnssSystem sys, double hz) {
  for (char band : std::string("125678")) {
    const double f = carrierFrequency(sys, band);
    if (f > 0.0 && std::abs(f - hz) < 1e3) return band;
  }
  return 0;
}

// The attribute of the code when it names this band; else the usual signal of the band.
char attributeOf(GnssSystem sys, char band, double code) {
  const long c = whole(code);
  if (c > 0 && c < static_cast<long>(kCodes.size()) && kCodes[c][0] == band) return kCodes[c][1];
  if (sys == GnssSystem::kBeidou) return 'I';
  if (sys == GnssSystem::kGps) return band == '2' ? 'L' : band == '5' ? 'Q' : 'C';
  return band == '1' || band == '6' ? 'C' : 'Q';
}

// Element k of the array at `path`, NaN when the array is shorter.
double element(const RosMessage& m, const std::string& path, std::size_t k) {
  return k < m.length(path) ? m.number(path + "[" + std::to_string(k) + "]") : NAN;
}

double gpsSeconds(const RosMessage& m, const std::string& path) {
  return m.number(path + ".week") * kWeek + m.number(path + ".tow");
}

}  // namespace

bool isGnssCommMeas(const std::string& type) { return isType(type, "GnssMeasMsg"); }
bool isGnssCommEphem(const std::string& type) { return isType(type, "GnssEphemMsg"); }

bool gnssCommSatellite(long n, SatId& out) {
  const std::array<std::pair<GnssSystem, long>, 4> ranges = {{{GnssSystem::kGps, kGps},
                                                              {GnssSystem::kGlonass, kGlonass},
                                                              {GnssSystem::kGalileo, kGalileo},
                                                              {GnssSystem::kBeidou, kBeidou}}};
  if (n <= 0) return false;
  for (const auto& [sys, count] : ranges) {
    if (n <= count) {
      out = {sys, static_cast<int>(n)};
      return true;
    }
    n -= count;
  }
  return false;
}

long gnssCommNumber(const SatId& sat) {
  switch (sat.sys) {
    case GnssSystem::kGps:
      return sat.prn <= kGps ? sat.prn : 0;
    case GnssSystem::kGlonass:
      return sat.prn <= kGlonass ? kGps + sat.prn : 0;
    case GnssSystem::kGalileo:
      return sat.prn <= kGalileo ? kGps + kGlonass + sat.prn : 0;
    case GnssSystem::kBeidou:
      return sat.prn <= kBeidou ? kGps + kGlonass + kGalileo + sat.prn : 0;
    default:
      return 0;
  }
}

void GnssCommDecoder::addMeasurements(const RosMessage& m, const std::string& where) {
  const std::size_t n = m.length("meas");
  if (n == 0) return;
  ObsEpoch epoch;
  epoch.t = gpsSeconds(m, "meas[0].time");
  if (!std::isfinite(epoch.t) || epoch.t <= 0.0) {
    if (log_.rawx_rejected++ == 0)
      log_.warnings.push_back(source_ + ": " + where + ": measurement time not valid");
    return;
  }
  RawxCounts& c = log_.rawx;
  for (std::size_t k = 0; k < n; ++k) {
    const std::string e = "meas[" + std::to_string(k) + "].";
    const std::size_t signals = m.length(e + "freqs");
    c.measurements += static_cast<long long>(signals);
    if (std::abs(gpsSeconds(m, e + "time") - epoch.t) > 1e-3) {
      ++mixed_times_;  // one message is one epoch; a satellite of another time is not in it
      continue;
    }
    SatObs sat;
    if (!gnssCommSatellite(whole(m.number(e + "sat")), sat.sat) || !isSupported(sat.sat.sys)) {
      c.unsupported_system += static_cast<long long>(signals);
      continue;
    }
    for (std::size_t i = 0; i < signals; ++i) {
      SignalObs g;
      g.band = bandOf(sat.sat.sys, element(m, e + "freqs", i));
      if (g.band == 0) {
        ++c.unknown_signal;
        continue;
      }
      g.attr = attributeOf(sat.sat.sys, g.band, element(m, e + "code", i));
      // status: bit 0 code valid, bit 1 phase valid (u-blox trkStat); without it, zero is none.
      const double status = element(m, e + "status", i);
      const int bits = whole(status);
      const double psr = element(m, e + "psr", i), cp = element(m, e + "cp", i);
      const bool code_ok = std::isfinite(psr) && psr > 0.0 && (bits < 0 || (bits & 1));
      const bool phase_ok = std::isfinite(cp) && cp != 0.0 && (bits < 0 || (bits & 2));
      if (!code_ok) ++c.invalid_code;
      if (!phase_ok) ++c.invalid_phase;
      if (!code_ok && !phase_ok) continue;
      if (code_ok) g.P = psr;
      if (phase_ok) g.L = cp;
      const double dopp = element(m, e + "dopp", i), cn0 = element(m, e + "CN0", i);
      if (std::isfinite(dopp) && dopp != 0.0) g.D = dopp;
      if (std::isfinite(cn0) && cn0 > 0.0) g.S = cn0;
      const double lli = element(m, e + "LLI", i);
      g.lli = std::max(whole(lli), 0) & 3;  // RTKLIB's bits are RINEX's
      sat.signals.push_back(g);
    }
    if (!sat.signals.empty()) epoch.sats.push_back(std::move(sat));
  }
  ++c.epochs;
  if (!log_.obs.epochs.empty() && epoch.t <= log_.obs.epochs.back().t) {
    if (log_.epochs_out_of_order++ == 0) first_out_of_order_ = where;
    return;
  }
  if (!epoch.sats.empty()) log_.obs.epochs.push_back(std::move(epoch));
}

void GnssCommDecoder::addEphemeris(const RosMessage& m, const std::string& where) {
  ++log_.subframes;
  Ephemeris eph;
  if (!gnssCommSatellite(whole(m.number("sat")), eph.sat) || eph.sat.sys == GnssSystem::kGlonass) {
    ++log_.subframes_not_read;
    return;
  }
  eph.toe = gpsSeconds(m, "toe");
  eph.toc = gpsSeconds(m, "toc");
  eph.sqrt_a = std::sqrt(m.number("A"));
  eph.e = m.number("e");
  eph.i0 = m.number("i0");
  eph.omega = m.number("omg");
  eph.omega0 = m.number("OMG0");
  eph.m0 = m.number("M0");
  eph.delta_n = m.number("delta_n");
  eph.omega_dot = m.number("OMG_dot");
  eph.idot = m.number("i_dot");
  eph.cuc = m.number("cuc");
  eph.cus = m.number("cus");
  eph.crc = m.number("crc");
  eph.crs = m.number("crs");
  eph.cic = m.number("cic");
  eph.cis = m.number("cis");
  eph.af0 = m.number("af0");
  eph.af1 = m.number("af1");
  eph.af2 = m.number("af2");
  eph.iode = m.number("iode");
  eph.iodc = m.number("iodc");
  eph.health = whole(m.number("health"));
  eph.accuracy = m.number("ura");  // metres, as in RINEX
  // RTKLIB's order: Galileo tgd0 is BGD E1/E5a and tgd1 BGD E1/E5b; giocal keeps E5b first.
  const bool galileo = eph.sat.sys == GnssSystem::kGalileo;
  eph.tgd = galileo ? m.number("tgd1") : m.number("tgd0");
  eph.tgd2 = galileo ? m.number("tgd0") : m.number("tgd1");
  if (galileo) eph.data_source = std::max(whole(m.number("code")), 0);  // RINEX data sources
  const double values[] = {eph.toe, eph.toc,       eph.sqrt_a, eph.e,   eph.m0,  eph.af0,
                           eph.af1, eph.omega_dot, eph.i0,     eph.cuc, eph.crs, eph.tgd};
  bool ok = eph.sqrt_a > 0.0 && eph.e >= 0.0 && eph.e < 1.0 && eph.toe > 0.0;
  for (double v : values) ok = ok && std::isfinite(v);
  if (!ok) {
    if (log_.subframes_rejected++ == 0) first_bad_ephemeris_ = where;
    return;
  }
  log_.nav.ephemerides.push_back(eph);
}

UbxLog GnssCommDecoder::finish() {
  UbxLog log = std::move(log_);
  if (log.obs.epochs.empty())
    throw std::runtime_error(source_ +
                             ": no gnss_comm/GnssMeasMsg epoch with a GPS, Galileo or "
                             "BeiDou measurement");
  log.nav = mergeNav({log.nav});  // drivers publish an ephemeris again at every reception
  if (log.epochs_out_of_order > 0) {
    log.warnings.push_back(source_ + ": " + first_out_of_order_ + ": " +
                           std::to_string(log.epochs_out_of_order) +
                           " GnssMeasMsg epochs not after the previous one dropped (first here)");
  }
  if (mixed_times_ > 0) {
    log.warnings.push_back(source_ + ": " + std::to_string(mixed_times_) +
                           " satellites timed apart from their message's epoch dropped");
  }
  if (log.subframes_rejected > 0) {
    log.warnings.push_back(source_ + ": " + first_bad_ephemeris_ + ": " +
                           std::to_string(log.subframes_rejected) +
                           " GnssEphemMsg with impossible orbits dropped (first here)");
  }
  log.obs.header.marker = "gnss_comm";
  describeObservations(log.obs);
  return log;
}

}  // namespace giocal::import
