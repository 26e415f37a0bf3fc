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
//                           [--shard k/n] (only every n-th seed from the k-th: one of n
//                           independent processes) [--results <file.csv>] (the per-seed rows, for
//                           --merge) [--label <name>] (the estimator's name in the rows, e.g.
//                           fgo-batch for a run with a window covering the whole drive)
//                           [--quiet 1] (no progress line on a terminal's standard error)
//        giocal_monte_carlo --merge <file.csv>... [--batch <name>]   (prints the summary of the
//                           shards' rows; --batch: the accuracy targets against that estimator)
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

#include "bench/monte_carlo_results.h"
#include "common/calibration/calibration_inputs.h"
#include "common/calibration/calibration_options.h"
#include "common/calibration/initial_state.h"
#include "common/io/progress_line.h"
#include "common/math/rotation.h"
#include "common/online/run_sink.h"
#include "options/giocal_config.h"
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

}  // namespace

int main(int argc, char** argv) try {
  std::string preset = std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml";
  int seeds = 20, first = 1, shard = 1, shards = 1;
  std::string config, results, label, batch;
  double arw = -1.0, gyro_bias = -1.0, straight_s = -1.0, arc_s = -1.0;  // negative: the preset's
  bool guess_at_truth = false, quiet = false;
  std::vector<std::string> schemes{"TC"}, merge;
  std::string box_csv, only;
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    if (k == "--merge") {
      for (++i; i < argc && std::string(argv[i]).rfind("--", 0) != 0; ++i) merge.push_back(argv[i]);
      --i;
      continue;
    }
    if (i + 1 >= argc) {
      std::cerr << k << ": missing value\n";
      return 2;
    }
    const std::string v = argv[++i];
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
      only = v;
    else if (k == "--box-csv")
      box_csv = v;
    else if (k == "--results")
      results = v;
    else if (k == "--label")
      label = v;
    else if (k == "--quiet")
      quiet = v != "0";
    else if (k == "--batch")
      batch = v;
    else if (k == "--shard") {
      char tail = 0;
      if (std::sscanf(v.c_str(), "%d/%d%c", &shard, &shards, &tail) != 2 || shards < 1 ||
          shard < 1 || shard > shards) {
        std::cerr << "--shard " << v << ": expected k/n with 1 <= k <= n\n";
        return 2;
      }
    } else if (k == "--schemes") {
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
  if (!merge.empty()) {
    giocal::bench::RunDescription run;
    const std::vector<giocal::bench::SeedResult> rows = giocal::bench::readSeedResults(merge, &run);
    giocal::bench::printSummary(run, rows, batch);
    return 0;
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
  // The preset by its path relative to the sources, so that shards run from anywhere agree.
  std::string edits = std::filesystem::path(preset).filename().string();
  if (straight_s >= 0.0) edits += ", straight " + std::to_string(straight_s) + " s";
  if (arc_s >= 0.0) edits += ", arcs " + std::to_string(arc_s) + " s";
  char gyro[96];
  std::snprintf(gyro, sizeof gyro, "; gyro ARW %g deg/sqrt(h), bias %g deg/h",
                cfg.imu.arw_deg_sqrt_h, cfg.imu.gyro_bias_deg_h);
  const giocal::bench::RunDescription description{edits + gyro, guess_at_truth};
  const giocal::GiocalConfig parsed = giocal::readGiocalConfig(config);
  const giocal::CalibrationOptions options = parsed.calibration;
  const giocal::FgoOptions fgo_options = parsed.fgo;
  std::map<std::string, Runner> estimators;
  for (const std::string& name : giocal::estimatorNames()) {
    if (!only.empty() && name != only) continue;
    estimators[name] = [name, &fgo_options](const giocal::CalibrationInputs& in,
                                            const giocal::CalibrationOptions& o,
                                            giocal::RunSink* sink) {
      return giocal::replayInputs(in, {name, o, fgo_options}, sink);
    };
  }
  if (estimators.empty()) {
    std::cerr << "--estimator " << only << ": not an estimator\n";
    return 2;
  }
  std::vector<giocal::bench::SeedResult> rows;
  // One directory per process, so that runs in parallel do not overwrite each other's datasets.
  const std::string work =
      std::filesystem::temp_directory_path() / ("giocal_monte_carlo_" + std::to_string(::getpid()));
  std::printf("%-6s %-5s %8s %8s %8s %8s %8s %10s %10s %8s %6s %8s\n", "seed", "est", "X m", "Y m",
              "roll", "pitch", "yaw", "s_v", "s_w", "NEES7", "fix%", "wall s");
  // Adds one final estimate to the rows and prints it.
  giocal::ProgressLine progress("giocal_monte_carlo", first, first + seeds, quiet, "of the seeds");
  auto score = [&](int seed, const std::string& name, const giocal::CalibrationEstimate& est,
                   const giocal::OdometerCalibration& truth, const giocal::CalibrationRun* r) {
    giocal::bench::SeedResult row;
    row.seed = seed;
    row.name = name;
    errorsAndSigmas(est, truth, row.error.data(), row.sigma.data());
    row.nees7 = giocal::calibrationError(est, truth).nees7;
    row.wall_s = row.epoch_s = row.real_time_factor = row.fix_percent = NAN;
    if (r) {
      row.wall_s = r->wall_time_s;
      if (r->timing.count("gnss_epoch_mean_s")) row.epoch_s = r->timing.at("gnss_epoch_mean_s");
      row.real_time_factor = r->data_duration_s / r->wall_time_s;
      row.fix_percent = 100.0 * r->fixRate();
    }
    rows.push_back(row);
    const double* v = row.error.data();
    progress.clear();
    std::printf("%-6d %-5s %8.4f %8.4f %8.3f %8.3f %8.3f %10.2e %10.2e %8.2f %6.1f %8.3f\n", seed,
                name.c_str(), v[0], v[1], v[2], v[3], v[4], v[5], v[6], row.nees7, row.fix_percent,
                row.wall_s);
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
    if ((seed - first) % shards != shard - 1) continue;
    progress.update(seed);
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
        const std::string base = label.empty() ? name : label;
        const std::string key = scheme == "TC" ? base : base + " " + scheme;
        giocal::CalibrationRun r;
        giocal::RunRecording rec;
        try {
          r = run(in_s, o, &rec);
        } catch (const std::exception& e) {
          progress.clear();
          std::printf("%-6d %-4s failed: %s\n", seed, key.c_str(), e.what());
          giocal::bench::SeedResult failed;
          failed.seed = seed;
          failed.name = key;
          failed.failed = true;
          rows.push_back(failed);
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
  progress.clear();
  if (box) std::fclose(box);
  std::filesystem::remove_all(work);
  giocal::bench::printSummary(description, rows, batch);
  if (!results.empty()) giocal::bench::writeSeedResults(results, description, rows);
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  std::printf("peak memory of this process: %.1f MiB\n",
              static_cast<double>(ru.ru_maxrss) / 1024.0);
  return 0;
} catch (const std::exception& e) {
  std::cerr << "giocal_monte_carlo: " << e.what() << "\n";
  return 1;
}
