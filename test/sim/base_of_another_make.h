// A simulated base of another make than its rover, on the paper preset's drive.
#pragma once

#include <string>

#include "sim/sim_config.h"

namespace giocal::test {

/// The paper preset with GPS, Galileo, BeiDou and QZSS, and a base of another make (the 5.3 km
/// pair's Trimble against its Septentrio rover): it tracks GPS L2 as semi-codeless L2W above 25
/// degrees and as L2C (L2X) everywhere, QZSS L1 as L1C/A and L1C (L1X). Its file lists those
/// signals and records the phase-shift corrections when `aligned`; otherwise its phases are raw,
/// L2X a quarter cycle from L2W and L1X from L1C.
inline sim::SimConfig paperWithBaseOfAnotherMake(bool aligned) {
  sim::SimConfig cfg =
      sim::readSimConfig(std::string(GIOCAL_SOURCE_DIR) + "/config/sim/paper.yaml");
  cfg.gnss.systems = "GECJ";
  cfg.gnss.base_signals = {
      {GnssSystem::kGps, '1', 'C'},        {GnssSystem::kGps, '2', 'W', 0.0, 25.0},
      {GnssSystem::kGps, '2', 'X', -0.25}, {GnssSystem::kQzss, '1', 'C'},
      {GnssSystem::kQzss, '1', 'X', 0.25}, {GnssSystem::kQzss, '2', 'X'}};
  cfg.gnss.base_phase_aligned = aligned;
  return cfg;
}

}  // namespace giocal::test
