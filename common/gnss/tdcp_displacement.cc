#include "common/gnss/tdcp_displacement.h"

#include <Eigen/Cholesky>
#include <map>
#include <utility>

#include "common/gnss/spp.h"

namespace giocal {

namespace {

// One Gauss-Newton solve over the signals marked used; unknowns d (3) and a clock change per
// system and band. Returns false when the geometry cannot carry it.
bool solveOnce(const TdcpPair& pair, const Eigen::Vector3d& p0_e, const std::vector<bool>& used,
               TdcpDisplacement& out, Eigen::VectorXd& normalized) {
  std::map<std::pair<GnssSystem, char>, int> clocks;
  int n = 0;
  for (size_t i = 0; i < pair.signals.size(); ++i) {
    if (!used[i]) continue;
    clocks.emplace(std::make_pair(pair.signals[i].sat.sys, pair.signals[i].band), 0);
    ++n;
  }
  int k = 3;
  for (auto& [key, column] : clocks) column = k++;
  if (n < k + 1) return false;
  Eigen::Vector3d d = out.d_e;
  Eigen::MatrixXd A(n, k);
  Eigen::VectorXd r(n), w(n);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(k);
  for (int iteration = 0; iteration < 4; ++iteration) {
    A.setZero();
    int row = 0;
    for (size_t i = 0; i < pair.signals.size(); ++i) {
      if (!used[i]) continue;
      const TdcpSignal& s = pair.signals[i];
      const Eigen::Vector3d r1 = s.sat1_e - (p0_e + d), r0 = s.sat0_e - p0_e;
      const double predicted = r1.norm() - r0.norm() - s.sat_clock_change_m + s.tropo_change_m;
      A.block<1, 3>(row, 0) = -r1.normalized().transpose();
      A(row, clocks.at({s.sat.sys, s.band})) = 1.0;
      w(row) = 1.0 / std::sqrt(s.variance);
      r(row) = s.phase_change_m - predicted;  // the clock columns start at zero each pass
      ++row;
    }
    const Eigen::MatrixXd Aw = w.asDiagonal() * A;
    const Eigen::MatrixXd N = Aw.transpose() * Aw;
    Eigen::LDLT<Eigen::MatrixXd> ldlt(N);
    if (ldlt.info() != Eigen::Success || ldlt.rcond() < 1e-12) return false;
    x = ldlt.solve(Aw.transpose() * (w.asDiagonal() * r));
    d += x.head<3>();
    out.cov = ldlt.solve(Eigen::MatrixXd::Identity(k, k)).topLeftCorner(3, 3);
    if (x.head<3>().norm() < 1e-6) break;
  }
  normalized = w.asDiagonal() * (r - A * x);
  out.d_e = d;
  out.signals_used = n;
  out.dof = n - k;
  out.chi2 = normalized.squaredNorm();
  return true;
}

}  // namespace

TdcpDisplacement solveTdcpDisplacement(const TdcpPair& pair, const Eigen::Vector3d& p0_e,
                                       const TdcpDisplacementOptions& options) {
  TdcpDisplacement out;
  std::vector<bool> used(pair.signals.size(), true);
  Eigen::VectorXd normalized;
  for (int rejections = 0;; ++rejections) {
    if (!solveOnce(pair, p0_e, used, out, normalized)) return TdcpDisplacement{};
    if (out.signals_used < options.min_satellites) return TdcpDisplacement{};
    if (out.dof < 1 || out.chi2 <= chi2Quantile(options.chi2_probability, out.dof)) break;
    if (rejections == options.max_rejections) return TdcpDisplacement{};
    long worst = 0;
    normalized.cwiseAbs().maxCoeff(&worst);
    for (size_t i = 0, row = 0; i < used.size(); ++i) {
      if (used[i] && static_cast<long>(row++) == worst) {
        used[i] = false;
        out.rejected.push_back(static_cast<int>(i));
        break;
      }
    }
  }
  out.valid = true;
  return out;
}

}  // namespace giocal
