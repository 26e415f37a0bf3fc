#include "common/calibration/coarse_mounting.h"

#include <cmath>

#include "common/math/rotation.h"

namespace giocal {

namespace {

// Ground robots drive on slopes of a few degrees, so the mean specific force of a drive is the
// up axis of the mean ground, not of the vehicle: a 2-degree tilt sigma covers it.
constexpr double kTiltSigma = 2.0 * M_PI / 180.0;
constexpr double kMinYawSigma = 1.0 * M_PI / 180.0;
constexpr double kMaxYawSigma = 10.0 * M_PI / 180.0;  // above: the drive cannot tell the heading
constexpr double kDerivativeSpan = 0.5;               // [s] for dv/dt from the odometer
// Slopes tilt the vehicle for longer than it accelerates: the local up axis, the mean specific
// force over this span, takes gravity out of the horizontal specific force on a slope too.
constexpr double kLocalUpSpan = 6.0;  // [s]

struct Window {
  double t;
  Eigen::Vector3d f, w;  // mean specific force and angular rate in b
  double v, yaw_rate;
};

// The IMU means over each odometer interval.
std::vector<Window> windowsOf(const std::vector<ImuSample>& imu,
                              const std::vector<OdomSample>& odom) {
  std::vector<Window> out;
  std::size_t i = 0;
  for (std::size_t k = 1; k < odom.size(); ++k) {
    const double t0 = odom[k - 1].t, t1 = odom[k].t;
    while (i < imu.size() && imu[i].t < t0) ++i;
    Eigen::Vector3d f = Eigen::Vector3d::Zero(), w = Eigen::Vector3d::Zero();
    int n = 0;
    for (std::size_t j = i; j < imu.size() && imu[j].t < t1; ++j, ++n) {
      f += imu[j].acc;
      w += imu[j].gyro;
    }
    if (n == 0 || t1 - t0 > 1.0) continue;
    out.push_back({0.5 * (t0 + t1), f / n, w / n, 0.5 * (odom[k - 1].v + odom[k].v),
                   0.5 * (odom[k - 1].w + odom[k].w)});
  }
  return out;
}

}  // namespace

CoarseMounting estimateMounting(const std::vector<ImuSample>& imu,
                                const std::vector<OdomSample>& odom) {
  CoarseMounting m;
  const std::vector<Window> ws = windowsOf(imu, odom);
  if (ws.size() < 20) {
    m.why_not = "fewer than 20 odometer intervals with IMU samples";
    return m;
  }
  Eigen::Vector3d mean_f = Eigen::Vector3d::Zero();
  for (const Window& w : ws) mean_f += w.f / static_cast<double>(ws.size());
  if (mean_f.norm() < 5.0) {
    m.why_not =
        "the mean specific force is not gravity (" + std::to_string(mean_f.norm()) + " m/s^2)";
    return m;
  }
  const Eigen::Vector3d up = mean_f.normalized();
  // A basis of the horizontal plane of b.
  const Eigen::Vector3d e1 =
      (std::abs(up.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY())
          .cross(up)
          .normalized();
  const Eigen::Vector3d e2 = up.cross(e1);
  // f_h = (a_long I + a_lat J) y, J turning y to the right (x_m = y_m x z_m), over the windows.
  Eigen::Vector2d sum_mf = Eigen::Vector2d::Zero();
  double sum_a2 = 0.0, sum_ww = 0.0, sum_w2 = 0.0;
  std::size_t j = 0;
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> rows;  // (a_long, a_lat), f_h
  std::size_t lo = 0, hi = 0;
  Eigen::Vector3d sum_f_local = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < ws.size(); ++k) {
    // dv/dt over about kDerivativeSpan around the window.
    std::size_t a = k, b = k;
    while (a > 0 && ws[k].t - ws[a].t < 0.5 * kDerivativeSpan) --a;
    while (b + 1 < ws.size() && ws[b].t - ws[k].t < 0.5 * kDerivativeSpan) ++b;
    if (ws[b].t - ws[a].t < 0.2) continue;
    const double a_long = (ws[b].v - ws[a].v) / (ws[b].t - ws[a].t);
    const double a_lat = -ws[k].v * ws[k].yaw_rate;
    while (lo < ws.size() && ws[lo].t < ws[k].t - 0.5 * kLocalUpSpan) sum_f_local -= ws[lo++].f;
    while (hi < ws.size() && ws[hi].t <= ws[k].t + 0.5 * kLocalUpSpan) sum_f_local += ws[hi++].f;
    const Eigen::Vector3d up_k = sum_f_local.normalized();
    const Eigen::Vector3d f_h = ws[k].f - ws[k].f.dot(up_k) * up_k;
    const Eigen::Vector2d f2(f_h.dot(e1), f_h.dot(e2));
    // M^T f with M = [[a_long, a_lat], [-a_lat, a_long]].
    sum_mf += Eigen::Vector2d(a_long * f2.x() - a_lat * f2.y(), a_lat * f2.x() + a_long * f2.y());
    sum_a2 += a_long * a_long + a_lat * a_lat;
    rows.push_back({{a_long, a_lat}, f2});
    sum_ww += ws[k].w.dot(up) * ws[k].yaw_rate;
    sum_w2 += ws[k].yaw_rate * ws[k].yaw_rate;
    ++j;
  }
  m.windows = static_cast<int>(j);
  if (sum_a2 <= 0.0) {
    m.why_not = "no speed change or turn in the drive: nothing tells the forward axis";
    return m;
  }
  const Eigen::Vector2d y2 = sum_mf / sum_a2;
  double r2 = 0.0;
  for (const auto& [acc, f2] : rows) {
    const Eigen::Vector2d pred(acc.x() * y2.x() + acc.y() * y2.y(),
                               -acc.y() * y2.x() + acc.x() * y2.y());
    r2 += (f2 - pred).squaredNorm();
  }
  const double sigma_f =
      std::sqrt(r2 / static_cast<double>(std::max<std::size_t>(1, 2 * rows.size() - 2)));
  const double sigma_yaw = sigma_f / std::sqrt(sum_a2) / std::max(1e-6, y2.norm());
  if (!(sigma_yaw < kMaxYawSigma)) {
    m.why_not = "too little speed change and turning to find the forward axis (yaw sigma " +
                std::to_string(sigma_yaw * 180.0 / M_PI) + " deg)";
    return m;
  }
  const Eigen::Vector3d y = (y2.x() * e1 + y2.y() * e2).normalized();
  Eigen::Matrix3d R_b_m;
  R_b_m.col(0) = y.cross(up);
  R_b_m.col(1) = y;
  R_b_m.col(2) = up;
  m.q_b_m = Eigen::Quaterniond(R_b_m).normalized();
  m.sigma_rpy = Eigen::Vector3d(kTiltSigma, kTiltSigma, std::max(kMinYawSigma, sigma_yaw));
  m.yaw_rate_slope = sum_w2 > 0.0 ? sum_ww / sum_w2 : 0.0;
  m.valid = true;
  return m;
}

}  // namespace giocal
