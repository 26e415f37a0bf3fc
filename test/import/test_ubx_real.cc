// The real u-blox F9P log (data/real/ublox-f9p-walk) imported by giocal and, independently, by
// RTKLIB's convbin (Debian package rtklib): every observation and GPS ephemeris must agree; the
// Galileo ephemerides (convbin 2.4.3 writes none) must place the receiver where RTKLIB's solution
// of the walk does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <tuple>

#include "common/geodesy/wgs84.h"
#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/pos_reader.h"
#include "common/gnss/rinex_nav.h"
#include "common/gnss/rinex_nav_writer.h"
#include "common/gnss/rinex_obs.h"
#include "common/gnss/rinex_obs_writer.h"
#include "common/gnss/spp.h"
#include "import/ubx_log.h"
#include "import/ubx_reference.h"
#include "temp_dir.h"

namespace giocal {
namespace {

using test::compareEphemerides;
using test::convbin;
using test::Converted;
using test::giocalImport;

const std::string kLog = std::string(GIOCAL_SOURCE_DIR) + "/data/real/ublox-f9p-walk/gnss_1730.ubx";
const std::string kPos =
    std::string(GIOCAL_SOURCE_DIR) + "/data/real/ublox-f9p-walk/gnss_1730_sf.pos";

using SignalKey = std::tuple<double, SatId, char, char>;

std::map<SignalKey, SignalObs> signalsOf(const ObsData& d) {
  std::map<SignalKey, SignalObs> m;
  for (const ObsEpoch& e : d.epochs) {
    for (const SatObs& s : e.sats) {
      for (const SignalObs& g : s.signals) m[{std::round(e.t * 1e3), s.sat, g.band, g.attr}] = g;
    }
  }
  return m;
}

double diff(double a, double b) {
  if (std::isnan(a) != std::isnan(b)) return INFINITY;
  return std::isnan(a) ? 0.0 : std::abs(a - b);
}

TEST(UbxRealLog, EveryObservationAgreesWithConvbin) {
  test::TempDir dir;
  import::UbxLog log;
  const Converted ours = giocalImport(dir, kLog, log);
  const Converted ref = convbin(dir, kLog);
  ASSERT_EQ(ours.obs.epochs.size(), ref.obs.epochs.size());
  EXPECT_EQ(ours.obs.epochs.size(), 536u);  // SOURCE.txt
  // convbin 2.4.3 knows neither the L5, E5a, E6 nor any BeiDou signal id of this X20 log: those
  // are giocal's alone; every signal convbin writes must be in giocal's import, equal.
  const auto a = signalsOf(ours.obs), b = signalsOf(ref.obs);
  std::map<std::string, int> only_ours;
  double max_p = 0, max_l = 0, max_d = 0, max_s = 0;
  int lli_same = 0, compared = 0;
  std::set<std::tuple<SatId, char, char>> phases_seen;
  for (const auto& [key, g] : a) {
    const auto it = b.find(key);
    if (it == b.end()) {
      ++only_ours[std::string(1, static_cast<char>(std::get<1>(key).sys)) + std::get<2>(key) +
                  std::get<3>(key)];
      continue;
    }
    ++compared;
    max_p = std::max(max_p, diff(g.P, it->second.P));
    max_l = std::max(max_l, diff(g.L, it->second.L));
    max_d = std::max(max_d, diff(g.D, it->second.D));
    max_s = std::max(max_s, diff(g.S, it->second.S));
    // giocal marks the first valid phase of a signal as a new ambiguity (slip); convbin does not
    // when the signal's first records came without a valid phase (once in this log).
    const auto signal = std::make_tuple(std::get<1>(key), std::get<2>(key), std::get<3>(key));
    const bool first_phase = !std::isnan(g.L) && phases_seen.insert(signal).second;
    lli_same += g.lli == it->second.lli || (first_phase && g.lli == (it->second.lli | 1));
  }
  std::cout << "UBX import vs convbin: " << compared << " of convbin's " << b.size()
            << " signals (GPS, Galileo) in " << ours.obs.epochs.size()
            << " epochs; largest differences: code " << max_p << " m, phase " << max_l
            << " cycles, Doppler " << max_d << " Hz, C/N0 " << max_s << " dB-Hz; LLI equal in "
            << lli_same << "; giocal's alone:";
  for (const auto& [sig, n] : only_ours) std::cout << " " << sig << " " << n;
  std::cout << "\n";
  EXPECT_EQ(compared, static_cast<int>(b.size()));
  for (const auto& [sig, n] : only_ours) {
    EXPECT_TRUE(sig == "G5Q" || sig == "E5Q" || sig == "E6B" || sig[0] == 'C') << sig;
  }
  EXPECT_LE(max_p, 1e-3);
  EXPECT_LE(max_l, 1e-3);
  EXPECT_LE(max_d, 1e-3);
  EXPECT_LE(max_s, 1e-3);
  EXPECT_EQ(lli_same, compared);
  EXPECT_EQ(log.stream.bad_checksums, 0);
  EXPECT_FALSE(log.stream.truncated_end);
}

TEST(UbxRealLog, GpsEphemeridesAgreeWithConvbin) {
  test::TempDir dir;
  import::UbxLog log;
  const Converted ours = giocalImport(dir, kLog, log);
  const Converted ref = convbin(dir, kLog);
  EXPECT_GE(compareEphemerides(ours, ref, GnssSystem::kGps), 4);  // convbin's 4 in the 134 s
}

// Single point positions from one system's satellites only, in the ENU frame of RTKLIB's RTK
// solution of the walk (made with a base station giocal does not have: centimetres, so SPP's
// metres show), by epoch time.
std::map<long long, Eigen::Vector3d> sppEnu(const ObsData& obs, const NavData& nav,
                                            GnssSystem sys) {
  const BroadcastOrbits orbits(nav);
  const std::vector<PositionFix> ref = readPosFile(kPos);
  std::map<long long, Eigen::Vector3d> out;
  for (ObsEpoch e : obs.epochs) {
    e.sats.erase(std::remove_if(e.sats.begin(), e.sats.end(),
                                [&](const SatObs& s) { return s.sat.sys != sys; }),
                 e.sats.end());
    const SppSolution s = solveSpp(e, orbits, SppOptions{});
    const PositionFix* f = fixAt(ref, e.t, kPositionTolerance);
    if (!s.valid || !f) continue;
    out[std::llround(e.t * 1e3)] = LocalFrame(f->p_e).enuFromEcef(s.p_e);
  }
  return out;
}

double median(std::vector<double> v) {
  if (v.empty()) return INFINITY;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

TEST(UbxRealLog, GalileoEphemeridesPositionTheReceiverAsGpsDoes) {
  test::TempDir dir;
  import::UbxLog log;
  const Converted ours = giocalImport(dir, kLog, log);
  int galileo = 0;
  for (const Ephemeris& e : ours.nav.ephemerides) galileo += e.sat.sys == GnssSystem::kGalileo;
  const auto gal = sppEnu(ours.obs, ours.nav, GnssSystem::kGalileo);
  const auto gps = sppEnu(ours.obs, ours.nav, GnssSystem::kGps);
  std::vector<double> h_gal, h_gps, up_gal, up_gps, between;
  for (const auto& [t, p] : gal) {
    h_gal.push_back(p.head<2>().norm());
    up_gal.push_back(p.z());
    const auto it = gps.find(t);
    if (it != gps.end()) between.push_back((p - it->second).head<2>().norm());
  }
  for (const auto& [t, p] : gps) {
    h_gps.push_back(p.head<2>().norm());
    up_gps.push_back(p.z());
  }
  // No ionosphere model: the 134 s hold no GPS subframe 4 page 18 (broadcast every 12.5 min), so
  // both systems' heights carry the whole ionospheric delay; horizontally they must agree.
  std::cout << "UBX import: " << galileo << " Galileo ephemerides; single point positions without "
            << "an ionosphere model, median horizontal / up error against RTKLIB's solution: "
            << "Galileo only " << median(h_gal) << " / " << median(up_gal) << " m in " << gal.size()
            << " epochs, GPS only " << median(h_gps) << " / " << median(up_gps) << " m in "
            << gps.size() << "; Galileo vs GPS horizontally " << median(between) << " m\n";
  EXPECT_GE(galileo, 4);
  EXPECT_GE(gal.size(), 500u);
  EXPECT_LT(median(h_gal), 15.0);  // the reference's base position is not known to be exact
  EXPECT_LT(median(h_gps), 15.0);
  EXPECT_LT(median(between), 5.0);  // the check of Galileo's decoding: it agrees with GPS's
}

TEST(UbxRealLog, BeidouD1EphemeridesAgreeWithConvbin) {
  test::TempDir dir;
  import::UbxLog log;
  const Converted ours = giocalImport(dir, kLog, log);
  const Converted ref = convbin(dir, kLog);
  // The X20 log carries D1 on B3I; convbin decodes the MEO/IGSO satellites' whole frames.
  const int compared = compareEphemerides(ours, ref, GnssSystem::kBeidou);
  EXPECT_GE(compared, 4);
  // (giocal's SPP takes BeiDou on B1I, which this log does not carry: no position check here;
  // the orbit code is tested on the mosaic receiver's RINEX.)
  std::cout << "BeiDou D1 ephemerides equal to convbin's in every field: " << compared << "\n";
}

}  // namespace
}  // namespace giocal
