#include "apps/simulate_command.h"

#include <chrono>
#include <filesystem>
#include <ostream>
#include <stdexcept>

#include "common/io/output_set.h"
#include "sim/simulator.h"

namespace giocal {

void runSimulate(const std::string& config, const std::string& out, std::uint64_t seed,
                 std::ostream& log, const StopRequest* stop) {
  const sim::SimConfig cfg = sim::readSimConfig(config);
  for (const char* f : {"dataset.yaml", "imu.csv", "odom.csv", "truth.csv", "truth_calib.yaml"}) {
    if (std::filesystem::exists(std::filesystem::path(out) / f)) {
      throw std::runtime_error(out + ": already holds a dataset (" + f +
                               "); choose an empty folder or remove it first");
    }
  }
  const auto start = std::chrono::steady_clock::now();
  const sim::SimulatedLogs logs = sim::simulate(cfg, seed);
  checkStop(stop);
  // The dataset appears whole or not at all; dataset.yaml, which names the others, goes last.
  OutputSet outputs(out);
  outputs.stagedPath("dataset.yaml", true);
  sim::writeDataset(logs, outputs.staging());
  checkStop(stop);
  outputs.commit();
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  log << "simulated '" << cfg.name << "' (seed " << seed
      << "): " << logs.truth.back().t - logs.truth.front().t << " s, " << logs.imu.size()
      << " IMU and " << logs.odom.size() << " odometer samples, " << logs.gnss.rover.size()
      << " GNSS epochs in " << wall << " s -> " << out << "\n";
  if (logs.gnss.rover.empty()) log << "note: the config has no gnss section; no RINEX written\n";
}

}  // namespace giocal
