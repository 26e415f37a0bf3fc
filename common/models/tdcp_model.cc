#include "common/models/tdcp_model.h"

#include "common/math/so3.h"
#include "common/models/block_values.h"

namespace giocal {

TdcpModel::TdcpModel(const LocalFrame& frame, TdcpPair pair)
    : frame_(frame), pair_(std::move(pair)), covariance_(tdcpCovariance(pair_)) {}

const std::vector<StateBlock>& TdcpModel::blocks() const {
  static const std::vector<StateBlock> kBlocks{
      vectorBlock(at(state::kP, Copy::kI)), rotationBlock(at(state::kQ, Copy::kI)),
      vectorBlock(at(state::kP, Copy::kJ)), rotationBlock(at(state::kQ, Copy::kJ)),
      vectorBlock(state::kPbg)};
  return kBlocks;
}

void TdcpModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                         std::vector<Eigen::MatrixXd>* jacobians) const {
  const Vec3 p_i = vec3At(params[0]), p_j = vec3At(params[2]), p_b_g = vec3At(params[4]);
  const Mat3 R_i = quatAt(params[1]).toRotationMatrix();
  const Mat3 R_j = quatAt(params[3]).toRotationMatrix();
  const Vec3 ant_i = frame_.ecefFromEnu(p_i + R_i * p_b_g);
  const Vec3 ant_j = frame_.ecefFromEnu(p_j + R_j * p_b_g);
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
  }
}

}  // namespace giocal
