// PositionResiduals: the LC scheme's position solutions against the run's own trajectory, measured
// as the run goes: how far their horizontal errors exceed their stated sigmas, and for how long
// they stay alike. A consumer receiver's fixes wander (the Husky bag's: 1.9 times their sigma,
// autocorrelation 0.45 after 10 s); the estimators take each fix as independent, so their sigmas
// come out too small by about ratio * sqrt(fixes per independent one).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "common/gnss/pos_reader.h"
#include "common/io/sensor_logs.h"

namespace giocal {

struct PositionResiduals {
  long fixes = 0;              // fixes compared with the trajectory
  double interval_s = 0.0;     // their median spacing
  double sigma_ratio = 0.0;    // robust RMS of residual / stated sigma, east and north pooled
  double correlation_s = 0.0;  // sum of the residuals' autocorrelation over lags, times the spacing
  double inflation = 1.0;      // 1 + 2 * that sum: how many fixes count as one independent fix
  /// By how much the run's sigmas understate what these fixes support (1: not at all).
  double understatedBy() const;
};

/// Fed the run's trajectory samples in time order; compares each fix that falls between two
/// samples less than kMaxSampleGap apart with the antenna interpolated there. Memory is constant:
/// the autocorrelation is summed over a ring of the last kLags residuals, the robust RMS from a
/// histogram.
class PositionResidualCheck {
 public:
  static constexpr int kLags = 256;
  static constexpr double kMaxSampleGap = 1.0;  // [s]
  /// `fixes` sorted by time; p_b_g: the antenna in the IMU frame.
  PositionResidualCheck(std::vector<PositionFix> fixes, const Eigen::Vector3d& p_b_g);
  void add(const TruthSample& s);
  PositionResiduals result() const;

 private:
  void addResidual(double t, double z_e, double z_n);
  std::vector<PositionFix> fixes_;
  Eigen::Vector3d p_b_g_;
  size_t next_ = 0;
  bool have_prev_ = false;
  double prev_t_ = 0.0;
  Eigen::Vector3d prev_antenna_e_ = Eigen::Vector3d::Zero();
  // Residuals normalized by their sigma, in a ring; sums of products per lag.
  std::array<Eigen::Vector2d, kLags + 1> ring_{};
  long n_ = 0, run_ = 0;  // residuals in all, and since the last break in the fixes
  double last_t_ = 0.0;
  static constexpr size_t kSpacingSample = 64;
  std::vector<double> spacing_;  // the first kSpacingSample spacings of the fixes
  double spacing_median_ = 1.0;  // their median [s] (1 s until known)
  std::array<double, kLags + 1> sum_products_{};
  std::array<long, kLags + 1> pairs_{};
  Eigen::Vector2d sum_ = Eigen::Vector2d::Zero();
  std::array<long, 400> abs_histogram_{};  // |z| in bins of 0.05
};

}  // namespace giocal
