// Fault injection: a simulated dataset of a preset, calibrated clean and then with one fault at a
// time and all of them together (NLOS code outliers, cycle slips with and without LLI, a 30 s GNSS
// outage, a base dropout, a 2 s IMU gap, odometer dropouts, duplicated samples and a time jump, a
// 1 ms receiver clock jump, wheel-slip bursts, a lever arm 0.1 m wrong). Prints per fault and
// estimator the final calibration error as a ratio to the clean run's, NEES7, and what the run
// said (warnings, status). Usage: giocal_fault_injection [--preset <yaml>] [--seed N] [--laps N]
// [--seeds N] (seeds seed..seed+N-1: per fault and estimator the RMS over seeds of the error
// against the clean runs', the largest single ratio, the mean NEES7, the runs that said why)
// [--leave-one-out 1] (also "all of the above" without each fault in turn, wheel slip included:
// which faults make a combination's error) [--combine "<name prefix>,<name prefix>"] (only the
// clean run and that one combination; "wheel slip" names the slip bursts) [--estimator ekf|fgo]
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "common/calibration/calibration_inputs.h"
#include "common/calibration/initial_state.h"
#include "replay/replay.h"
#include "sim/simulator.h"

namespace {

using giocal::CalibrationInputs;
using Fault = std::function<void(CalibrationInputs&, std::mt19937_64&)>;

/// The data's middle third: faults land while the robot drives and the calibration is moving.
double tAt(const CalibrationInputs& in, double share) {
  const double t0 = in.rover.epochs.front().t, t1 = in.rover.epochs.back().t;
  return t0 + share * (t1 - t0);
}

template <class T>
void dropBetween(std::vector<T>& v, double t0, double t1) {
  v.erase(std::remove_if(v.begin(), v.end(), [&](const T& s) { return s.t >= t0 && s.t < t1; }),
          v.end());
}

void nlos(CalibrationInputs& in, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0), bias(5.0, 50.0);
  for (auto& e : in.rover.epochs)
    for (auto& s : e.sats)
      for (auto& sig : s.signals)
        if (std::isfinite(sig.P) && u(rng) < 0.1) sig.P += bias(rng);
}

/// 20 slips of 1-5 cycles on random satellites from random epochs on, flagged or not.
void slips(CalibrationInputs& in, std::mt19937_64& rng, bool lli) {
  std::uniform_int_distribution<size_t> epoch(in.rover.epochs.size() / 10,
                                              in.rover.epochs.size() - 1);
  std::uniform_int_distribution<int> cycles(1, 5);
  for (int n = 0; n < 20; ++n) {
    const size_t k0 = epoch(rng);
    if (in.rover.epochs[k0].sats.empty()) continue;
    std::uniform_int_distribution<size_t> pick(0, in.rover.epochs[k0].sats.size() - 1);
    const giocal::SatId sat = in.rover.epochs[k0].sats[pick(rng)].sat;
    const double jump = cycles(rng);
    for (size_t k = k0; k < in.rover.epochs.size(); ++k) {
      for (auto& s : in.rover.epochs[k].sats) {
        if (!(s.sat == sat)) continue;
        for (auto& sig : s.signals) {
          sig.L += jump;
          if (lli && k == k0) sig.lli |= 1;
        }
      }
    }
  }
}

void clockJump(CalibrationInputs& in, std::mt19937_64&) {
  const double t = tAt(in, 0.5), dt = 1e-3;
  for (auto& e : in.rover.epochs) {
    if (e.t < t) continue;
    for (auto& s : e.sats) {
      for (auto& sig : s.signals) {
        sig.P += giocal::kSpeedOfLight * dt;
        sig.L += dt * giocal::carrierFrequency(s.sat.sys, sig.band);
      }
    }
  }
}

void duplicatesAndJump(CalibrationInputs& in, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<giocal::ImuSample> imu;
  for (const auto& s : in.imu) {
    imu.push_back(s);
    if (u(rng) < 0.01) imu.push_back(s);  // 1 % of IMU samples twice
  }
  in.imu = imu;
  std::vector<giocal::OdomSample> odom;
  for (const auto& s : in.odom) {
    odom.push_back(s);
    if (u(rng) < 0.01) odom.push_back(s);
  }
  // One odometer stamp 0.5 s back in time (a driver's clock step).
  odom[odom.size() / 2].t -= 0.5;
  in.odom = odom;
}

void wrongLeverArm(CalibrationInputs& in, std::mt19937_64&) {
  in.description.p_b_g += Eigen::Vector3d::Constant(0.1);
}

struct Named {
  std::string name;
  Fault apply;
};

