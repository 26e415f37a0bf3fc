#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "common/geodesy/wgs84.h"
#include "common/gnss/broadcast_orbits.h"
#include "common/gnss/double_difference.h"
#include "common/gnss/rinex_nav.h"
#include "common/gnss/rinex_obs.h"
#include "common/gnss/rtk_job.h"
#include "common/math/rotation.h"
#include "common/time/gps_time.h"
#include "sim/base_of_another_make.h"
#include "sim/simulator.h"
#include "temp_dir.h"

namespace giocal {
namespace {

sim::SimConfig paper() {
  return sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
}

double sigmaAt(double s0, double el) {
  return s0 * std::sqrt(1.0 + 1.0 / std::max(std::sin(el), 0.05));
}

TEST(GnssSimulation, DoubleDifferencesAtTheTruePositionsAreAtTheNoiseLevel) {
  const sim::SimConfig cfg = paper();
  const sim::SimulatedLogs logs = sim::simulate(cfg, 2);
  const BroadcastOrbits orbits(readRinexNav(cfg.gnss.nav_file));
  ASSERT_EQ(logs.gnss.rover.size(), 151u);
  double code_sq = 0, phase_sq = 0, dphase_sq = 0;
  int code_n = 0, phase_n = 0, dphase_n = 0;
  std::map<SatId, double> last_phase_residual;
  for (size_t k = 0; k < logs.gnss.rover.size(); ++k) {
    const ObsEpoch& r = logs.gnss.rover[k];
    const ObsEpoch& b = logs.gnss.base[k];
    const Eigen::Vector3d& x = logs.antenna_e[k];
    // GPS L1 double differences against the highest satellite.
    std::vector<SdGeometry> geo;
    std::vector<const SatObs*> ro, bo;
    for (const SatObs& s : r.sats) {
      const SatObs* sb = b.find(s.sat);
      if (s.sat.sys != GnssSystem::kGps || !sb) continue;
      const SignalObs* sr1 = s.bestOnBand('1');
      const SignalObs* sb1 = sb->bestOnBand('1');
      const auto pr = orbits.atReception(s.sat, r.t, sr1->P, '1', x);
      const auto pb = orbits.atReception(s.sat, b.t, sb1->P, '1', logs.gnss.base_e);
      SdGeometry g;
      g.sat = s.sat;
      g.sat_at_rover_e = pr->p_e;
      g.base_range = (pb->p_e - logs.gnss.base_e).norm();
      geo.push_back(g);
      ro.push_back(&s);
      bo.push_back(sb);
    }
    ASSERT_GE(geo.size(), 5u);
    std::vector<double> el(geo.size());
    const Geodetic gx = geodeticFromEcef(x);
    for (size_t i = 0; i < geo.size(); ++i) {
      const Eigen::Vector3d u = (geo[i].sat_at_rover_e - x).normalized();
      el[i] = std::asin((rotationEcefFromEnu(gx.lat, gx.lon).transpose() * u).z());
    }
    const size_t ref = static_cast<size_t>(std::max_element(el.begin(), el.end()) - el.begin());
    const double lambda = kSpeedOfLight / carrierFrequency(GnssSystem::kGps, '1');
    for (size_t i = 0; i < geo.size(); ++i) {
      if (i == ref) continue;
      const double dd_range = ddRange(x, geo[i], geo[ref], nullptr);
      auto sd = [&](size_t j, bool phase) {
        const SignalObs* a = ro[j]->bestOnBand('1');
        const SignalObs* c = bo[j]->bestOnBand('1');
        return phase ? (a->L - c->L) * lambda : a->P - c->P;
      };
      const double var_code =
          2 * (std::pow(sigmaAt(0.3, el[i]), 2) + std::pow(sigmaAt(0.3, el[ref]), 2));
      const double var_phase =
          2 * (std::pow(sigmaAt(0.003, el[i]), 2) + std::pow(sigmaAt(0.003, el[ref]), 2));
      const double code = sd(i, false) - sd(ref, false) - dd_range;
      code_sq += code * code / var_code;
      ++code_n;
      auto amb = [&](int rx, size_t j) { return logs.gnss.ambiguity.at({rx, geo[j].sat, '1'}); };
      const double dd_n = (amb(0, i) - amb(1, i)) - (amb(0, ref) - amb(1, ref));
      const double phase = sd(i, true) - sd(ref, true) - dd_range - lambda * dd_n;
      phase_sq += phase * phase;
      ++phase_n;
      // Epoch-to-epoch differences remove the slowly varying atmosphere and leave the noise.
      if (last_phase_residual.count(geo[i].sat) && k > 0) {
        const double d = phase - last_phase_residual[geo[i].sat];
        dphase_sq += d * d / (2 * var_phase);
        ++dphase_n;
      }
      last_phase_residual[geo[i].sat] = phase;
    }
  }
  const double code_rms = std::sqrt(code_sq / code_n);
  const double phase_rms = std::sqrt(phase_sq / phase_n);
  const double dphase_rms = std::sqrt(dphase_sq / dphase_n);
  std::cout << "DD code normalized RMS " << code_rms << ", DD phase residual RMS "
            << phase_rms * 1000
            << " mm (noise + 4 km atmosphere), time-differenced DD phase normalized RMS "
            << dphase_rms << "\n";
  EXPECT_NEAR(code_rms, 1.0, 0.15);
  EXPECT_LT(phase_rms, 0.02);
  EXPECT_NEAR(dphase_rms, 1.0, 0.15);
}

struct PosRow {
  int q;
  double lat, lon, h;
};

std::map<std::string, PosRow> readPos(const std::string& path) {
  std::map<std::string, PosRow> out;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '%') continue;
    std::istringstream ss(line);
    std::string d, t;
    PosRow r;
    ss >> d >> t >> r.lat >> r.lon >> r.h >> r.q;
    out[d + " " + t.substr(0, 8)] = r;
  }
  return out;
}

