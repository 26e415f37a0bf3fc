#include "common/models/tdcp_model.h"

#include <Eigen/Cholesky>
#include <cmath>

#include "common/math/so3.h"
#include "common/models/block_values.h"

namespace giocal {

TdcpModel::TdcpModel(const LocalFrame& frame, TdcpPair pair, bool with_drift)
    : frame_(frame),
      pair_(std::move(pair)),
      covariance_(tdcpCovariance(pair_)),
      with_drift_(with_drift) {}

const std::vector<StateBlock>& TdcpModel::blocks() const {
  static const std::vector<StateBlock> kBlocks{
      vectorBlock(at(state::kP, Copy::kI)), rotationBlock(at(state::kQ, Copy::kI)),
      vectorBlock(at(state::kP, Copy::kJ)), rotationBlock(at(state::kQ, Copy::kJ)),
      vectorBlock(state::kPbg)};
  static const std::vector<StateBlock> kWithDrift = [] {
    std::vector<StateBlock> b = kBlocks;
    b.push_back(vectorBlock(state::kTdcpDrift));
    return b;
  }();
  return with_drift_ ? kWithDrift : kBlocks;
}

void TdcpModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                         std::vector<Eigen::MatrixXd>* jacobians) const {
  const Vec3 p_i = vec3At(params[0]), p_j = vec3At(params[2]), p_b_g = vec3At(params[4]);
  const Mat3 R_i = quatAt(params[1]).toRotationMatrix();
  const Mat3 R_j = quatAt(params[3]).toRotationMatrix();
  const double dt = pair_.t1 - pair_.t0;
  const Vec3 drift = with_drift_ ? Vec3(vec3At(params[5]) * dt) : Vec3::Zero();
  const Vec3 ant_i = frame_.ecefFromEnu(p_i + R_i * p_b_g);
  const Vec3 ant_j = frame_.ecefFromEnu(p_j + R_j * p_b_g + drift);
  const long m = residualSize();
  residual.resize(m);
  if (jacobians) {
    jacobians->clear();
    for (const StateBlock& b : blocks())
      jacobians->push_back(Eigen::MatrixXd::Zero(m, b.tangentSize()));
  }
  const Mat3& R_e_n = frame_.R_e_n();
  for (long a = 0; a < m; ++a) {
    const TdcpRow& row = pair_.rows[static_cast<size_t>(a)];
    Eigen::RowVector3d G_i, G_j;
    residual[a] = tdcpPredict(pair_, row, ant_i, ant_j, &G_i, &G_j) - tdcpObserved(pair_, row);
    if (!jacobians) continue;
    const Eigen::RowVector3d Gn_i = G_i * R_e_n, Gn_j = G_j * R_e_n;
    (*jacobians)[0].row(a) = Gn_i;
    (*jacobians)[1].row(a) = -Gn_i * R_i * skew(p_b_g);
    (*jacobians)[2].row(a) = Gn_j;
    (*jacobians)[3].row(a) = -Gn_j * R_j * skew(p_b_g);
    (*jacobians)[4].row(a) = Gn_i * R_i + Gn_j * R_j;
    if (with_drift_) (*jacobians)[5].row(a) = Gn_j * dt;
  }
}

Eigen::Matrix3d tdcpDriftCovariance(const LocalFrame& frame, const TdcpPair& pair,
                                    const Eigen::Vector3d& p_e, double sigma) {
  const Eigen::Matrix3d nan = Eigen::Matrix3d::Constant(NAN);
  const auto m = static_cast<long>(pair.rows.size());
  // Each row's gradient (ENU) and its satellites: row a = rate(sat) - rate(ref).
  std::vector<SatId> sats;
  const auto index = [&sats](const SatId& s) {
    for (size_t k = 0; k < sats.size(); ++k) {
      if (sats[k] == s) return static_cast<long>(k);
    }
    sats.push_back(s);
    return static_cast<long>(sats.size() - 1);
  };
  Eigen::MatrixXd G(m, 3), D = Eigen::MatrixXd::Zero(m, static_cast<long>(pair.signals.size()));
  for (long a = 0; a < m; ++a) {
    const TdcpRow& row = pair.rows[static_cast<size_t>(a)];
    Eigen::RowVector3d g0, g1;
    tdcpPredict(pair, row, p_e, p_e, &g0, &g1);
    G.row(a) = g1 * frame.R_e_n();
    D(a, index(pair.signals[static_cast<size_t>(row.signal)].sat)) += 1.0;
    D(a, index(pair.signals[static_cast<size_t>(row.ref)].sat)) -= 1.0;
  }
  if (sats.size() < 4) return nan;
  // Weighted by the rows' covariance, as the estimators weigh them: A = (G' C^-1 G)^-1 G' C^-1.
  const Eigen::LLT<Eigen::MatrixXd> C(tdcpCovariance(pair));
  if (C.info() != Eigen::Success) return nan;
  C.matrixL().solveInPlace(G);
  Eigen::MatrixXd Dw = D.leftCols(static_cast<long>(sats.size()));
  C.matrixL().solveInPlace(Dw);
  const Eigen::LDLT<Eigen::Matrix3d> N(G.transpose() * G);
  // A sky that leaves a direction unfixed: its velocity is the position's, not the rows'.
  if (N.info() != Eigen::Success || !(N.rcond() > 1e-9)) return nan;
  const Eigen::MatrixXd AD = N.solve(G.transpose() * Dw);  // 3 x satellites
  return sigma * sigma * AD * AD.transpose();
}

}  // namespace giocal
