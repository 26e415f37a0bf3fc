// Monte Carlo of the calibrators on simulated datasets: simulates a preset with N seeds (each
// seed draws new sensor noise, biases and initial calibration guess), calibrates each dataset and
// prints the mean absolute final errors in the form of the reference paper's Table "Mean
// calibration errors", the mean NEES of the seven observable calibration states, and timing.
// Usage: giocal_monte_carlo [--preset config/sim/paper.yaml] [--seeds 20] [--first 1]
//                           [--config <yaml>] [--estimator ekf|fgo]
//                           [--arw-deg-sqrt-h A] [--gyro-bias-deg-h B]   (override the preset's
//                           gyro) [--straight-s S]   (duration of the preset's straight
//                           segments) [--arc-s S]   (of its arcs; 0 drops them: a drive that
//                           never turns, docs/results.md) [--guess-at-truth 1]   (start from the
//                           true calibration, keeping the prior sigma: a diagnostic of
//                           linearization, see docs/results.md) [--schemes TC,TC-LE-C,TC-LE-OL]
//                           (the paper's simulation schemes: the GNSS lever arm known exactly; 0.1
//                           m wrong per axis and held; the same error, estimated online) [--box-csv
//                           <file>] (per seed and scheme, errors and sigmas at 0, 60 and 120 s
//                           after the first rover epoch: the paper's box-plot statistics)
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "common/calibration/calibration_inputs.h"
#include "common/calibration/calibration_options.h"
#include "common/calibration/initial_state.h"
#include "common/math/rotation.h"
#include "common/online/run_sink.h"
#include "replay/config.h"
#include "replay/estimator_factory.h"
#include "replay/replay.h"
#include "sim/simulator.h"

namespace {

using Runner = std::function<giocal::CalibrationRun(
    const giocal::CalibrationInputs&, const giocal::CalibrationOptions&, giocal::RunSink*)>;

/// X, Y, roll, pitch, yaw [deg], s_v, s_w: errors and sigmas in the tables' order.
void errorsAndSigmas(const giocal::CalibrationEstimate& est,
                     const giocal::OdometerCalibration& truth, double v[7], double sd[7]) {
  const giocal::CalibrationError e = giocal::calibrationError(est, truth);
  const double vv[7] = {e.p_b_m.x(),
                        e.p_b_m.y(),
                        e.rpy.x() * giocal::kRadToDeg,
                        e.rpy.y() * giocal::kRadToDeg,
                        e.rpy.z() * giocal::kRadToDeg,
                        e.s_v,
                        e.s_w};
  const Eigen::Matrix<double, 8, 1> s = est.sigma();
  const double ss[7] = {s[2], s[3], s[5], s[6], s[7], s[0], s[1]};
  for (int k = 0; k < 7; ++k) {
    v[k] = vv[k];
    sd[k] = ss[k];
  }
}

struct Tally {
  // Per seed: signed final error and its reported 1-sigma of X, Y, roll, pitch, yaw, s_v, s_w.
  std::map<int, std::array<double, 7>> error, sigma;
  std::vector<double> nees, wall, rtf, fix, epoch;
  int failures = 0;
};

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? NAN : s / static_cast<double>(v.size());
}

