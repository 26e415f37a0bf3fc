// The window's linearized system, private to the sliding window's solver: the symbolic plan a
// sparsity pattern needs once, and one linearization (sparse robust Hessian, gradient, CHOLMOD
// factorization) with its solves, marginal covariances and Gauss-Newton steps.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "common/math/null_space.h"
#include "fgo/sliding_window.h"

namespace giocal {

/// CHOLMOD's simplicial LL^T with its factor in reach, for solves with L alone.
struct SimplicialLlt : Eigen::CholmodSimplicialLLT<Eigen::SparseMatrix<double>> {
  cholmod_factor* factor() { return m_cholmodFactor; }
};

/// What a sparsity pattern needs once: H's pattern, where each factor's J^T J entries go, and
/// CHOLMOD's ordering and symbolic analysis. Windows of the same shape share it (below).
struct SymbolicPlan {
  std::vector<int> shape;               // the window's shape: blocks, held indices, segments
  Eigen::SparseMatrix<double> pattern;  // of H's lower triangle, values zero
  std::vector<std::vector<int>> dest;   // per layout: where each lower entry of its J^T J goes
  std::vector<std::vector<int>> src;    // per layout: that entry's place in the factor's Hf
  long factored = -1;                   // the linearization whose numbers `llt` holds
  bool ok = false;
  SimplicialLlt llt;
};

struct SlidingWindow::WindowPlan {
  long structure = -1;
  int n = 0;
  std::map<StateKey, int> offset;
  std::vector<int> held;  // tangent indices held at their value in a solve
  std::vector<FactorLayout> layouts;
  std::shared_ptr<SymbolicPlan> symbolic;
};

struct SlidingWindow::Linearization {
  long id = 0;
  long version = -1;
  Eigen::SparseMatrix<double> H;  // lower triangle (CHOLMOD reads only that)
  Eigen::VectorXd b;              // J^T r
  double cost = 0.0;
  // The iterations of one solve, and the covariances after it, have one sparsity pattern: its
  // layout, ordering and symbolic analysis are made once.
  std::shared_ptr<WindowPlan> plan;

  void factorize() {
    SymbolicPlan& sp = *plan->symbolic;
    if (sp.factored == id) return;
    sp.llt.factorize(H);
    sp.ok = sp.llt.info() == Eigen::Success;
    sp.factored = id;
  }
  /// H^-1 X; the dense pivoting LDLT where H is singular (a direction nothing observes) still
  /// returns the observed part.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& X) {
    factorize();
    Eigen::MatrixXd Y;
    if (plan->symbolic->ok) Y = plan->symbolic->llt.solve(X);
    if (!plan->symbolic->ok || !Y.allFinite()) {
      Y = Eigen::MatrixXd(H).selfadjointView<Eigen::Lower>().ldlt().solve(X);
    }
    return Y;
  }
  /// G^T C G, C the covariance of the tangent indices `idx` (G null: C itself): with
  /// H = P^T L L^T P it is Y^T Y, Y = L^-1 P E G (E their unit columns), one triangular solve with
  /// G's columns where H^-1 E takes two with idx's.
  Eigen::MatrixXd marginal(const std::vector<int>& idx, const Eigen::MatrixXd* G = nullptr) {
    factorize();
    const auto n = static_cast<long>(H.rows()), k = static_cast<long>(idx.size());
    const long m = G ? G->cols() : k;
    SimplicialLlt& llt = plan->symbolic->llt;
    if (plan->symbolic->ok) {
      cholmod_common& cm = llt.cholmod();
      cholmod_dense* E = cholmod_zeros(n, m, CHOLMOD_REAL, &cm);
      for (long j = 0; E && j < k; ++j) {
        for (long c = 0; c < m; ++c)
          static_cast<double*>(E->x)[c * n + idx[j]] = G ? (*G)(j, c) : double(c == j);
      }
      cholmod_dense* PE = E ? cholmod_solve(CHOLMOD_P, llt.factor(), E, &cm) : nullptr;
      cholmod_dense* Y = PE ? cholmod_solve(CHOLMOD_L, llt.factor(), PE, &cm) : nullptr;
      Eigen::MatrixXd C;
      if (Y)
        C.noalias() = Eigen::Map<Eigen::MatrixXd>(static_cast<double*>(Y->x), n, m).transpose() *
                      Eigen::Map<Eigen::MatrixXd>(static_cast<double*>(Y->x), n, m);
      cholmod_free_dense(&E, &cm);
      cholmod_free_dense(&PE, &cm);
      cholmod_free_dense(&Y, &cm);
      if (C.size() && C.allFinite()) return 0.5 * (C + C.transpose());
    }
    // H singular: the pseudo-inverse holds the observed part. Asked for the covariance itself,
    // a direction nothing observes gets an infinite variance (not the pseudo-inverse's 0, which
    // would read as perfectly known); along G (a quadratic form of the observed part) it stays.
    Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n, k);
    for (long j = 0; j < k; ++j) E(idx[j], j) = 1.0;
    const Eigen::MatrixXd X = solve(E);
    Eigen::MatrixXd C(k, k);
    for (long r = 0; r < k; ++r) C.row(r) = X.row(idx[r]);
    C = 0.5 * (C + C.transpose());
    if (G) return G->transpose() * C * *G;
    const Eigen::MatrixXd H_full = Eigen::MatrixXd(H).selfadjointView<Eigen::Lower>();
    const std::vector<int> none = unobservedIndices(H_full, idx);
    for (long j = 0; j < k; ++j) {
      if (std::find(none.begin(), none.end(), idx[j]) == none.end()) continue;
      C.row(j).setZero();
      C.col(j).setZero();
      C(j, j) = std::numeric_limits<double>::infinity();
    }
    return C;
  }
  /// The Gauss-Newton step with the held components at zero: the unconstrained step corrected
  /// along H^-1 E (E the held columns), so that one factorization of the whole H serves the
  /// step and the covariances. damping > 0: Levenberg-Marquardt on a copy of H.
  Eigen::VectorXd step(double damping) {
    if (damping > 0.0) {
      Linearization damped;
      damped.id = -1;  // never a window linearization's
      damped.plan = plan;
      plan->symbolic->factored = -2;  // each damping is factorized anew
      damped.H = H;
      damped.b = b;
      for (int i = 0; i < H.rows(); ++i) {
        damped.H.coeffRef(i, i) += damping * std::max(H.coeff(i, i), 1e-6);
      }
      return damped.step(0.0);
    }
    const std::vector<int>& held = plan->held;
    const long nh = static_cast<long>(held.size());
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(H.rows(), 1 + nh);
    rhs.col(0) = -b;
    for (long k = 0; k < nh; ++k) rhs(held[static_cast<size_t>(k)], 1 + k) = 1.0;
    const Eigen::MatrixXd X = solve(rhs);
    Eigen::VectorXd dx = X.col(0);
    if (held.empty()) return dx;
    const Eigen::MatrixXd Z = X.rightCols(nh);
    Eigen::MatrixXd M(held.size(), held.size());
    Eigen::VectorXd dh(static_cast<long>(held.size()));
    for (size_t k = 0; k < held.size(); ++k) {
      M.row(static_cast<long>(k)) = Z.row(held[k]);
      dh[static_cast<long>(k)] = dx[held[k]];
    }
    dx -= Z * M.ldlt().solve(dh);
    for (int i : held) dx[i] = 0.0;  // exactly
    return dx;
  }
};

}  // namespace giocal
