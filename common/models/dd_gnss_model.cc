#include "common/models/dd_gnss_model.h"

#include <algorithm>

#include "common/math/so3.h"
#include "common/models/block_values.h"

namespace giocal {

DdGnssModel::DdGnssModel(const LocalFrame& frame, std::vector<SdGeometry> geometry,
                         std::vector<DdObservation> observations,
                         std::vector<std::pair<double, double>> undiff_variance)
    : frame_(frame), geometry_(std::move(geometry)), obs_(std::move(observations)) {
  blocks_ = {vectorBlock(state::kP), rotationBlock(state::kQ), vectorBlock(state::kPbg)};
  for (const DdObservation& o : obs_) {
    if (!o.phase) continue;
    for (const SatId& s : {o.sat, o.ref}) {
      if (ambiguityBlock(s, o.band) < 0) {
        amb_keys_.push_back({s, o.band});
        blocks_.push_back(vectorBlock(ambiguityKey(s, o.band), 1));
      }
    }
  }
  covariance_ = ddCovariance(obs_, undiff_variance);
}

int DdGnssModel::ambiguityBlock(const SatId& sat, char band) const {
  const auto it = std::find(amb_keys_.begin(), amb_keys_.end(), std::make_pair(sat, band));
  return it == amb_keys_.end() ? -1 : 3 + static_cast<int>(it - amb_keys_.begin());
}

void DdGnssModel::evaluate(const double* const* params, Eigen::VectorXd& residual,
                           std::vector<Eigen::MatrixXd>* jacobians) const {
  const Vec3 p_n_b = vec3At(params[0]);
  const Mat3 R_n_b = quatAt(params[1]).toRotationMatrix();
  const Vec3 p_b_g = vec3At(params[2]);
  const Vec3 antenna_e = frame_.ecefFromEnu(p_n_b + R_n_b * p_b_g);
  const long m = residualSize();
  residual.resize(m);
  if (jacobians) {
    jacobians->clear();
    for (const StateBlock& b : blocks_)
      jacobians->push_back(Eigen::MatrixXd::Zero(m, b.tangentSize()));
  }
  const Mat3& R_e_n = frame_.R_e_n();
  for (long a = 0; a < m; ++a) {
    const DdObservation& o = obs_[static_cast<size_t>(a)];
    Eigen::RowVector3d G;
    const int bi = o.phase ? ambiguityBlock(o.sat, o.band) : -1;
    const int br = o.phase ? ambiguityBlock(o.ref, o.band) : -1;
    residual[a] = ddPredict(o, geometry_, antenna_e, o.phase ? params[bi][0] : 0.0,
                            o.phase ? params[br][0] : 0.0, &G) -
                  o.value;
    if (!jacobians) continue;
    const Eigen::RowVector3d G_n = G * R_e_n;
    (*jacobians)[0].row(a) = G_n;
    (*jacobians)[1].row(a) = -G_n * R_n_b * skew(p_b_g);
    (*jacobians)[2].row(a) = G_n * R_n_b;
    if (o.phase) {
      (*jacobians)[static_cast<size_t>(bi)](a, 0) = o.lambda;
      (*jacobians)[static_cast<size_t>(br)](a, 0) = -o.lambda;
    }
  }
}

}  // namespace giocal
