#include "common/calibration/fix_heights.h"

#include <algorithm>
#include <cmath>

#include "common/geodesy/wgs84.h"
#include "common/math/median.h"

namespace giocal {

namespace {

constexpr int kMinFixes = 30;
constexpr double kMinDistance = 50.0;  // [m]
constexpr int kSpeedStep = 5;          // bins each side of the speed's difference quotient
constexpr double kMaxGrade = 0.5;      // sin of the steepest grade believed
constexpr double kMaxStep = 0.5;       // a gap in the sensors integrates no longer than this [s]

struct Profile {
  std::vector<double> t, height, distance;
  double at(const std::vector<double>& y, double x) const {
    const auto it = std::lower_bound(t.begin(), t.end(), x);
    if (it == t.begin()) return y.front();
    if (it == t.end()) return y.back();
    const size_t k = static_cast<size_t>(it - t.begin());
    const double u = (x - t[k - 1]) / (t[k] - t[k - 1]);
    return y[k - 1] + u * (y[k] - y[k - 1]);
  }
};

// The height and distance the IMU's grade and the odometer's speed give, bin by bin.
Profile motionProfile(const DriveProfile& drive) {
  const auto bins = drive.finished();
  const double g = drive.gravity();
  Profile p;
  double h = 0.0, d = 0.0;
  for (size_t i = 0; i < bins.size(); ++i) {
    const auto& [t, b] = bins[i];
    if (i > 0) {
      const size_t lo = i >= kSpeedStep ? i - kSpeedStep : 0;
      const size_t hi = std::min(bins.size() - 1, i + kSpeedStep);
      const double dv =
          hi > lo && bins[hi].first > bins[lo].first
              ? (bins[hi].second.speed - bins[lo].second.speed) / (bins[hi].first - bins[lo].first)
              : 0.0;
      // Along a grade theta the forward specific force is dv/dt + g sin(theta).
      const double grade = std::clamp((b.f_forward - dv) / g, -kMaxGrade, kMaxGrade);
      // A bin without both sensors is covered by the next; a longer gap integrates kMaxStep.
      const double dt = std::min(t - bins[i - 1].first, kMaxStep);
      h += b.speed * grade * dt;
      d += std::abs(b.speed) * dt;
    }
    p.t.push_back(t);
    p.height.push_back(h);
    p.distance.push_back(d);
  }
  return p;
}

}  // namespace

DriveProfile::Bin* DriveProfile::binAt(double t) {
  const long k = static_cast<long>(std::floor(t / kBin));
  if (bins_.empty()) first_ = k;
  // Before the first bin, or a stamp days ahead (a week rollover): not part of the drive.
  if (k < first_ || k - first_ > kMaxBins) return nullptr;
  if (k - first_ >= static_cast<long>(bins_.size()))
    bins_.resize(static_cast<size_t>(k - first_ + 1));
  return &bins_[static_cast<size_t>(k - first_)];
}

void DriveProfile::addImu(const ImuSample& s) {
  Bin* b = s.acc.allFinite() ? binAt(s.t) : nullptr;
  if (!b) return;
  b->f_forward += forward_b_.dot(s.acc);
  ++b->imu;
  gravity_sum_ += s.acc.norm();
  ++imu_;
}

void DriveProfile::addOdometer(const OdomSample& o) {
  Bin* b = std::isfinite(o.v) ? binAt(o.t) : nullptr;
  if (!b) return;
  b->speed += o.v;
  ++b->odom;
}

std::vector<std::pair<double, DriveProfile::Bin>> DriveProfile::finished() const {
  std::vector<std::pair<double, Bin>> out;
  for (size_t k = 0; k < bins_.size(); ++k) {
    Bin b = bins_[k];
    if (b.imu == 0 || b.odom == 0) continue;
    b.f_forward /= b.imu;
    b.speed /= b.odom;
    out.emplace_back((static_cast<double>(first_ + static_cast<long>(k)) + 0.5) * kBin, b);
  }
  return out;
}

FixHeights checkFixHeights(const std::vector<PositionFix>& fixes, const DriveProfile& drive) {
  FixHeights r;
  const Profile p = motionProfile(drive);
  if (p.t.size() < 2 || drive.gravity() <= 0.0) {
    r.why_not = "no IMU and odometer over the drive to compare the heights with";
    return r;
  }
  std::vector<double> y, d, sigma;
  for (const PositionFix& f : fixes) {
    if (f.t < p.t.front() || f.t > p.t.back() || !(f.cov_enu(2, 2) > 0.0)) continue;
    y.push_back(geodeticFromEcef(f.p_e).h - p.at(p.height, f.t));
    d.push_back(p.at(p.distance, f.t));
    sigma.push_back(std::sqrt(f.cov_enu(2, 2)));
  }
  r.fixes = static_cast<int>(y.size());
  r.distance_m = d.empty() ? 0.0 : d.back() - d.front();
  if (r.fixes < kMinFixes || r.distance_m < kMinDistance) {
    r.why_not = std::to_string(r.fixes) + " fixes over " +
                std::to_string(static_cast<int>(r.distance_m)) + " m of driving (needs " +
                std::to_string(kMinFixes) + " over " +
                std::to_string(static_cast<int>(kMinDistance)) + " m)";
    return r;
  }
  // y = c + grade d: the heights' offset, and the grade a constant error in the mounting's pitch
  // gives; what is left is the solution's own height error.
  const double n = static_cast<double>(y.size());
  double sd = 0, sy = 0, sdd = 0, sdy = 0;
  for (size_t k = 0; k < y.size(); ++k) {
    sd += d[k];
    sy += y[k];
    sdd += d[k] * d[k];
    sdy += d[k] * y[k];
  }
  const double det = n * sdd - sd * sd;
  r.grade = det > 0.0 ? (n * sdy - sd * sy) / det : 0.0;
  const double c = (sy - r.grade * sd) / n;
  std::vector<double> e(y.size());
  for (size_t k = 0; k < y.size(); ++k) e[k] = y[k] - c - r.grade * d[k];
  const double mid = median(e);
  for (double& v : e) v = std::abs(v - mid);
  r.spread_m = 1.4826 * median(e);  // the MAD as a sigma: a few wrong fixes do not decide it
  r.reported_sigma_m = median(sigma);
  r.decided = true;
  return r;
}

}  // namespace giocal