std::vector<Named> faults() {
  return {
      {"NLOS 10 % of code +5..50 m", nlos},
      {"cycle slips with LLI", [](CalibrationInputs& in, auto& r) { slips(in, r, true); }},
      {"cycle slips without LLI", [](CalibrationInputs& in, auto& r) { slips(in, r, false); }},
      {"GNSS outage 30 s",
       [](CalibrationInputs& in, auto&) {
         dropBetween(in.rover.epochs, tAt(in, 0.4), tAt(in, 0.4) + 30.0);
       }},
      {"base dropout 30 s",
       [](CalibrationInputs& in, auto&) {
         dropBetween(in.base.epochs, tAt(in, 0.6), tAt(in, 0.6) + 30.0);
       }},
      {"IMU gap 2 s",
       [](CalibrationInputs& in, auto&) { dropBetween(in.imu, tAt(in, 0.5), tAt(in, 0.5) + 2); }},
      {"odometer dropouts 3 x 2 s",
       [](CalibrationInputs& in, auto&) {
         for (double s : {0.3, 0.5, 0.7}) dropBetween(in.odom, tAt(in, s), tAt(in, s) + 2.0);
       }},
      {"duplicates 1 % + time jump", duplicatesAndJump},
      {"receiver clock jump 1 ms", clockJump},
      {"lever arm 0.1 m wrong", wrongLeverArm},
  };
}

/// What a run said that the clean run did not: its status, new warnings (their text up to the
/// first ':' or number), and the counters that moved.
std::string newSayings(const giocal::CalibrationRun& run, const giocal::CalibrationRun& clean) {
  std::string out = run.status != "ok" ? run.status + "; " : "";
  const auto head = [](const std::string& w) {
    return w.substr(0, w.find_first_of(":0123456789"));
  };
  for (const std::string& w : run.warnings) {
    bool known = false;
    for (const std::string& c : clean.warnings) known = known || head(c) == head(w);
    if (!known) out += w + "; ";
  }
  for (const auto& [name, n] : run.counters) {
    const auto it = clean.counters.find(name);
    const long before = it == clean.counters.end() ? 0 : it->second;
    if (name != "dd_rows" && name != "odometer_intervals" && n != before)
      out += name + " " + std::to_string(before) + "->" + std::to_string(n) + "; ";
  }
  return out.empty() ? "-" : out.substr(0, out.size() - 2);
}

/// Error of the seven observable states in units of the prior's sigma, RMS over them.
double score(const giocal::CalibrationRun& run, const CalibrationInputs& in) {
  const giocal::CalibrationError e = giocal::calibrationError(run.final(), in.truth->calib);
  const Eigen::Matrix<double, 8, 8> P =
      giocal::priorCalibrationCovariance(in.description.initial_calibration);
  double sum = 0.0;
  for (int i = 0; i < 8; ++i) {
    if (i == giocal::calib_index::kP + 2) continue;  // p_b_m.z: held
    sum += e.tangent[i] * e.tangent[i] / P(i, i);
  }
  return std::sqrt(sum / 7.0);
}

struct Options {
  std::string preset = std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml";
  std::uint64_t seed = 61;
  int seeds = 1;
  int laps = 0;
  bool leave_one_out = false;
  std::string combine, only_estimator;
};

struct Row {
  std::string name, est, said;
  double score = NAN, clean_score = NAN, nees = NAN;
};

/// The cases of one seed: the clean drive, each fault, wheel slip, all of them, and what the
/// options ask for besides.
std::vector<std::pair<std::string, CalibrationInputs>> casesOf(const Options& o,
                                                               std::uint64_t seed) {
  giocal::sim::SimConfig cfg = giocal::sim::readSimConfig(o.preset);
  if (o.laps > 0) cfg.segments.resize(std::min<size_t>(cfg.segments.size(), 2 + 4 * o.laps));
  const std::string work =
      std::filesystem::temp_directory_path() / ("giocal_faults_" + std::to_string(::getpid()));
  const auto load = [&](const giocal::sim::SimConfig& c) {
    std::filesystem::remove_all(work);
    giocal::sim::writeDataset(giocal::sim::simulate(c, seed), work);
    CalibrationInputs in = giocal::loadCalibrationInputs(work);
    std::filesystem::remove_all(work);
    return in;
  };
  const CalibrationInputs clean = load(cfg);
  giocal::sim::SimConfig slipping = cfg;
  slipping.odometer.slip_rate_per_min = 2.0;  // wheel-slip bursts: 0.5 s at 1.3x, 2 a minute
  std::vector<std::pair<std::string, CalibrationInputs>> cases{{"clean", clean}};
  std::mt19937_64 rng(seed);
  if (!o.combine.empty()) {
    std::vector<std::string> names;
    for (size_t a = 0, b; a <= o.combine.size(); a = b + 1) {
      b = std::min(o.combine.find(',', a), o.combine.size());
      names.push_back(o.combine.substr(a, b - a));
    }
    const auto named = [&](const std::string& fault) {
      return std::any_of(names.begin(), names.end(),
                         [&](const std::string& n) { return fault.rfind(n, 0) == 0; });
    };
    CalibrationInputs c = named("wheel slip") ? load(slipping) : clean;
    for (const Named& f : faults())
      if (named(f.name)) f.apply(c, rng);
    cases.push_back({o.combine, c});
    return cases;
  }
  for (const Named& f : faults()) {
    CalibrationInputs in = clean;
    f.apply(in, rng);
    cases.push_back({f.name, in});
  }
  cases.push_back({"wheel-slip bursts 2/min", load(slipping)});
  const CalibrationInputs slip_data = cases.back().second;
  CalibrationInputs all = slip_data;
  for (const Named& f : faults()) f.apply(all, rng);
  cases.push_back({"all of the above", all});
  if (o.leave_one_out) {
    const std::vector<Named> each = faults();
    for (size_t skip = 0; skip <= each.size(); ++skip) {
      const bool skip_slip = skip == each.size();
      std::mt19937_64 r(seed);
      CalibrationInputs c = skip_slip ? clean : slip_data;
      for (size_t k = 0; k < each.size(); ++k)
        if (k != skip) each[k].apply(c, r);
      cases.push_back({"all but " + (skip_slip ? std::string("wheel slip") : each[skip].name), c});
    }
  }
  return cases;
}

