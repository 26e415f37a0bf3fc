// FactorGraphCore's epoch variables: the names of an epoch's states, adding them to the window
// with their values, and reading an epoch's navigation state back.
#include "common/math/rotation.h"
#include "fgo/factor_graph_core.h"

namespace giocal {

FgoEpoch FactorGraphCore::newEpoch(double t) {
  FgoEpoch e;
  e.t = t;
  e.k = next_k_++;
  e.p = atEpoch(state::kP, e.k);
  e.q = atEpoch(state::kQ, e.k);
  e.v = atEpoch(state::kV, e.k);
  e.ba = atEpoch(state::kBa, e.k);
  e.bg = atEpoch(state::kBg, e.k);
  e.sv = atEpoch(state::kSv, e.k);
  e.sw = atEpoch(state::kSw, e.k);
  e.cd = atEpoch(state::kClockDrift, e.k);
  e.vt = atEpoch(state::kTdcpDrift, e.k);
  e.bs = atEpoch(state::kSppBias, e.k);
  return e;
}

void FactorGraphCore::addNavVariables(const FgoEpoch& e, const NavState& x, double s_v, double s_w,
                                      double cd) {
  Eigen::VectorXd q(4);
  quatToWxyz(x.q_n_b, q.data());
  w_.addVariable(vectorBlock(e.p), x.p_n_b);
  w_.addVariable(rotationBlock(e.q), q);
  w_.addVariable(vectorBlock(e.v), x.v_n_b);
  w_.addVariable(vectorBlock(e.ba), x.b_a);
  w_.addVariable(vectorBlock(e.bg), x.b_g);
  w_.addVariable(vectorBlock(e.sv, 1), Eigen::VectorXd::Constant(1, s_v));
  w_.addVariable(vectorBlock(e.sw, 1), Eigen::VectorXd::Constant(1, s_w));
  if (holds(calib_index::kSw)) w_.holdComponents(e.sw, {0});
  w_.addVariable(vectorBlock(e.cd, 1), Eigen::VectorXd::Constant(1, cd));
}

NavState FactorGraphCore::nav(const FgoEpoch& e) const {
  NavState x;
  x.t = e.t;
  x.p_n_b = w_.value(e.p);
  x.q_n_b = quatFromWxyz(w_.value(e.q).data());
  x.v_n_b = w_.value(e.v);
  x.b_a = w_.value(e.ba);
  x.b_g = w_.value(e.bg);
  return x;
}

}  // namespace giocal
