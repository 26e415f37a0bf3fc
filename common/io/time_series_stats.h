// TimeSeriesStats: sample count, span, nominal rate and gaps of a time-stamped log.
#pragma once

#include <cstddef>
#include <vector>

namespace giocal {

struct TimeSeriesStats {
  std::size_t samples = 0;
  double t_first = 0.0;
  double t_last = 0.0;
  double median_dt = 0.0;    // nominal sample interval [s]
  std::size_t gaps = 0;      // intervals longer than gap_factor * median_dt
  double largest_gap = 0.0;  // [s]
  double gap_start = 0.0;    // time at which the largest gap starts
};

/// `times` must be increasing (the readers guarantee it).
TimeSeriesStats timeSeriesStats(const std::vector<double>& times, double gap_factor = 3.0);

}  // namespace giocal