/// The reported final sigma against the one implied by how much the final errors still follow
/// the guess's errors: for a linear-Gaussian estimator, final = (P / P0) guess + noise.
struct Implied {
  double reported[7], b[7], implied[7];
};
Implied impliedSigma(const Tally& t, const Tally& guess) {
  Implied out{};
  for (size_t k = 0; k < 7; ++k) {
    double eg = 0, gg = 0, s2 = 0, p2 = 0;
    int n = 0;
    for (const auto& [seed, e] : t.error) {
      const auto g = guess.error.find(seed);
      if (g == guess.error.end()) continue;
      eg += e[k] * g->second[k];
      gg += g->second[k] * g->second[k];
      s2 += std::pow(t.sigma.at(seed)[k], 2);
      p2 += std::pow(guess.sigma.at(seed)[k], 2);
      ++n;
    }
    out.reported[k] = n ? std::sqrt(s2 / n) : NAN;
    out.b[k] = gg > 0 ? eg / gg : NAN;
    out.implied[k] = n ? std::sqrt(p2 / n * std::max(out.b[k], 0.0)) : NAN;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::string preset = std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml";
  int seeds = 20, first = 1;
  std::string config;
  double arw = -1.0, gyro_bias = -1.0, straight_s = -1.0, arc_s = -1.0;  // negative: the preset's
  bool guess_at_truth = false;
  std::vector<std::string> schemes{"TC"};
  std::string box_csv;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--preset")
      preset = v;
    else if (k == "--seeds")
      seeds = std::stoi(v);
    else if (k == "--first")
      first = std::stoi(v);
    else if (k == "--config")
      config = v;
    else if (k == "--arw-deg-sqrt-h")
      arw = std::stod(v);
    else if (k == "--gyro-bias-deg-h")
      gyro_bias = std::stod(v);
    else if (k == "--straight-s")
      straight_s = std::stod(v);
    else if (k == "--arc-s")
      arc_s = std::stod(v);
    else if (k == "--guess-at-truth")
      guess_at_truth = std::stoi(v) != 0;
    else if (k == "--estimator")
      continue;  // read below
    else if (k == "--box-csv")
      box_csv = v;
    else if (k == "--schemes") {
      schemes.clear();
      std::stringstream ss(v);
      for (std::string s; std::getline(ss, s, ',');) {
        if (s != "TC" && s != "TC-LE-C" && s != "TC-LE-OL") {
          std::cerr << "unknown scheme " << s << " (TC, TC-LE-C, TC-LE-OL)\n";
          return 2;
        }
        schemes.push_back(s);
      }
    } else {
      std::cerr << "unknown option " << k << "\n";
      return 2;
    }
  }
  giocal::sim::SimConfig cfg = giocal::sim::readSimConfig(preset);
  if (arw >= 0.0) cfg.imu.arw_deg_sqrt_h = arw;
  if (gyro_bias >= 0.0) cfg.imu.gyro_bias_deg_h = gyro_bias;
  // Segments of `type` last `duration` s; 0 drops them.
  const auto setDuration = [&cfg](const std::string& type, double duration) {
    if (duration < 0.0) return;
    for (giocal::sim::SegmentSpec& s : cfg.segments) {
      if (s.type == type) s.duration = duration;
    }
    cfg.segments.erase(std::remove_if(cfg.segments.begin(), cfg.segments.end(),
                                      [&type](const giocal::sim::SegmentSpec& s) {
                                        return s.type == type && !(s.duration > 0.0);
                                      }),
                       cfg.segments.end());
  };
  setDuration("straight", straight_s);
  setDuration("arc", arc_s);
  std::string edits;
  if (straight_s >= 0.0) edits += ", straight " + std::to_string(straight_s) + " s";
  if (arc_s >= 0.0) edits += ", arcs " + std::to_string(arc_s) + " s";
  const giocal::GiocalConfig parsed = giocal::readGiocalConfig(config);
  const giocal::CalibrationOptions options = parsed.calibration;
  const giocal::FgoOptions fgo_options = parsed.fgo;
  std::map<std::string, Runner> estimators;
  for (const std::string& name : giocal::estimatorNames()) {
    estimators[name] = [name, &fgo_options](const giocal::CalibrationInputs& in,
                                            const giocal::CalibrationOptions& o,
                                            giocal::RunSink* sink) {
      return giocal::replayInputs(in, {name, o, fgo_options}, sink);
    };
  }
  std::string only;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::string(argv[i]) == "--estimator") only = argv[i + 1];
  }
  if (!only.empty()) {
    for (auto it = estimators.begin(); it != estimators.end();) {
      it = it->first == only ? std::next(it) : estimators.erase(it);
    }
  }
  std::map<std::string, Tally> tally;
  // One directory per process, so that runs in parallel do not overwrite each other's datasets.
  const std::string work =
      std::filesystem::temp_directory_path() / ("giocal_monte_carlo_" + std::to_string(::getpid()));
  std::printf("%-6s %-5s %8s %8s %8s %8s %8s %10s %10s %8s %6s %8s\n", "seed", "est", "X m", "Y m",
              "roll", "pitch", "yaw", "s_v", "s_w", "NEES7", "fix%", "wall s");
  // Adds one final estimate to a scheme's tally and prints its row.
  auto score = [&](int seed, const std::string& name, const giocal::CalibrationEstimate& est,
                   const giocal::OdometerCalibration& truth, const giocal::CalibrationRun* r) {
    Tally& t = tally[name];
    const giocal::CalibrationError e = giocal::calibrationError(est, truth);
    double v[7], sd[7];
    errorsAndSigmas(est, truth, v, sd);
    for (int k = 0; k < 7; ++k) {
      t.error[seed][static_cast<size_t>(k)] = v[k];
      t.sigma[seed][static_cast<size_t>(k)] = sd[k];
    }
    t.nees.push_back(e.nees7);
    if (r) {
      t.wall.push_back(r->wall_time_s);
      if (r->timing.count("gnss_epoch_mean_s"))
        t.epoch.push_back(r->timing.at("gnss_epoch_mean_s"));
      t.rtf.push_back(r->data_duration_s / r->wall_time_s);
      t.fix.push_back(100.0 * r->fixRate());
    }
    std::printf("%-6d %-5s %8.4f %8.4f %8.3f %8.3f %8.3f %10.2e %10.2e %8.2f %6.1f %8.3f\n", seed,
                name.c_str(), v[0], v[1], v[2], v[3], v[4], v[5], v[6], e.nees7,
                r ? 100.0 * r->fixRate() : NAN, r ? r->wall_time_s : NAN);
  };
  std::FILE* box = box_csv.empty() ? nullptr : std::fopen(box_csv.c_str(), "w");
  if (!box_csv.empty() && !box) {
    std::cerr << box_csv << ": cannot open for writing\n";
    return 1;
  }
  if (box) {
    std::fprintf(box, "seed,estimator,scheme,t_s");
    for (const char* q : {"x", "y", "roll_deg", "pitch_deg", "yaw_deg", "s_v", "s_w"})
      std::fprintf(box, ",err_%s,sd_%s", q, q);
    std::fprintf(box, "\n");
  }
  for (int seed = first; seed < first + seeds; ++seed) {
    std::filesystem::remove_all(work);
    const giocal::sim::SimulatedLogs logs =
        giocal::sim::simulate(cfg, static_cast<std::uint64_t>(seed));
    giocal::sim::writeDataset(logs, work);
    giocal::CalibrationInputs in = giocal::loadCalibrationInputs(work);
    if (guess_at_truth) in.description.initial_calibration.mean = in.truth->calib;
    // The initial guess with its prior sigma: the baseline that the data must improve on.
    giocal::CalibrationEstimate guess;
    guess.calib = in.description.initial_calibration.mean;
    guess.cov = giocal::priorCalibrationCovariance(in.description.initial_calibration);
    score(seed, "guess", guess, in.truth->calib, nullptr);
    const double t0 = in.rover.epochs.front().t;
    for (const std::string& scheme : schemes) {
      giocal::CalibrationInputs in_s = in;
      giocal::CalibrationOptions o = options;
      if (scheme != "TC") {
        // The paper's lever-arm error: 0.1 m per axis, held (LE-C) or estimated online (LE-OL).
        in_s.description.p_b_g += Eigen::Vector3d::Constant(0.1);
        o.estimate_p_b_g = scheme == "TC-LE-OL";
        o.p_b_g_sigma = 0.1;
      }
      for (const auto& [name, run] : estimators) {
        const std::string key = scheme == "TC" ? name : name + " " + scheme;
        giocal::CalibrationRun r;
        giocal::RunRecording rec;
        try {
          r = run(in_s, o, &rec);
        } catch (const std::exception& e) {
          std::printf("%-6d %-4s failed: %s\n", seed, key.c_str(), e.what());
          ++tally[key].failures;
          continue;
        }
        score(seed, key, r.final(), in.truth->calib, &r);
        if (box_csv.empty()) continue;
        for (double at : {0.0, 60.0, 120.0}) {
          // The latest estimate at that time; before the first one, the initial guess.
          giocal::CalibrationEstimate est = guess;
          for (const giocal::CalibrationEstimate& h : rec.history) {
            if (h.t <= t0 + at + 1e-6) est = h;
          }
          double v[7], sd[7];
          errorsAndSigmas(est, in.truth->calib, v, sd);
          std::fprintf(box, "%d,%s,%s,%g", seed, name.c_str(), scheme.c_str(), at);
          for (int k = 0; k < 7; ++k) std::fprintf(box, ",%.9g,%.9g", v[k], sd[k]);
          std::fprintf(box, "\n");
        }
      }
    }
  }
  if (box) std::fclose(box);
  std::filesystem::remove_all(work);
  std::printf(
      "\nMean absolute calibration errors over %d seeds (%s%s; gyro ARW %g deg/sqrt(h), bias %g "
      "deg/h%s)\n",
      seeds, preset.c_str(), edits.c_str(), cfg.imu.arw_deg_sqrt_h, cfg.imu.gyro_bias_deg_h,
      guess_at_truth ? "; initial guess at the truth" : "");
  std::printf("%-10s %8s %8s %8s %8s %8s %10s %10s | %8s %8s %9s\n", "scheme", "X m", "Y m",
              "roll deg", "pitch", "yaw", "V scale", "W scale", "NEES7", "fix %", "x real");
  std::printf("%-10s %8.2f %8.2f %8.2f %8.2f %8.2f %10.1e %10.1e |\n", "paper TC", 0.06, 0.05, 0.24,
              0.05, 3.29, 6.0e-4, 3.1e-3);
  for (const auto& [name, t] : tally) {
    double mean_abs[7], rms_z[7];
    for (size_t k = 0; k < 7; ++k) {
      std::vector<double> a, z2;
      for (const auto& [seed, e] : t.error) {
        a.push_back(std::abs(e[k]));
        z2.push_back(std::pow(e[k] / t.sigma.at(seed)[k], 2));
      }
      mean_abs[k] = mean(a);
      rms_z[k] = std::sqrt(mean(z2));
    }
    std::printf("%-10s %8.3f %8.3f %8.3f %8.3f %8.3f %10.1e %10.1e | %8.2f %8.1f %9.0f\n",
                (name == "guess" ? "guess" : "giocal " + name).c_str(), mean_abs[0], mean_abs[1],
                mean_abs[2], mean_abs[3], mean_abs[4], mean_abs[5], mean_abs[6], mean(t.nees),
                mean(t.fix), mean(t.rtf));
    std::printf("%-10s %8.2f %8.2f %8.2f %8.2f %8.2f %10.2f %10.2f |\n", "  err/sigma", rms_z[0],
                rms_z[1], rms_z[2], rms_z[3], rms_z[4], rms_z[5], rms_z[6]);
    if (name != "guess" && !guess_at_truth && tally.count("guess")) {
      const Implied im = impliedSigma(t, tally.at("guess"));
      std::printf("%-10s %8.3f %8.3f %8.3f %8.3f %8.3f %10.1e %10.1e |\n", "  sigma",
                  im.reported[0], im.reported[1], im.reported[2], im.reported[3], im.reported[4],
                  im.reported[5], im.reported[6]);
      std::printf("%-10s %8.2f %8.2f %8.2f %8.2f %8.2f %10.2f %10.2f |\n", "  b", im.b[0], im.b[1],
                  im.b[2], im.b[3], im.b[4], im.b[5], im.b[6]);
      std::printf("%-10s %8.3f %8.3f %8.3f %8.3f %8.3f %10.1e %10.1e |\n", "  implied",
                  im.implied[0], im.implied[1], im.implied[2], im.implied[3], im.implied[4],
                  im.implied[5], im.implied[6]);
    }
    if (!t.epoch.empty())
      std::printf("  %s: mean solve time per GNSS epoch %.1f ms\n", name.c_str(),
                  1e3 * mean(t.epoch));
    if (t.failures) std::printf("  %s failed on %d seeds\n", name.c_str(), t.failures);
  }
  std::printf(
      "NEES7: mean over seeds of the normalized error of the 7 observable states (X, Y, "
      "roll, pitch, yaw, s_v, s_w); consistent near 7 (95%% of single runs below 14.1).\n"
      "err/sigma: RMS over seeds of each final error divided by its reported 1-sigma; consistent "
      "near 1.\n"
      "sigma: RMS over seeds of the reported final 1-sigma. b: least-squares slope of the final "
      "error on the guess's error over the seeds (0: the data decide, 1: the guess does).\n"
      "implied: prior sigma x sqrt(b), the final sigma of an efficient linear-Gaussian estimator "
      "with that slope; a check of the reported sigma where b is well above 0.\n");
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  std::printf("peak memory of this process: %.1f MiB\n",
              static_cast<double>(ru.ru_maxrss) / 1024.0);
  return 0;
}
