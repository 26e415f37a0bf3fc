#include "common/calibration/odometer_delay.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>

namespace giocal {

namespace {

constexpr long kMinSamples = 200;        // blocks: 40 s of driving
constexpr double kBlock = 0.2;           // [s] odometer samples summed into one comparison
constexpr double kMinYawRateRms = 0.05;  // [rad/s]: below it the lag is not seen
constexpr std::size_t kMaxPending = 2000;
constexpr double kMaxInterval = 0.5;
constexpr std::size_t kFitHalfWidth = 10;
constexpr double kMaxSigma = 0.02;  // [s]  // [s] longer odometer intervals are gaps

}  // namespace

OdometerDelayEstimator::OdometerDelayEstimator(const Eigen::Vector3d& up_b, double max_delay_s,
                                               double step_s)
    : up_b_(up_b.normalized()), max_delay_s_(max_delay_s), step_s_(step_s) {
  const auto lags = static_cast<std::size_t>(std::lround(2.0 * max_delay_s_ / step_s_)) + 1;
  for (std::size_t k = 0; k < lags; ++k) delays_.push_back(-max_delay_s_ + double(k) * step_s_);
  sum_x_.assign(lags, 0.0);
  sum_xx_.assign(lags, 0.0);
  sum_xw_.assign(lags, 0.0);
}

void OdometerDelayEstimator::addImu(double t, const Eigen::Vector3d& gyro_b) {
  if (!std::isfinite(t) || !gyro_b.allFinite()) return;
  if (!gyro_.empty() && t <= gyro_.back().t) return;
  const double rate = up_b_.dot(gyro_b);
  const double angle =
      gyro_.empty() ? 0.0
                    : gyro_.back().angle + 0.5 * (gyro_.back().rate + rate) * (t - gyro_.back().t);
  gyro_.push_back({t, rate, angle});
  while (!pending_.empty() && pending_.front().t1 + max_delay_s_ <= t) {
    compare(pending_.front());
    pending_.pop_front();
  }
  // Keep what the oldest waiting (or the next) block can still ask for.
  const double keep_from =
      (pending_.empty() ? t - kBlock - kMaxInterval : pending_.front().t0) - 2.0 * max_delay_s_;
  while (gyro_.size() > 2 && gyro_[1].t < keep_from) gyro_.pop_front();
}

void OdometerDelayEstimator::addOdometer(double t, double yaw_rate) {
  if (!std::isfinite(t) || !std::isfinite(yaw_rate)) return;
  const double dt = t - last_odometer_t_;
  last_odometer_t_ = t;
  const double previous = last_yaw_rate_;
  last_yaw_rate_ = yaw_rate;
  if (!(dt > 0.0 && dt <= kMaxInterval)) {  // the first sample, or after a gap: a new block
    block_ = {t, t, 0.0};
    return;
  }
  block_.angle += 0.5 * (previous + yaw_rate) * dt;
  block_.t1 = t;
  if (block_.t1 - block_.t0 < kBlock) return;
  if (pending_.size() >= kMaxPending) pending_.pop_front();  // the IMU stopped: bounded memory
  pending_.push_back(block_);
  block_ = {t, t, 0.0};
}

bool OdometerDelayEstimator::anglesAt(const std::vector<Rate>& samples, double t,
                                      std::vector<double>& angles) const {
  angles.resize(sum_x_.size());
  if (samples.size() < 2 || angles.empty()) return false;
  // Locals: a store into `angles` could otherwise alias the members, reloaded every candidate;
  // the candidates from delays_, the same doubles the grid formula gives.
  const Rate* g = samples.data();
  const std::size_t n = samples.size();
  double* out = angles.data();
  const double* d = delays_.data();
  // The largest delay first: rising times (k d is monotonic in k), so the samples are walked
  // once and the range is checked at its two ends.
  if (t - d[angles.size() - 1] < g[0].t || t - d[0] > g[n - 1].t) return false;
  // The interval's end, while there is a later one: a candidate at or after it moves on (rarely:
  // several candidates share an interval), so each candidate costs one comparison.
  std::size_t at = 0;
  double next_t = -INFINITY, a_t = 0.0, a_angle = 0.0, a_rate = 0.0, slope = 0.0;
  for (std::size_t k = angles.size(); k-- > 0;) {
    const double tk = t - d[k];
    if (next_t <= tk) {
      while (at + 2 < n && g[at + 1].t <= tk) ++at;
      const Rate &a = g[at], &b = g[at + 1];
      if (b.t - a.t > 0.1) return false;  // an IMU gap
      // The rate is linear between samples: its integral is quadratic.
      slope = b.t > a.t ? (b.rate - a.rate) / (b.t - a.t) : 0.0;
      a_t = a.t;
      a_angle = a.angle;
      a_rate = a.rate;
      next_t = at + 2 < n ? b.t : INFINITY;
    }
    const double h = tk - a_t;
    out[k] = a_angle + a_rate * h + 0.5 * slope * h * h;
  }
  return true;
}

void OdometerDelayEstimator::compare(const Block& b) {
  const double span = b.t1 - b.t0;
  const double w = b.angle / span;
  // The samples the candidates read, copied once: indexing the ring for each of the ~1000
  // look-ups cost more than the comparison itself (callgrind). From the last sample at or
  // before the earliest time asked to the one after the first at or after the latest, one more
  // each side for the rounding of the delay grid, so that every look-up finds the samples (and
  // the gaps) it would find in the whole ring.
  // Binary search by index (the ring has no iterators): the first sample later than t (or_at:
  // not earlier than t).
  const auto firstAfter = [&](double t, bool or_at) {
    std::size_t lo = 0, hi = gyro_.size();
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      const bool before = or_at ? gyro_[mid].t < t : gyro_[mid].t <= t;
      if (before) {
        lo = mid + 1;
      } else {
        hi = mid;
      }
    }
    return lo;
  };
  std::size_t first = firstAfter(b.t0 - max_delay_s_, false);
  for (int k = 0; k < 2 && first > 0; ++k) --first;
  std::size_t last = firstAfter(b.t1 + max_delay_s_, true);
  for (int k = 0; k < 2 && last < gyro_.size(); ++k) ++last;
  window_.clear();
  for (std::size_t k = first; k < last; ++k) window_.push_back(gyro_[k]);
  // Every candidate sees the same blocks: one outside the data or across a gap skips the block.
  const bool start_known = b.t0 == end_t_;
  std::swap(start_, end_);
  end_t_ = NAN;
  if (!start_known && !anglesAt(window_, b.t0, start_)) return;
  if (!anglesAt(window_, b.t1, end_)) return;
  end_t_ = b.t1;
  ++n_;
  sum_w_ += w;
  sum_ww_ += w * w;
  for (std::size_t j = 0; j < end_.size(); ++j) {
    const double x = (end_[j] - start_[j]) / span;
    sum_x_[j] += x;
    sum_xx_[j] += x * x;
    sum_xw_[j] += x * w;
  }
}

