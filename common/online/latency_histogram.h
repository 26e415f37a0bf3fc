// LatencyHistogram: percentiles of per-epoch processing times in constant memory (log-spaced
// bins, 5 % wide, from 1 microsecond to 100 s).
#pragma once

#include <array>
#include <cmath>

namespace giocal {

class LatencyHistogram {
 public:
  void add(double seconds) {
    ++count_;
    sum_ += seconds;
    max_ = std::max(max_, seconds);
    const double b = std::log(std::max(seconds, kMin) / kMin) / std::log(kRatio);
    ++bins_[static_cast<size_t>(std::min(b, double(kBins - 1)))];
  }
  long count() const { return count_; }
  double mean() const { return count_ ? sum_ / double(count_) : 0.0; }
  double max() const { return max_; }
  /// Upper edge of the bin holding the p-quantile (0 < p <= 1): at most 5 % above the true value.
  double percentile(double p) const {
    long need = static_cast<long>(std::ceil(p * double(count_))), seen = 0;
    for (int b = 0; b < kBins; ++b) {
      seen += bins_[static_cast<size_t>(b)];
      if (seen >= need && seen > 0) return std::min(kMin * std::pow(kRatio, b + 1), max_);
    }
    return max_;
  }

 private:
  static constexpr double kMin = 1e-6, kRatio = 1.05;
  static constexpr int kBins = 380;  // 1e-6 * 1.05^380 = 1.1e2 s
  std::array<long, kBins> bins_{};
  long count_ = 0;
  double sum_ = 0.0, max_ = 0.0;
};

}  // namespace giocal