struct FixCount {
  int epochs = 0, fixed = 0, within = 0;  // fixed: Q = 1; within: fixed and inside the limit
};

// Fixed epochs and those within `limit` horizontally of the true antenna.
FixCount countFixes(const sim::SimulatedLogs& logs, const std::string& pos, double limit) {
  const auto rows = readPos(pos);
  FixCount c;
  c.epochs = static_cast<int>(logs.gnss.rover.size());
  for (size_t k = 0; k < logs.gnss.rover.size(); ++k) {
    const auto it =
        rows.find(formatCalendar(calendarFromGpsSeconds(logs.gnss.rover[k].t)).substr(0, 19));
    if (it == rows.end() || it->second.q != 1) continue;
    const LocalFrame f(logs.antenna_e[k]);
    const Eigen::Vector3d enu = f.enuFromEcef(ecefFromGeodetic(
        Geodetic{it->second.lat * kDegToRad, it->second.lon * kDegToRad, it->second.h}));
    ++c.fixed;
    c.within += enu.head<2>().norm() < limit;
  }
  return c;
}

// Share of epochs fixed and within 2 cm horizontal of the true antenna.
double fixedWithin2cm(const sim::SimulatedLogs& logs, const std::string& pos) {
  const FixCount c = countFixes(logs, pos, 0.02);
  return static_cast<double>(c.within) / static_cast<double>(c.epochs);
}

RtkJob rtkJob(const std::string& dataset, const Eigen::Vector3d& base_e, const std::string& out) {
  RtkJob job;
  job.rover = dataset + "/rover.obs";
  job.base = dataset + "/base.obs";
  job.nav = {dataset + "/nav.rnx"};
  job.base_pos = base_e;
  job.out = out;
  return job;
}

