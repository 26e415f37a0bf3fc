#include "common/math/row_compression.h"

#include <Eigen/Cholesky>
#include <Eigen/QR>

namespace giocal {

MeasurementRows compressRows(const MeasurementRows& rows, const std::vector<int>& subset) {
  const Eigen::Index m = rows.H.rows(), n = rows.H.cols();
  std::vector<bool> in(static_cast<size_t>(m), false);
  for (int i : subset) in[static_cast<size_t>(i)] = true;
  std::vector<int> others, cols;
  for (Eigen::Index i = 0; i < m; ++i) {
    if (!in[static_cast<size_t>(i)]) others.push_back(static_cast<int>(i));
  }
  for (Eigen::Index j = 0; j < n; ++j) {
    for (int i : subset) {
      if (rows.H(i, j) != 0.0) {
        cols.push_back(static_cast<int>(j));
        break;
      }
    }
  }
  const auto k = static_cast<Eigen::Index>(subset.size());
  const auto c = static_cast<Eigen::Index>(cols.size());
  if (k <= c) return rows;
  for (int i : subset) {
    for (int o : others) {
      if (rows.R(i, o) != 0.0) return rows;
    }
  }
  // Whitened [H r] of the subset on its columns, then its triangular factor: Q^T [A a] =
  // [T t; 0 e], and T^T T = A^T A, T^T t = A^T a; e, the residual no state explains, goes.
  Eigen::MatrixXd Rs(k, k), A(k, c + 1);
  for (Eigen::Index a = 0; a < k; ++a) {
    for (Eigen::Index b = 0; b < k; ++b) Rs(a, b) = rows.R(subset[a], subset[b]);
    for (Eigen::Index j = 0; j < c; ++j) A(a, j) = rows.H(subset[a], cols[j]);
    A(a, c) = rows.residual[subset[a]];
  }
  const Eigen::LLT<Eigen::MatrixXd> llt(Rs);
  if (llt.info() != Eigen::Success) return rows;
  llt.matrixL().solveInPlace(A);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(A);
  const Eigen::MatrixXd T = qr.matrixQR().topRows(c).triangularView<Eigen::Upper>();

  const auto mo = static_cast<Eigen::Index>(others.size());
  MeasurementRows out;
  out.H = Eigen::MatrixXd::Zero(mo + c, n);
  out.residual.resize(mo + c);
  out.R = Eigen::MatrixXd::Zero(mo + c, mo + c);
  for (Eigen::Index a = 0; a < mo; ++a) {
    out.H.row(a) = rows.H.row(others[a]);
    out.residual[a] = rows.residual[others[a]];
    for (Eigen::Index b = 0; b < mo; ++b) out.R(a, b) = rows.R(others[a], others[b]);
  }
  for (Eigen::Index a = 0; a < c; ++a) {
    for (Eigen::Index j = 0; j < c; ++j) out.H(mo + a, cols[j]) = T(a, j);
    out.residual[mo + a] = T(a, c);
    out.R(mo + a, mo + a) = 1.0;
  }
  return out;
}

}  // namespace giocal