OdometerDelay OdometerDelayEstimator::estimate() const {
  OdometerDelay out;
  out.samples = n_;
  if (n_ < kMinSamples) return out;
  const double n = static_cast<double>(n_);
  const double sww = sum_ww_ - sum_w_ * sum_w_ / n;
  // Residual of w = a x + b at each candidate delay.
  std::vector<double> r(sum_x_.size());
  std::size_t best = 0;
  for (std::size_t j = 0; j < r.size(); ++j) {
    const double sxx = sum_xx_[j] - sum_x_[j] * sum_x_[j] / n;
    const double sxw = sum_xw_[j] - sum_x_[j] * sum_w_ / n;
    r[j] = sxx > 0.0 ? sww - sxw * sxw / sxx : std::numeric_limits<double>::infinity();
    if (r[j] < r[best]) best = j;
  }
  const std::size_t mid = r.size() / 2;
  out.yaw_rate_rms = std::sqrt(std::max(0.0, sum_xx_[mid] / n));
  if (best < kFitHalfWidth || best + kFitHalfWidth >= r.size() || out.yaw_rate_rms < kMinYawRateRms)
    return out;
  // A parabola fitted over +-kFitHalfWidth grid points: the residual is jagged from point to
  // point (each candidate averages other gyro samples), its trend is the delay's information.
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d aty = Eigen::Vector3d::Zero();
  for (std::size_t j = best - kFitHalfWidth; j <= best + kFitHalfWidth; ++j) {
    const double x = (static_cast<double>(j) - static_cast<double>(best)) * step_s_;
    const Eigen::Vector3d row(1.0, x, x * x);
    ata += row * row.transpose();
    aty += row * (r[j] - r[best]);
  }
  const Eigen::Vector3d c = ata.ldlt().solve(aty);
  if (!(c(2) > 0.0) || !c.allFinite()) return out;
  const double half_width = static_cast<double>(kFitHalfWidth) * step_s_;
  const double shift = std::clamp(-c(1) / (2.0 * c(2)), -half_width, half_width);
  out.delay_s = -max_delay_s_ + static_cast<double>(best) * step_s_ + shift;
  // R(d) = R_min + c2 (d - delay)^2 = R_min + (d - delay)^2 / (2 sigma^2) * 2 sigma_r^2.
  const double sigma_r2 = std::max(r[best], 0.0) / (n - 3.0);
  // The curvature of the whole searched range bounds the local one from below: wiggles of the
  // residual from noise (the gyro's, over block edges) look like minima locally, a real delay
  // raises the residual across the range.
  Eigen::Matrix3d ata_all = Eigen::Matrix3d::Zero();
  Eigen::Vector3d aty_all = Eigen::Vector3d::Zero();
  for (std::size_t j = 0; j < r.size(); ++j) {
    const double x = (static_cast<double>(j) - static_cast<double>(best)) * step_s_ - shift;
    const Eigen::Vector3d row(1.0, x, x * x);
    ata_all += row * row.transpose();
    aty_all += row * (r[j] - r[best]);
  }
  const double c2 = std::min(c(2), ata_all.ldlt().solve(aty_all)(2));
  if (!(c2 > 0.0)) return out;
  out.sigma_s = std::sqrt(sigma_r2 / c2);
  // A drive with little change of turn rate leaves the residual flat: another delay as good
  // (within a chi-square step of 4) far from this one makes the estimate no estimate.
  for (std::size_t j = 0; j < r.size(); ++j) {
    const double d = -max_delay_s_ + static_cast<double>(j) * step_s_;
    if (std::abs(d - out.delay_s) > 4.0 * out.sigma_s + half_width &&
        r[j] - r[best] < 4.0 * sigma_r2)
      return out;
  }
  // Beyond kMaxSigma the curve is too flat for its sigma to be trusted (the paper preset's drive:
  // 25-60 ms claimed, 40-340 ms off): no estimate.
  out.valid = std::isfinite(out.sigma_s) && out.sigma_s < kMaxSigma;
  return out;
}

}  // namespace giocal