TEST(GnssSimulation, RtklibAndGiocalRtkFixThePaperPreset) {
  test::TempDir dir;
  const sim::SimConfig cfg = paper();
  const sim::SimulatedLogs logs = sim::simulate(cfg, 4);
  sim::writeDataset(logs, dir.file("paper"));
  const std::string d = dir.file("paper");
  const Eigen::Vector3d b = logs.gnss.base_e;
  char cmd[2048];
  std::ofstream(dir.file("sim.conf")) << "pos1-navsys=41\npos2-arthres=3\n";  // GPS+Galileo+BeiDou
  std::snprintf(
      cmd, sizeof(cmd),
      "rnx2rtkp -k %s -t -p 2 -f 2 -m 15 -r %.4f %.4f %.4f -o %s %s/rover.obs %s/base.obs "
      "%s/nav.rnx 2>/dev/null",
      dir.file("sim.conf").c_str(), b.x(), b.y(), b.z(), dir.file("rtklib.pos").c_str(), d.c_str(),
      d.c_str(), d.c_str());
  ASSERT_EQ(std::system(cmd), 0) << "rnx2rtkp (Debian package rtklib) must be installed: " << cmd;
  const double rtklib = fixedWithin2cm(logs, dir.file("rtklib.pos"));
  runRtk(rtkJob(d, b, dir.file("giocal.pos")));
  const double giocal = fixedWithin2cm(logs, dir.file("giocal.pos"));
  std::cout << "paper preset: epochs fixed within 2 cm horizontal: rnx2rtkp " << 100 * rtklib
            << " %, giocal rtk " << 100 * giocal << " %\n";
  EXPECT_GE(rtklib, 0.95);
  EXPECT_GE(giocal, 0.95);
}

