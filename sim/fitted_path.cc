#include "sim/fitted_path.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace giocal::sim {
namespace {

// Uniform cubic B-spline basis at x in [0, 1] and its first two derivatives (per unit of x).
void basis(double x, double b[4], double d1[4], double d2[4]) {
  const double y = 1.0 - x, x2 = x * x, x3 = x2 * x;
  b[0] = y * y * y / 6.0;
  b[1] = (3.0 * x3 - 6.0 * x2 + 4.0) / 6.0;
  b[2] = (-3.0 * x3 + 3.0 * x2 + 3.0 * x + 1.0) / 6.0;
  b[3] = x3 / 6.0;
  d1[0] = -0.5 * y * y;
  d1[1] = 1.5 * x2 - 2.0 * x;
  d1[2] = -1.5 * x2 + x + 0.5;
  d1[3] = 0.5 * x2;
  d2[0] = y;
  d2[1] = 3.0 * x - 2.0;
  d2[2] = -3.0 * x + 1.0;
  d2[3] = x;
}

// Gauss-Legendre on [0, 1], 6 points: exact for polynomials of degree 11.
constexpr double kNode[6] = {0.033765242898423975, 0.16939530676686776, 0.38069040695840156,
                             0.61930959304159844,  0.83060469323313224, 0.96623475710157603};
constexpr double kWeight[6] = {0.085662246189585178, 0.18038078652406930, 0.23395696728634552,
                               0.23395696728634552,  0.18038078652406930, 0.085662246189585178};

// (speed, heading, pitch) of the segment whose four control points are c, at x.
template <typename T>
void splineAt(const T* const* c, double x, T out[3]) {
  double b[4], d1[4], d2[4];
  basis(x, b, d1, d2);
  for (int k = 0; k < 3; ++k)
    out[k] = b[0] * c[0][k] + b[1] * c[1][k] + b[2] * c[2][k] + b[3] * c[3][k];
}

// The displacement of m over [0, x] of a segment of h seconds: int u (-sin psi cos th,
// cos psi cos th, sin th) dt.
template <typename T>
void displacementOf(const T* const* c, double x, double h, T out[3]) {
  using std::cos;
  using std::sin;
  for (int k = 0; k < 3; ++k) out[k] = T(0.0);
  for (int i = 0; i < 6; ++i) {
    T s[3];
    splineAt(c, x * kNode[i], s);
    const T w = s[0] * (h * x * kWeight[i]);
    out[0] -= w * sin(s[1]) * cos(s[2]);
    out[1] += w * cos(s[1]) * cos(s[2]);
    out[2] += w * sin(s[2]);
  }
}

// R_n_m p_m_g with R_n_m = Rz(psi) Rx(th).
template <typename T>
void antennaOffset(const T* const* c, double x, const Eigen::Vector3d& p, T out[3]) {
  using std::cos;
  using std::sin;
  T s[3];
  splineAt(c, x, s);
  const T cp = cos(s[1]), sp = sin(s[1]), ct = cos(s[2]), st = sin(s[2]);
  const T v1 = ct * p.y() - st * p.z(), v2 = st * p.y() + ct * p.z();
  out[0] = cp * p.x() - sp * v1;
  out[1] = sp * p.x() + cp * v1;
  out[2] = v2;
}

struct FixCost {
  double x, h;
  Eigen::Vector3d a, p_m_g, inv_sigma;
  template <typename T>
  bool operator()(const T* P, const T* c0, const T* c1, const T* c2, const T* c3, T* r) const {
    const T* const c[4] = {c0, c1, c2, c3};
    T d[3], o[3];
    displacementOf(c, x, h, d);
    antennaOffset(c, x, p_m_g, o);
    for (int k = 0; k < 3; ++k) r[k] = (P[k] + d[k] + o[k] - a[k]) * inv_sigma[k];
    return true;
  }
};

struct ContinuityCost {
  double h, inv_sigma;
  template <typename T>
  bool operator()(const T* P0, const T* P1, const T* c0, const T* c1, const T* c2, const T* c3,
                  T* r) const {
    const T* const c[4] = {c0, c1, c2, c3};
    T d[3];
    displacementOf(c, 1.0, h, d);
    for (int k = 0; k < 3; ++k) r[k] = (P1[k] - P0[k] - d[k]) * inv_sigma;
    return true;
  }
};

// Second differences of the control points, about h^2 times the second derivatives.
struct SmoothCost {
  Eigen::Vector3d inv_sigma;
  template <typename T>
  bool operator()(const T* c0, const T* c1, const T* c2, T* r) const {
    for (int k = 0; k < 3; ++k) r[k] = (c2[k] - 2.0 * c1[k] + c0[k]) * inv_sigma[k];
    return true;
  }
};

struct PitchPrior {
  double inv_sigma;
  template <typename T>
  bool operator()(const T* c, T* r) const {
    r[0] = c[2] * inv_sigma;
    return true;
  }
};

// The fixes' position at t, linearly interpolated (held beyond the ends).
Eigen::Vector3d positionAt(const std::vector<AntennaFix>& f, double t) {
  if (t <= f.front().t) return f.front().p_n;
  if (t >= f.back().t) return f.back().p_n;
  const auto it = std::upper_bound(f.begin(), f.end(), t,
                                   [](double v, const AntennaFix& a) { return v < a.t; });
  const AntennaFix &b = *it, &a = *std::prev(it);
  return a.p_n + (b.p_n - a.p_n) * ((t - a.t) / (b.t - a.t));
}

// The fixes with each coordinate replaced by the median of five fixes about it: the start of
// the fit, where an isolated wrong fix (metres off with a centimetre's sigma) leaves no trace.
// A median of five points of a monotone coordinate is the point itself.
std::vector<AntennaFix> medianOfFive(const std::vector<AntennaFix>& f) {
  std::vector<AntennaFix> out = f;
  for (size_t k = 2; k + 2 < f.size(); ++k) {
    for (int axis = 0; axis < 3; ++axis) {
      std::array<double, 5> v;
      for (size_t i = 0; i < 5; ++i) v[i] = f[k + i - 2].p_n[axis];
      std::nth_element(v.begin(), v.begin() + 2, v.end());
      out[k].p_n[axis] = v[2];
    }
  }
  return out;
}

}  // namespace

