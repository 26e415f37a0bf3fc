#include "common/math/row_compression.h"

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <cmath>
#include <numeric>

namespace giocal {

namespace {

/// Whitens the rows of A (the rows `subset` of a measurement with covariance R) by each block of
/// mutually correlated rows on its own: a GNSS epoch's DD groups are uncorrelated with each other,
/// so this costs the sum of the groups' cubes, not the subset's. False if a block's covariance is
/// not positive definite.
bool whitenByBlocks(const Eigen::MatrixXd& R, const std::vector<int>& subset, Eigen::MatrixXd& A) {
  const auto k = static_cast<Eigen::Index>(subset.size());
  // The blocks: connected components of R's pattern, by union-find over its lower triangle.
  std::vector<Eigen::Index> root(static_cast<size_t>(k));
  std::iota(root.begin(), root.end(), Eigen::Index{0});
  const auto find = [&root](Eigen::Index a) {
    while (root[static_cast<size_t>(a)] != a) {
      a = root[static_cast<size_t>(a)] = root[static_cast<size_t>(root[static_cast<size_t>(a)])];
    }
    return a;
  };
  for (Eigen::Index b = 0; b < k; ++b) {
    const double* col = R.col(subset[static_cast<size_t>(b)]).data();
    for (Eigen::Index a = b + 1; a < k; ++a) {
      if (col[subset[static_cast<size_t>(a)]] == 0.0) continue;
      const Eigen::Index ra = find(a), rb = find(b);
      if (ra != rb) root[static_cast<size_t>(std::max(ra, rb))] = std::min(ra, rb);
    }
  }
  std::vector<Eigen::Index> members;
  for (Eigen::Index a = 0; a < k; ++a) {
    if (find(a) != a) continue;  // each block once, from its first row
    members.clear();
    for (Eigen::Index b = a; b < k; ++b) {
      if (find(b) == a) members.push_back(b);
    }
    const auto row = [&](Eigen::Index i) { return subset[static_cast<size_t>(members[i])]; };
    if (members.size() == 1) {
      const double r = R(row(0), row(0));
      if (!(r > 0.0)) return false;
      A.row(a) /= std::sqrt(r);
      continue;
    }
    const auto kb = static_cast<Eigen::Index>(members.size());
    Eigen::MatrixXd Rb(kb, kb), Ab(kb, A.cols());
    for (Eigen::Index i = 0; i < kb; ++i) {
      for (Eigen::Index j = 0; j < kb; ++j) Rb(i, j) = R(row(i), row(j));
      Ab.row(i) = A.row(members[i]);
    }
    const Eigen::LLT<Eigen::MatrixXd> llt(Rb);
    if (llt.info() != Eigen::Success) return false;
    llt.matrixL().solveInPlace(Ab);
    for (Eigen::Index i = 0; i < kb; ++i) A.row(members[i]) = Ab.row(i);
  }
  return true;
}

}  // namespace

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
  Eigen::MatrixXd A(k, c + 1);
  for (Eigen::Index a = 0; a < k; ++a) {
    for (Eigen::Index j = 0; j < c; ++j) A(a, j) = rows.H(subset[a], cols[j]);
    A(a, c) = rows.residual[subset[a]];
  }
  if (!whitenByBlocks(rows.R, subset, A)) return rows;
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
