// The Monte Carlo's per-seed results: one row per seed and estimator, written to a CSV file by
// each shard and read back by the merge step, which prints the same summary as a single run.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace giocal::bench {

/// The final error and reported 1-sigma of X, Y, roll, pitch, yaw [deg], s_v, s_w of one seed's
/// run of one estimator (or of the initial guess), with its timing.
struct SeedResult {
  int seed = 0;
  std::string name;  // "guess", "ekf", "fgo", "fgo TC-LE-C", or a --label
  bool failed = false;
  std::array<double, 7> error{}, sigma{};
  double nees7 = 0.0;
  double wall_s = 0.0, epoch_s = 0.0, real_time_factor = 0.0, fix_percent = 0.0;  // NaN: none
};

/// What the rows were computed from; shards merged together must agree on it.
struct RunDescription {
  std::string title;  // preset, edits, gyro
  bool guess_at_truth = false;
};

/// Writes the rows to `path` through a temporary file (an interrupted shard leaves no result).
void writeSeedResults(const std::string& path, const RunDescription& run,
                      const std::vector<SeedResult>& rows);

/// Reads the files of several shards; throws naming the file and line of a malformed row, of a
/// shard computed from another run description, or of a seed and estimator found twice.
std::vector<SeedResult> readSeedResults(const std::vector<std::string>& paths, RunDescription* run);

/// Prints the summary table (mean absolute errors, err/sigma, the implied sigma) of the rows, and,
/// when `batch` names an estimator among them, the accuracy targets against that full batch.
void printSummary(const RunDescription& run, const std::vector<SeedResult>& rows,
                  const std::string& batch);

}  // namespace giocal::bench
