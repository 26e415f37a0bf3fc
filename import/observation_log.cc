#include "import/observation_log.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace giocal::import {

namespace {

double medianInterval(const std::vector<ObsEpoch>& epochs) {
  std::vector<double> dt;
  for (std::size_t k = 1; k < epochs.size(); ++k) dt.push_back(epochs[k].t - epochs[k - 1].t);
  if (dt.empty()) return 0.0;
  std::nth_element(dt.begin(), dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2), dt.end());
  return std::round(dt[dt.size() / 2] * 1e3) / 1e3;
}

}  // namespace

void describeObservations(ObsData& obs) {
  std::map<char, std::set<std::pair<char, char>>> seen;
  for (const ObsEpoch& e : obs.epochs) {
    for (const SatObs& s : e.sats) {
      for (const SignalObs& g : s.signals)
        seen[static_cast<char>(s.sat.sys)].insert({g.band, g.attr});
    }
  }
  obs.header.obs_types.clear();
  for (const auto& [sys, signals] : seen) {
    auto& types = obs.header.obs_types[sys];
    for (const auto& [band, attr] : signals) {
      for (char kind : {'C', 'L', 'D', 'S'}) types.push_back(std::string{kind, band, attr});
    }
  }
  obs.header.interval = medianInterval(obs.epochs);
}

}  // namespace giocal::import
