// median: the middle value of a sample (the upper of the two middle ones for an even count).
#pragma once

#include <algorithm>
#include <vector>

namespace giocal {

/// 0 for an empty sample.
inline double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace giocal