// The field preset (GPS only, trees, a building on one side): what giocal rtk calls fixed is within
// 5 cm of the true antenna. Before the fixes of issue 23 (short blockages restarting ambiguities,
// restarts on a reference satellite's NLOS error, partial fixes of decimetre sigma called fixed)
// about one fix in ten under trees was wrong, some by tens of metres (bench/rtk_under_trees.sh).
TEST(GnssSimulation, GiocalRtkFixesUnderTreesAreWithin5cm) {
  test::TempDir dir;
  const sim::SimulatedLogs logs = sim::simulate(
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/field.yaml"), 3);
  sim::writeDataset(logs, dir.file("field"));
  runRtk(rtkJob(dir.file("field"), logs.gnss.base_e, dir.file("giocal.pos")));
  const FixCount c = countFixes(logs, dir.file("giocal.pos"), 0.05);
  std::cout << "field preset seed 3: " << c.fixed << " of " << c.epochs << " epochs fixed, "
            << c.fixed - c.within << " more than 5 cm from the true antenna\n";
  EXPECT_GE(c.fixed, c.epochs / 2);
  EXPECT_LE(c.fixed - c.within, c.fixed / 100);
}

TEST(GnssSimulation, ABaseOfAnotherMakeWritesItsSignalsAndPhaseShifts) {
  for (const bool aligned : {true, false}) {
    SCOPED_TRACE(aligned ? "aligned" : "raw phases");
    test::TempDir dir;
    const sim::SimulatedLogs logs = sim::simulate(test::paperWithBaseOfAnotherMake(aligned), 4);
    sim::writeDataset(logs, dir.file("d"));
    const ObsData base = readRinexObs(dir.file("d/base.obs"));
    const ObsData rover = readRinexObs(dir.file("d/rover.obs"));
    EXPECT_EQ(base.header.obs_types.at('G'),
              (std::vector<std::string>{"C1C", "L1C", "D1C", "S1C", "C2W", "L2W", "D2W", "S2W",
                                        "C2X", "L2X", "D2X", "S2X"}));
    EXPECT_EQ(rover.header.obs_types.at('G'),
              (std::vector<std::string>{"C1C", "L1C", "D1C", "S1C", "C2W", "L2W", "D2W", "S2W"}));
    EXPECT_EQ(rover.header.obs_types.at('J'),
              (std::vector<std::string>{"C1C", "L1C", "D1C", "S1C", "C2L", "L2L", "D2L", "S2L"}));
    // The record states the correction applied; a file of raw phases records none.
    const auto shift = [&](char sys, const char* code) {
      const auto it = base.header.phase_shift.find({sys, code});
      return it == base.header.phase_shift.end() ? 0.0 : it->second;
    };
    EXPECT_EQ(shift('G', "L2X"), aligned ? -0.25 : 0.0);
    EXPECT_EQ(shift('J', "L1X"), aligned ? 0.25 : 0.0);
    EXPECT_EQ(shift('G', "L2W"), 0.0);
    // Two signals of one band at one receiver: the same integer, so their phases differ by the
    // noise when aligned and by the raw offset (minus the correction) when not, as simulated;
    // the reader aligns the raw ones again and says so (phase_alignment.h).
    EXPECT_EQ(base.warnings.size(), aligned ? 0u : 2u);
    const RinexObsReader reader(dir.file("d/base.obs"));
    EXPECT_EQ(reader.phaseOffsets().size(), 2u);
    for (const SignalOffset& o : reader.phaseOffsets())
      EXPECT_NEAR(o.applied, aligned ? 0.0 : (o.sys == 'G' ? 0.25 : -0.25), 1e-12) << o.sys;
    int both = 0, x_only = 0, qzss = 0;
    double diff_sum = 0.0;
    for (const ObsEpoch& e : logs.gnss.base) {
      for (const SatObs& s : e.sats) {
        qzss += s.sat.sys == GnssSystem::kQzss;
        if (s.sat.sys != GnssSystem::kGps) continue;
        const SignalObs *w = nullptr, *x = nullptr;
        for (const SignalObs& g : s.signals) {
          if (g.band == '2' && g.attr == 'W') w = &g;
          if (g.band == '2' && g.attr == 'X') x = &g;
        }
        ASSERT_NE(x, nullptr) << s.sat.str();
        x_only += w == nullptr;  // below 25 degrees
        if (!w) continue;
        ++both;
        diff_sum += x->L - w->L;
        EXPECT_NEAR(x->L - w->L, aligned ? 0.0 : 0.25, 0.1) << s.sat.str();
      }
    }
    EXPECT_GT(both, 500);
    EXPECT_GT(x_only, 100);
    EXPECT_GT(qzss, 100);  // Michibiki's ephemerides (health 1) are used
    EXPECT_NEAR(diff_sum / both, aligned ? 0.0 : 0.25, 0.01);
  }
}

// giocal rtk against such a base: with aligned phases (what RINEX 3.01 and later require) it
// fixes as against a base of its own make; with raw phases too, since the reader aligns them
// (before it did, 2026-12-01, 97 of 151: a satellite whose base signal differed from its
// group's by a quarter cycle could not fix, and the fix was withheld, none wrong).
TEST(GnssSimulation, GiocalRtkFixesAgainstABaseOfAnotherMake) {
  test::TempDir dir;
  sim::SimConfig same = paper();
  same.gnss.systems = "GECJ";
  FixCount c[3];
  const sim::SimConfig cfgs[3] = {same, test::paperWithBaseOfAnotherMake(true),
                                  test::paperWithBaseOfAnotherMake(false)};
  for (int k = 0; k < 3; ++k) {
    const sim::SimulatedLogs logs = sim::simulate(cfgs[k], 4);
    const std::string d = dir.file("d" + std::to_string(k));
    sim::writeDataset(logs, d);
    runRtk(rtkJob(d, logs.gnss.base_e, d + "/giocal.pos"));
    c[k] = countFixes(logs, d + "/giocal.pos", 0.05);
  }
  std::cout << "paper preset seed 4, GPS+Galileo+BeiDou+QZSS: fixed " << c[0].fixed << " of "
            << c[0].epochs << " against a base of the rover's make, " << c[1].fixed
            << " against another make (aligned phases), " << c[2].fixed
            << " (raw phases); more than 5 cm off: " << c[0].fixed - c[0].within << ", "
            << c[1].fixed - c[1].within << ", " << c[2].fixed - c[2].within << "\n";
  EXPECT_GE(c[0].fixed, c[0].epochs * 95 / 100);
  EXPECT_GE(c[1].fixed, c[0].fixed - 1);
  EXPECT_GE(c[2].fixed, c[0].fixed - 1);
  for (const FixCount& x : c) EXPECT_EQ(x.fixed, x.within);
}

}  // namespace
}  // namespace giocal