FittedPath::FittedPath(const std::vector<AntennaFix>& fixes, const Eigen::Vector3d& p_m_g,
                       const FittedPathOptions& o)
    : h_(o.knot_spacing), p_m_g_(p_m_g) {
  if (fixes.size() < 10) throw std::invalid_argument("fewer than 10 positions to fit a path to");
  if (!(h_ >= 0.05 && h_ <= 30.0)) {
    throw std::invalid_argument("knot spacing " + std::to_string(h_) + " s (0.05 to 30 s)");
  }
  if (!(fixes.front().t >= 0.0)) throw std::invalid_argument("positions before the path's start");
  for (size_t k = 1; k < fixes.size(); ++k) {
    const double gap = fixes[k].t - fixes[k - 1].t;
    if (!(gap > 0.0)) throw std::invalid_argument("positions not in rising time");
    if (gap > 30.0) {
      throw std::invalid_argument("a gap of " + std::to_string(gap) + " s between positions at t=" +
                                  std::to_string(fixes[k - 1].t) + " s (at most 30 s is bridged)");
    }
  }
  duration_ = fixes.back().t;
  const std::vector<AntennaFix> start = medianOfFive(fixes);
  const int S = std::max(1, static_cast<int>(std::ceil(duration_ / h_ - 1e-9)));

  // Start: speed, heading and pitch of the fixes' velocity over 2 s; the heading of the nearest
  // moving instant where the vehicle stands; the antenna offset taken off for the anchors.
  control_.assign(static_cast<size_t>(S + 3), Eigen::Vector3d::Zero());
  std::vector<bool> moving(control_.size(), false);
  for (size_t j = 0; j < control_.size(); ++j) {
    const double t = std::clamp((static_cast<double>(j) - 1.0) * h_, 0.0, duration_);
    const double t0 = std::max(0.0, t - 1.0), t1 = std::min(duration_, t + 1.0);
    const Eigen::Vector3d v = (positionAt(start, t1) - positionAt(start, t0)) / (t1 - t0);
    const double speed = v.head<2>().norm();
    moving[j] = speed > 0.1;  // RTK noise over 2 s is millimetres per second
    control_[j] = {speed, moving[j] ? std::atan2(-v.x(), v.y()) : 0.0,
                   moving[j] ? std::atan2(v.z(), speed) : 0.0};
  }
  const auto first = std::find(moving.begin(), moving.end(), true);
  double psi =
      first == moving.end() ? 0.0 : control_[static_cast<size_t>(first - moving.begin())].y();
  for (size_t j = 0; j < control_.size(); ++j) {
    if (!moving[j]) {
      control_[j].y() = psi;
      continue;
    }
    control_[j].y() = psi + std::remainder(control_[j].y() - psi, 2.0 * M_PI);  // unwrapped
    psi = control_[j].y();
  }
  anchor_.resize(static_cast<size_t>(S + 1));
  for (int s = 0; s <= S; ++s) {
    const Eigen::Vector3d& c = control_[static_cast<size_t>(s + 1)];
    const double* cs[4] = {c.data(), c.data(), c.data(), c.data()};
    Eigen::Vector3d off;
    antennaOffset(cs, 0.0, p_m_g_, off.data());
    anchor_[static_cast<size_t>(s)] = positionAt(start, s * h_) - off;
  }

  ceres::Problem problem;
  const auto cp = [&](int j) { return control_[static_cast<size_t>(j)].data(); };
  const auto ap = [&](int s) { return anchor_[static_cast<size_t>(s)].data(); };
  for (const AntennaFix& f : fixes) {
    const int s = std::min(S - 1, static_cast<int>(f.t / h_));
    const double x = f.t / h_ - s;
    auto* cost = new ceres::AutoDiffCostFunction<FixCost, 3, 3, 3, 3, 3, 3>(
        new FixCost{x, h_, f.p_n, p_m_g_, f.sigma.cwiseMax(o.min_sigma).cwiseInverse()});
    // Robust as well: beyond 3 sigma a solution's pull fades (Cauchy).
    problem.AddResidualBlock(cost, new ceres::CauchyLoss(3.0), ap(s), cp(s), cp(s + 1), cp(s + 2),
                             cp(s + 3));
  }
  for (int s = 0; s < S; ++s) {
    auto* cost = new ceres::AutoDiffCostFunction<ContinuityCost, 3, 3, 3, 3, 3, 3, 3>(
        new ContinuityCost{h_, 1e4});  // 0.1 mm
    problem.AddResidualBlock(cost, nullptr, ap(s), ap(s + 1), cp(s), cp(s + 1), cp(s + 2),
                             cp(s + 3));
  }
  const Eigen::Vector3d smooth(1.0 / (o.jerk_sigma * h_ * h_), 1.0 / (o.yaw_accel_sigma * h_ * h_),
                               1.0 / (o.pitch_accel_sigma * h_ * h_));
  for (int j = 0; j + 2 < static_cast<int>(control_.size()); ++j) {
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<SmoothCost, 3, 3, 3, 3>(new SmoothCost{smooth}), nullptr,
        cp(j), cp(j + 1), cp(j + 2));
  }
  for (int j = 0; j < static_cast<int>(control_.size()); ++j) {
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<PitchPrior, 1, 3>(new PitchPrior{1.0 / o.pitch_sigma}),
        nullptr, cp(j));
  }
  ceres::Solver::Options options;
  options.linear_solver_type =
      ceres::IsSparseLinearAlgebraLibraryTypeAvailable(options.sparse_linear_algebra_library_type)
          ? ceres::SPARSE_NORMAL_CHOLESKY
          : ceres::DENSE_NORMAL_CHOLESKY;
  options.max_num_iterations = 100;
  options.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);

  // The path is the integral from the first anchor: continuous and kinematically exact.
  for (int s = 0; s < S; ++s) {
    anchor_[static_cast<size_t>(s + 1)] = anchor_[static_cast<size_t>(s)] + displacement(s, 1.0);
  }
  std::vector<double> misses;
  for (const AntennaFix& f : fixes) {
    const Eigen::Vector3d miss = antennaAt(f.t) - f.p_n;
    misses.push_back(miss.norm());
    max_ = std::max(max_, miss.norm());
    if (miss.cwiseQuotient(f.sigma.cwiseMax(o.min_sigma)).cwiseAbs().maxCoeff() > 5.0) ++outliers_;
  }
  std::nth_element(misses.begin(), misses.begin() + static_cast<long>(misses.size() / 2),
                   misses.end());
  median_ = misses[misses.size() / 2];
}

