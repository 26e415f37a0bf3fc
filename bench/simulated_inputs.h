// The benches' common start: a preset and seed from the command line (--preset, --seed), the
// drive simulated into /tmp and loaded as a calibrator's inputs.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>

#include "common/calibration/calibration_inputs.h"
#include "sim/simulator.h"

namespace giocal::bench {

struct PresetSeed {
  std::string preset = std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml";
  std::uint64_t seed = 1;
};

inline PresetSeed presetAndSeed(int argc, char** argv) {
  PresetSeed p;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--preset")) p.preset = argv[i + 1];
    if (!std::strcmp(argv[i], "--seed")) p.seed = std::stoull(argv[i + 1]);
  }
  return p;
}

/// The drive of `p` simulated into /tmp/<name>_<seed> and loaded.
inline CalibrationInputs simulatedInputs(const PresetSeed& p, const std::string& name) {
  const std::string dir = "/tmp/" + name + "_" + std::to_string(p.seed);
  sim::writeDataset(sim::simulate(sim::readSimConfig(p.preset), p.seed), dir);
  return loadCalibrationInputs(dir);
}

}  // namespace giocal::bench
