#include "common/calibration/position_residuals.h"

#include <algorithm>
#include <cmath>

#include "common/geodesy/wgs84.h"
#include "common/math/rotation.h"

namespace giocal {

namespace {
constexpr double kBin = 0.05;
// Lags whose autocorrelation fell below this end the sum (the initial positive sequence).
constexpr double kNegligibleCorrelation = 0.05;
}  // namespace

double PositionResiduals::understatedBy() const {
  return sigma_ratio * std::sqrt(std::max(1.0, inflation));
}

PositionResidualCheck::PositionResidualCheck(std::vector<PositionFix> fixes,
                                             const Eigen::Vector3d& p_b_g)
    : fixes_(std::move(fixes)), p_b_g_(p_b_g) {}

void PositionResidualCheck::add(const TruthSample& s) {
  Geodetic g;
  g.lat = s.lat_deg * kDegToRad;
  g.lon = s.lon_deg * kDegToRad;
  g.h = s.h;
  const Eigen::Matrix3d R_e_enu = rotationEcefFromEnu(g.lat, g.lon);
  // The lever arm turned by the attitude in n, taken as the ENU at the sample (the two differ by
  // the distance from the origin over the Earth's radius: a fraction of a millimetre here).
  const Eigen::Vector3d antenna_e = ecefFromGeodetic(g) + R_e_enu * (s.q_n_b * p_b_g_);
  while (next_ < fixes_.size() && fixes_[next_].t <= s.t) {
    const PositionFix& f = fixes_[next_++];
    if (!have_prev_ || f.t < prev_t_ || s.t - prev_t_ > kMaxSampleGap) continue;
    const double u = s.t > prev_t_ ? (f.t - prev_t_) / (s.t - prev_t_) : 1.0;
    const Eigen::Vector3d at = (1.0 - u) * prev_antenna_e_ + u * antenna_e;
    const Eigen::Vector3d r = R_e_enu.transpose() * (f.p_e - at);
    const double sd_e = std::sqrt(f.cov_enu(0, 0)), sd_n = std::sqrt(f.cov_enu(1, 1));
    if (!(sd_e > 0.0) || !(sd_n > 0.0) || !r.allFinite()) continue;
    addResidual(f.t, r.x() / sd_e, r.y() / sd_n);
  }
  have_prev_ = true;
  prev_t_ = s.t;
  prev_antenna_e_ = antenna_e;
}

void PositionResidualCheck::addResidual(double t, double z_e, double z_n) {
  const Eigen::Vector2d z(z_e, z_n);
  // A break in the fixes (ten spacings, or a second when the spacing is not known yet) starts
  // the lags again: products across it would not be at their lag.
  if (n_ > 0 && spacing_.size() < kSpacingSample) {
    spacing_.push_back(t - last_t_);
    std::vector<double> s = spacing_;  // the median of the first spacings, then kept
    std::nth_element(s.begin(), s.begin() + s.size() / 2, s.end());
    spacing_median_ = s[s.size() / 2];
  }
  if (n_ > 0 && t - last_t_ > 10.0 * spacing_median_) run_ = 0;
  ring_[static_cast<size_t>(run_ % (kLags + 1))] = z;
  for (long k = 0; k <= std::min<long>(run_, kLags); ++k) {
    const Eigen::Vector2d& a = ring_[static_cast<size_t>((run_ - k) % (kLags + 1))];
    sum_products_[static_cast<size_t>(k)] += z.dot(a);
    pairs_[static_cast<size_t>(k)] += 2;
  }
  sum_ += z;
  for (int c = 0; c < 2; ++c) {
    const auto bin = static_cast<size_t>(std::min(std::abs(z[c]) / kBin, 399.0));
    ++abs_histogram_[bin];
  }
  ++n_;
  ++run_;
  last_t_ = t;
}

PositionResiduals PositionResidualCheck::result() const {
  PositionResiduals r;
  r.fixes = n_;
  if (n_ < 2) return r;
  r.interval_s = spacing_median_;
  // Robust RMS: the median |z| over that of a unit normal (0.6745).
  const long half = (2 * n_ + 1) / 2;
  long seen = 0;
  for (size_t b = 0; b < abs_histogram_.size(); ++b) {
    seen += abs_histogram_[b];
    if (seen >= half) {
      r.sigma_ratio = (static_cast<double>(b) + 0.5) * kBin / 0.6745;
      break;
    }
  }
  // Autocorrelation about the mean, per lag, summed while it stays above negligible.
  const Eigen::Vector2d mean = sum_ / static_cast<double>(n_);
  const double mean_sq = mean.squaredNorm() / 2.0;
  const double c0 = sum_products_[0] / static_cast<double>(pairs_[0]) - mean_sq;
  if (!(c0 > 0.0)) return r;
  double sum = 0.0;
  for (size_t k = 1; k <= kLags && pairs_[k] > 0; ++k) {
    const double rho = (sum_products_[k] / static_cast<double>(pairs_[k]) - mean_sq) / c0;
    if (rho < kNegligibleCorrelation) break;
    sum += rho;
  }
  r.correlation_s = sum * r.interval_s;
  r.inflation = 1.0 + 2.0 * sum;
  return r;
}

}  // namespace giocal
