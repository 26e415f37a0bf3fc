#include "common/math/kalman_update.h"

#include <Eigen/Cholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <optional>

namespace giocal {

namespace {
constexpr double kDowndateTolerance = 1e-9;  // of a prior variance, a negative result may reach
}  // namespace

UpdateResult kalmanUpdate(Eigen::MatrixXd& P, const MeasurementRows& rows, double chi2_gate,
                          const std::vector<int>& held, KalmanWorkspace* workspace) {
  UpdateResult out;
  // Constructed only when needed: an empty workspace's sparse matrix allocates.
  std::optional<KalmanWorkspace> local;
  kalmanUpdateInto(P, rows, chi2_gate, held, workspace ? *workspace : local.emplace(), out);
  if (!out.accepted) out.dx.resize(0);
  return out;
}

void kalmanUpdateInto(Eigen::MatrixXd& P, const MeasurementRows& rows, double chi2_gate,
                      const std::vector<int>& held, KalmanWorkspace& ws, UpdateResult& out) {
  kalmanGainInto(P, rows, chi2_gate, held, ws, out);
  if (out.accepted) kalmanDowndate(P, held, ws, out);
}

void kalmanGainInto(const Eigen::MatrixXd& P, const MeasurementRows& rows, double chi2_gate,
                    const std::vector<int>& held, KalmanWorkspace& ws, UpdateResult& out) {
  out.nis = 0.0;
  out.accepted = false;
  out.numerical_failure = false;
  const Eigen::Index n = P.rows(), m = rows.H.rows();
  // H's zeros skipped: GNSS and odometer rows touch a few blocks of a long state.
  const Eigen::SparseMatrix<double>& H = ws.sparse(rows.H);
  Eigen::Map<Eigen::MatrixXd> PHt = ws.matrix(KalmanWorkspace::kPHt, n, m);
  PHt.noalias() = P * H.transpose();
  // W = H P first: S = W H^T then runs over W's contiguous columns (twice as fast as H (P H^T)
  // with a sparse left factor), and the same W is then solved in place below.
  Eigen::Map<Eigen::MatrixXd> W = ws.matrix(KalmanWorkspace::kW, m, n);
  W = PHt.transpose();
  Eigen::Map<Eigen::MatrixXd> S = ws.matrix(KalmanWorkspace::kS, m, m);
  S.noalias() = W * H.transpose();
  S += rows.R;
  const Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(S);  // in place: S becomes its factor
  if (llt.info() != Eigen::Success) {
    out.numerical_failure = true;
    return;
  }
  Eigen::Map<Eigen::VectorXd> innovation(ws.matrix(KalmanWorkspace::kInnovation, m, 1).data(), m);
  innovation = -rows.residual;
  Eigen::Map<Eigen::VectorXd> s_innovation(ws.matrix(KalmanWorkspace::kSInnovation, m, 1).data(),
                                           m);
  s_innovation = innovation;
  llt.solveInPlace(s_innovation);
  out.nis = innovation.dot(s_innovation);
  if (!(out.nis <= chi2_gate)) return;
  out.dx.noalias() = PHt * s_innovation;  // K0 v, K0 = P H^T S^-1 never formed
  for (int i : held) out.dx[i] = 0.0;
  ws.gain_rows = m;
  out.accepted = true;
}

void kalmanDowndate(Eigen::MatrixXd& P, const std::vector<int>& held, KalmanWorkspace& ws,
                    UpdateResult& out) {
  const Eigen::Index n = P.rows(), m = ws.gain_rows;
  // What kalmanGainInto left: W = (P H^T)^T and S's Cholesky factor in S's lower triangle.
  Eigen::Map<Eigen::MatrixXd> W = ws.matrix(KalmanWorkspace::kW, m, n);
  const Eigen::Map<Eigen::MatrixXd> S = ws.matrix(KalmanWorkspace::kS, m, m);
  // Joseph form (I-KH) P (I-KH)^T + K R K^T with the optimal gain K0 = PH^T S^-1 and K = D K0,
  // D the mask of the states that are not held: with M = K0 S K0^T = K0 (PH^T)^T it expands to
  // P - D M - M D + D M D, which is P - M except on the held x held block, where it is P.
  // M = W^T W with W = L^-1 (PH^T)^T (S = L L^T): one triangular solve and a symmetric rank-m
  // update of P's lower triangle, half the work of forming K0 and K0 (PH^T)^T.
  S.triangularView<Eigen::Lower>().solveInPlace(W);
  // The downdate in floating point can overshoot a variance the update nearly zeroes: checked
  // on the diagonal, and undone (from this copy) rather than kept.
  Eigen::Map<Eigen::MatrixXd> P_before = ws.matrix(KalmanWorkspace::kPBefore, n, n);
  P_before = P;
  const auto n_held = static_cast<Eigen::Index>(held.size());
  Eigen::Map<Eigen::MatrixXd> P_held = ws.matrix(KalmanWorkspace::kPHeld, n_held, n_held);
  for (size_t a = 0; a < held.size(); ++a)
    for (size_t b = 0; b < held.size(); ++b) P_held(a, b) = P(held[a], held[b]);
  P.selfadjointView<Eigen::Lower>().rankUpdate(W.transpose(), -1.0);
  P.triangularView<Eigen::StrictlyUpper>() = P.transpose();
  for (size_t a = 0; a < held.size(); ++a)
    for (size_t b = 0; b < held.size(); ++b) P(held[a], held[b]) = P_held(a, b);
  // Beyond rounding (a variance the update nearly zeroes may end a few ulps below zero).
  const bool overshot =
      (P.diagonal().array() < -kDowndateTolerance * P_before.diagonal().array().abs()).any();
  if (overshot || !P.diagonal().allFinite()) {
    P = P_before;
    out.numerical_failure = true;
    out.accepted = false;
  }
}

Eigen::VectorXd normalizedInnovations(const Eigen::MatrixXd& P, const MeasurementRows& rows) {
  // S_ii = h_i P h_i^T over the row's nonzeros only: a row touches a few blocks of the state.
  // The nonzeros are found column by column (H is column-major, and most of a long state's
  // columns are zero in every row: skipped by one vectorized test), then listed row by row.
  const Eigen::Index m = rows.residual.size(), n = rows.H.cols();
  std::vector<Eigen::Index> nonzero_cols;
  std::vector<Eigen::Index> start(static_cast<size_t>(m) + 1, 0);
  nonzero_cols.reserve(static_cast<size_t>(n));
  for (Eigen::Index j = 0; j < n; ++j) {
    if (!(rows.H.col(j).array() != 0.0).any()) continue;
    nonzero_cols.push_back(j);
    const double* c = rows.H.col(j).data();
    for (Eigen::Index i = 0; i < m; ++i) start[static_cast<size_t>(i) + 1] += c[i] != 0.0;
  }
  for (Eigen::Index i = 0; i < m; ++i) start[i + 1] += start[i];
  std::vector<Eigen::Index> cols(static_cast<size_t>(start[m]));
  std::vector<Eigen::Index> next(start.begin(), start.end() - 1);
  for (const Eigen::Index j : nonzero_cols) {  // ascending, so each row's list is sorted
    const double* c = rows.H.col(j).data();
    for (Eigen::Index i = 0; i < m; ++i) {
      if (c[i] != 0.0) cols[static_cast<size_t>(next[i]++)] = j;
    }
  }
  // Consecutive rows with the same columns (a GNSS epoch's rows all touch the same pose blocks)
  // are taken together: their h gathered into H_c, P on those columns into P_cc, and
  // S_ii = R_ii + ((H_c P_cc) .* H_c) summed along the row.
  Eigen::VectorXd z(m);
  Eigen::MatrixXd H_c, P_cc;
  for (Eigen::Index i0 = 0; i0 < m;) {
    const Eigen::Index b0 = start[i0], k = start[i0 + 1] - b0;
    const Eigen::Index* c = cols.data() + b0;
    Eigen::Index i1 = i0 + 1;
    while (i1 < m && start[i1 + 1] - start[i1] == k &&
           std::equal(c, c + k, cols.data() + start[i1]))
      ++i1;
    H_c.resize(i1 - i0, k);
    P_cc.resize(k, k);
    for (Eigen::Index u = 0; u < k; ++u) {
      H_c.col(u) = rows.H.col(c[u]).segment(i0, i1 - i0);
      for (Eigen::Index v = 0; v < k; ++v) P_cc(v, u) = P(c[v], c[u]);
    }
    const Eigen::VectorXd hPh = (H_c * P_cc).cwiseProduct(H_c).rowwise().sum();
    for (Eigen::Index i = i0; i < i1; ++i) {
      const double s = rows.R(i, i) + hPh[i - i0];
      z[i] = std::abs(rows.residual[i]) / std::sqrt(std::max(s, 1e-300));
    }
    i0 = i1;
  }
  return z;
}

}  // namespace giocal
