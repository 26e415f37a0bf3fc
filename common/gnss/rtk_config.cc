#include "common/gnss/rtk_config.h"

#include "common/io/yaml_fields.h"

namespace giocal {

RtkOptions readRtkOptions(const std::string& path) {
  if (path.empty()) return {};
  return readRtkOptions(YamlFields(path));
}

RtkOptions readRtkOptions(const YamlFields& y) {
  RtkOptions o;
  const std::string s = "rtk.";
  o.dd.elevation_mask_deg =
      y.numberOr(s + "elevation_mask_deg", o.dd.elevation_mask_deg, 0.0, 60.0);
  o.dd.frequencies = static_cast<int>(y.numberOr(s + "frequencies", o.dd.frequencies, 1, 3));
  if (y.has(s + "systems")) {
    o.dd.systems.clear();
    const std::string sys = y.text(s + "systems");
    for (char c : sys) {
      const auto g = static_cast<GnssSystem>(c);
      if (!isSupported(g)) y.fail(s + "systems", "letters must be among G, E, C, J");
      o.dd.systems.push_back(g);
    }
    if (o.dd.systems.empty()) y.fail(s + "systems", "needs at least one system");
  }
  o.dd.code.sigma_zenith = y.numberOr(s + "code_sigma", o.dd.code.sigma_zenith, 1e-4, 100.0);
  o.dd.phase.sigma_zenith = y.numberOr(s + "phase_sigma", o.dd.phase.sigma_zenith, 1e-5, 1.0);
  o.accel_noise = y.numberOr(s + "accel_noise", o.accel_noise, 0.0, 1000.0);
  o.ambiguity_noise = y.numberOr(s + "ambiguity_noise", o.ambiguity_noise, 0.0, 10.0);
  o.innovation_gate = y.numberOr(s + "innovation_gate", o.innovation_gate, 1.0, 1e6);
  o.lambda.ratio_threshold =
      y.numberOr(s + "ratio_threshold", o.lambda.ratio_threshold, 1.0, 100.0);
  o.lambda.min_fixed = static_cast<int>(y.numberOr(s + "min_fixed", o.lambda.min_fixed, 1, 100));
  o.fix_and_hold = y.numberOr(s + "fix_and_hold", o.fix_and_hold ? 1 : 0, 0, 1) != 0.0;
  o.hold_sigma_cycles = y.numberOr(s + "hold_sigma_cycles", o.hold_sigma_cycles, 1e-6, 1.0);
  o.max_fix_sigma = y.numberOr(s + "max_fix_sigma", o.max_fix_sigma, 1e-4, 1e3);
  o.max_fix_residual = y.numberOr(s + "max_fix_residual", o.max_fix_residual, 1.0, 100.0);
  o.max_outage = y.numberOr(s + "max_outage", o.max_outage, 0.0, 600.0);
  o.divergence_sigma = y.numberOr(s + "divergence_sigma", o.divergence_sigma, 1.0, 1e6);
  o.max_base_offset = y.numberOr(s + "max_base_offset", o.max_base_offset, 0.0, 60.0);
  return o;
}

}  // namespace giocal