Eigen::Vector3d FittedPath::displacement(int s, double x) const {
  const double* c[4];
  for (int i = 0; i < 4; ++i) c[i] = control_[static_cast<size_t>(s + i)].data();
  Eigen::Vector3d d;
  displacementOf(c, x, h_, d.data());
  return d;
}

PlanarMotion FittedPath::motionAt(int s, double x) const {
  double b[4], d1[4], d2[4];
  basis(x, b, d1, d2);
  Eigen::Vector3d v = Eigen::Vector3d::Zero(), v1 = v, v2 = v;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d& c = control_[static_cast<size_t>(s + i)];
    v += b[i] * c;
    v1 += d1[i] / h_ * c;
    v2 += d2[i] / (h_ * h_) * c;
  }
  PlanarMotion m;
  m.v = v.x();
  m.v_dot = v1.x();
  m.psi = v.y();
  m.psi_dot = v1.y();
  m.psi_ddot = v2.y();
  m.th = v.z();
  m.th_dot = v1.z();
  m.th_ddot = v2.z();
  return m;
}

VehicleKinematics FittedPath::at(double t) const {
  const double tc = std::clamp(t, 0.0, duration_);
  const int S = static_cast<int>(anchor_.size()) - 1;
  const int s = std::min(S - 1, static_cast<int>(tc / h_));
  const double x = tc / h_ - s;
  return planarKinematics(t, anchor_[static_cast<size_t>(s)] + displacement(s, x), motionAt(s, x));
}

Eigen::Vector3d FittedPath::antennaAt(double t) const {
  const VehicleKinematics m = at(t);
  return m.p_n_m + m.R_n_m * p_m_g_;
}

}  // namespace giocal::sim