/// Calibrates each case with each estimator; with one seed, prints each row as it comes.
std::vector<Row> runSeed(const Options& o, std::uint64_t seed) {
  const auto cases = casesOf(o, seed);
  const bool print = o.seeds == 1;
  if (print) {
    std::printf("preset %s, seed %llu, %.0f s of data\n", o.preset.c_str(),
                static_cast<unsigned long long>(seed), cases.front().second.dataDuration());
    std::printf("%-34s %-4s %9s %8s  %s\n", "fault", "est", "err/clean", "NEES7",
                "what the run said beyond the clean run's (status, warnings, counters)");
  }
  std::vector<Row> rows;
  for (const std::string est : {"ekf", "fgo"}) {
    if (!o.only_estimator.empty() && est != o.only_estimator) continue;
    double clean_score = NAN;
    giocal::CalibrationRun clean_run;
    for (const auto& [name, in] : cases) {
      Row row{name, est, "", NAN, NAN, NAN};
      try {
        const giocal::CalibrationRun run = giocal::replayInputs(in, {est, {}, {}}, nullptr);
        row.score = score(run, in);
        row.nees = giocal::calibrationError(run.final(), in.truth->calib).nees7;
        if (name == "clean") clean_run = run;
        row.said = newSayings(run, clean_run);
      } catch (const std::exception& e) {
        row.said = std::string("FAILED: ") + e.what();
      }
      if (name == "clean") clean_score = row.score;
      row.clean_score = clean_score;
      if (row.said.size() > 160) row.said = row.said.substr(0, 157) + "...";
      if (print) {
        std::printf("%-34s %-4s %9.2f %8.2f  %s\n", name.c_str(), est.c_str(),
                    row.score / clean_score, row.nees, row.said.c_str());
        std::fflush(stdout);
      }
      rows.push_back(row);
    }
  }
  return rows;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--preset")
      o.preset = argv[i + 1];
    else if (a == "--seed")
      o.seed = std::stoull(argv[i + 1]);
    else if (a == "--seeds")
      o.seeds = std::max(1, std::stoi(argv[i + 1]));
    else if (a == "--laps")
      o.laps = std::stoi(argv[i + 1]);
    else if (a == "--leave-one-out")
      o.leave_one_out = std::stoi(argv[i + 1]) != 0;
    else if (a == "--combine")
      o.combine = argv[i + 1];
    else if (a == "--estimator")
      o.only_estimator = argv[i + 1];
    else {
      std::cerr << "unknown option " << a << "\n";
      return 2;
    }
  }
  if (o.seeds == 1) {
    runSeed(o, o.seed);
    return 0;
  }
  // Over seeds: one seed's clean error can be small by luck, and its ratios then large by luck.
  std::vector<Row> all;
  for (int k = 0; k < o.seeds; ++k) {
    const std::vector<Row> rows = runSeed(o, o.seed + static_cast<std::uint64_t>(k));
    all.insert(all.end(), rows.begin(), rows.end());
  }
  std::printf("preset %s, seeds %llu-%llu\n", o.preset.c_str(),
              static_cast<unsigned long long>(o.seed),
              static_cast<unsigned long long>(o.seed + static_cast<std::uint64_t>(o.seeds) - 1));
  std::printf("%-34s %-4s %9s %9s %8s %8s  %s\n", "fault", "est", "RMS ratio", "max ratio", "NEES7",
              "failed", "runs that said something beyond the clean run's");
  std::vector<std::pair<std::string, std::string>> order;
  for (const Row& r : all)
    if (std::find(order.begin(), order.end(), std::make_pair(r.name, r.est)) == order.end())
      order.push_back({r.name, r.est});
  for (const auto& [name, est] : order) {
    double s2 = 0.0, c2 = 0.0, worst = 0.0, nees = 0.0;
    int n = 0, failed = 0, said = 0;
    for (const Row& r : all) {
      if (r.name != name || r.est != est) continue;
      ++n;
      said += r.said != "-";
      if (!std::isfinite(r.score)) {
        ++failed;
        continue;
      }
      s2 += r.score * r.score;
      c2 += r.clean_score * r.clean_score;
      worst = std::max(worst, r.score / r.clean_score);
      nees += r.nees;
    }
    std::printf("%-34s %-4s %9.2f %9.2f %8.2f %8d  %d of %d\n", name.c_str(), est.c_str(),
                std::sqrt(s2 / c2), worst, nees / std::max(1, n - failed), failed, said, n);
  }
  return 0;
}
