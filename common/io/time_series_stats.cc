#include "common/io/time_series_stats.h"

#include <algorithm>

namespace giocal {

TimeSeriesStats timeSeriesStats(const std::vector<double>& times, double gap_factor) {
  TimeSeriesStats s;
  s.samples = times.size();
  if (times.empty()) return s;
  s.t_first = times.front();
  s.t_last = times.back();
  if (times.size() < 2) return s;
  std::vector<double> dt(times.size() - 1);
  for (size_t k = 0; k + 1 < times.size(); ++k) dt[k] = times[k + 1] - times[k];
  std::vector<double> sorted = dt;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2),
                   sorted.end());
  s.median_dt = sorted[sorted.size() / 2];
  for (size_t k = 0; k < dt.size(); ++k) {
    if (dt[k] > gap_factor * s.median_dt) {
      ++s.gaps;
      if (dt[k] > s.largest_gap) {
        s.largest_gap = dt[k];
        s.gap_start = times[k];
      }
    }
  }
  return s;
}

}  // namespace giocal
