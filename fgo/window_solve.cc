// The window's own Gauss-Newton solve and its covariances, from one sparse robust Hessian.
#include <Eigen/Cholesky>
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/math/null_space.h"
#include "common/math/rotation.h"
#include "fgo/sliding_window.h"

namespace giocal {

namespace {

// Levenberg damping beyond which a step that raises the cost is given up: the values stay at the
// last ones that lowered it, and the solve reports it.
constexpr double kMaxDamping = 1e2;

/// CHOLMOD's simplicial LL^T with its factor in reach, for solves with L alone.
struct SimplicialLlt : Eigen::CholmodSimplicialLLT<Eigen::SparseMatrix<double>> {
  cholmod_factor* factor() { return m_cholmodFactor; }
};

}  // namespace

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

std::shared_ptr<SlidingWindow::WindowPlan> SlidingWindow::plan() const {
  auto p = std::make_shared<WindowPlan>();
  p->structure = structure_;
  const std::vector<StateKey> order = estimatedVariables();
  p->offset = tangentOffsets(order, &p->n);
  for (const StateKey& name : order) {
    for (int c : vars_.at(name).held) p->held.push_back(p->offset.at(name) + c);
  }
  std::vector<const Factor*> all;
  for (const Factor& fac : factors_) all.push_back(&fac);
  p->layouts = layouts(p->offset, all);
  // A window that slid by one epoch usually has the shape of the last: the same blocks at the
  // same offsets, the same held indices and every factor on the same segments. Then H's pattern,
  // the scatter indices and CHOLMOD's ordering (the same pattern gives the same one) are reused:
  // the symbolic work was about a seventh of the factor graph's time.
  std::vector<int> shape{p->n, static_cast<int>(order.size())};
  for (const StateKey& name : order) {
    shape.push_back(p->offset.at(name));
    shape.push_back(vars_.at(name).block.tangentSize());
  }
  shape.push_back(static_cast<int>(p->held.size()));
  shape.insert(shape.end(), p->held.begin(), p->held.end());
  for (const FactorLayout& l : p->layouts) {
    shape.push_back(static_cast<int>(l.segments.size()));
    for (const Segment& v : l.segments) shape.insert(shape.end(), {v.global, v.local, v.size});
  }
  if (plan_ && plan_->symbolic && plan_->symbolic->shape == shape) {
    p->symbolic = plan_->symbolic;
    return p;
  }
  p->symbolic = std::make_shared<SymbolicPlan>();
  ++symbolic_analyses_;
  SymbolicPlan& sp = *p->symbolic;
  sp.shape = std::move(shape);
  // The window's Hessian is sparse (a chain of epochs plus the calibration and ambiguity columns):
  // a sparse factorization is ~10x cheaper than a dense one at window 30, and CHOLMOD's ordering
  // ~15x cheaper than Eigen's own AMD (measured, docs/results.md). Its lower triangle's pattern is
  // built block by block: per variable (a column block), the variables at or after it that share
  // a factor with it (row blocks, its own first).
  const int n = p->n;
  std::vector<int> block_of(static_cast<size_t>(n), -1), start, size;
  for (const StateKey& name : order) {
    block_of[static_cast<size_t>(p->offset.at(name))] = static_cast<int>(start.size());
    start.push_back(p->offset.at(name));
    size.push_back(vars_.at(name).block.tangentSize());
  }
  // The factors on each variable; then per variable its distinct neighbours at or after it
  // (marked once each rather than collected with repeats and sorted).
  std::vector<std::vector<const FactorLayout*>> on(start.size());
  for (const FactorLayout& l : p->layouts) {
    for (const Segment& v : l.segments) on[static_cast<size_t>(block_of[v.global])].push_back(&l);
  }
  std::vector<std::vector<int>> below(start.size());  // row-block starts per column block
  std::vector<int> marked(start.size(), -1);
  for (size_t c = 0; c < start.size(); ++c) {
    for (const FactorLayout* l : on[c]) {
      for (const Segment& u : l->segments) {
        const int r = block_of[u.global];
        if (u.global < start[c] || marked[static_cast<size_t>(r)] == static_cast<int>(c)) continue;
        marked[static_cast<size_t>(r)] = static_cast<int>(c);
        below[c].push_back(u.global);
      }
    }
  }
  std::vector<std::vector<int>> rows_before(start.size());  // per row block, in a column below
  std::vector<int> outer(static_cast<size_t>(n) + 1, 0), inner;
  for (size_t c = 0; c < start.size(); ++c) {
    std::vector<int>& rows = below[c];
    std::sort(rows.begin(), rows.end());
    int before = 0;
    for (int r : rows) {
      rows_before[c].push_back(before);
      if (r != start[c]) before += size[static_cast<size_t>(block_of[r])];
    }
    for (int j = 0; j < size[c]; ++j) {
      outer[static_cast<size_t>(start[c] + j)] = static_cast<int>(inner.size());
      for (int r : rows) {
        const int first = r == start[c] ? r + j : r;
        for (int i = first; i < r + size[static_cast<size_t>(block_of[r])]; ++i) inner.push_back(i);
      }
    }
  }
  outer[static_cast<size_t>(n)] = static_cast<int>(inner.size());
  const std::vector<double> zeros(inner.size(), 0.0);
  sp.pattern = Eigen::Map<const Eigen::SparseMatrix<double>>(
      n, n, static_cast<long>(inner.size()), outer.data(), inner.data(), zeros.data());
  // Each entry of a factor's J^T J in H's lower triangle: where it goes (dest) and where it is in
  // the factor's own lower-triangular Hf (src), read per linearization as value[dest] += Hf[src].
  for (const FactorLayout& l : p->layouts) {
    std::vector<int>& d = sp.dest.emplace_back();
    std::vector<int>& from = sp.src.emplace_back();
    d.reserve(static_cast<size_t>(l.cols * (l.cols + 1) / 2));
    from.reserve(d.capacity());
    for (const Segment& u : l.segments) {
      for (const Segment& v : l.segments) {
        if (v.global > u.global) continue;
        const size_t c = static_cast<size_t>(block_of[v.global]);
        const std::vector<int>& rows = below[c];
        const size_t at = static_cast<size_t>(std::lower_bound(rows.begin(), rows.end(), u.global) -
                                              rows.begin());
        for (int j = 0; j < v.size; ++j) {
          const int col = v.global + j;
          // Column j of a diagonal block starts at its row j; an off-diagonal block's rows follow
          // the diagonal block's remaining rows and the blocks before it.
          const int base = u.global == v.global ? outer[static_cast<size_t>(col)] - j
                                                : outer[static_cast<size_t>(col)] + (v.size - j) +
                                                      rows_before[c][at];
          for (int i = u.global == v.global ? j : 0; i < u.size; ++i) {
            d.push_back(base + i);
            const int r = u.local + i, q = v.local + j;  // local row and column
            from.push_back(r >= q ? q * l.cols + r : r * l.cols + q);
          }
        }
      }
    }
  }
  sp.llt.cholmod().print = 0;  // a singular H is handled by the callers, not printed
  sp.llt.analyzePattern(sp.pattern);
  return p;
}

std::shared_ptr<SlidingWindow::Linearization> SlidingWindow::linearizeWindow() const {
  if (!plan_ || plan_->structure != structure_) plan_ = plan();
  auto lin = std::make_shared<Linearization>();
  lin->id = ++linearizations_;
  lin->version = version_;
  lin->plan = plan_;
  lin->H = plan_->symbolic->pattern;
  lin->b = Eigen::VectorXd::Zero(plan_->n);
  double* value = lin->H.valuePtr();
  forEachWhitenedFactor(
      plan_->layouts,
      [&](size_t k, const FactorLayout&, const Eigen::MatrixXd& Hf) {
        const std::vector<int>& d = plan_->symbolic->dest[k];
        const int* from = plan_->symbolic->src[k].data();
        const double* h = Hf.data();  // the lower triangle of the factor's own columns
        for (size_t t = 0; t < d.size(); ++t) value[d[t]] += h[from[t]];
      },
      &lin->b, true, &lin->cost);
  if (!lin->b.allFinite()) lin->cost = std::numeric_limits<double>::infinity();
  return lin;
}

SlidingWindow::Linearization& SlidingWindow::factorization() const {
  if (!linearization_ || linearization_->version != version_) linearization_ = linearizeWindow();
  linearization_->factorize();
  return *linearization_;
}

Eigen::MatrixXd SlidingWindow::marginalOf(const std::vector<StateKey>& names,
                                          const Eigen::MatrixXd* G) const {
  Linearization& f = factorization();  // (mutable: factorized on first use)
  std::vector<int> idx;
  for (const StateKey& name : names) {
    const auto it = f.plan->offset.find(name);
    if (it == f.plan->offset.end())
      throw std::out_of_range("no estimated window variable '" + name.str() + "'");
    for (int k = 0; k < vars_.at(name).block.tangentSize(); ++k) idx.push_back(it->second + k);
  }
  if (G && static_cast<long>(idx.size()) != G->rows())
    throw std::invalid_argument("covarianceAlong: G has " + std::to_string(G->rows()) +
                                " rows for " + std::to_string(idx.size()) + " tangent dimensions");
  return f.marginal(idx, G);
}

Eigen::MatrixXd SlidingWindow::covariance(const std::vector<StateKey>& names) const {
  return marginalOf(names, nullptr);
}

Eigen::MatrixXd SlidingWindow::covarianceAlong(const std::vector<StateKey>& names,
                                               const Eigen::MatrixXd& G) const {
  return marginalOf(names, &G);
}

SlidingWindow::SolveReport SlidingWindow::solve(int max_iterations, double function_tolerance) {
  return solver_ == WindowSolver::kCeres ? solveWithCeres(max_iterations, function_tolerance)
                                         : solveGaussNewton(max_iterations, function_tolerance);
}

SlidingWindow::SolveReport SlidingWindow::solveGaussNewton(int max_iterations,
                                                           double function_tolerance) {
  std::shared_ptr<Linearization> lin = linearizeWindow();
  SolveReport report{std::isfinite(lin->cost), 0, lin->cost, ""};
  if (!report.usable) {
    report.failure = "non-finite cost";
    return report;
  }
  std::vector<std::pair<StateKey, Eigen::VectorXd>> saved;
  for (const auto& [name, at] : lin->plan->offset) saved.push_back({name, vars_.at(name).value});
  double damping = 0.0;
  for (int it = 0; it < max_iterations; ++it) {
    const Eigen::VectorXd dx = lin->step(damping);
    if (!dx.allFinite()) {
      report.failure = "non-finite step";
      break;
    }
    // A step the quadratic model says gains less than the tolerance is not taken: the solve ends
    // here, and the factorization just made serves the covariances (no relinearization).
    const Eigen::VectorXd H_dx = lin->H.selfadjointView<Eigen::Lower>() * dx;
    const double predicted = -lin->b.dot(dx) - 0.5 * dx.dot(H_dx);
    const double enough = std::max(function_tolerance * lin->cost, 0.5 * step_sigma_ * step_sigma_);
    if (predicted <= enough) break;
    double x_norm = 0.0;
    for (auto& [name, x] : saved) {
      Variable& v = vars_.at(name);
      x = v.value;
      x_norm += x.squaredNorm();
      const auto d = dx.segment(lin->plan->offset.at(name), v.block.tangentSize());
      if (v.block.kind == BlockKind::kRotation) {
        quatToWxyz(boxPlus(quatFromWxyz(v.value.data()), d), v.value.data());
      } else {
        v.value += d;
      }
    }
    ++version_;
    std::shared_ptr<Linearization> next = linearizeWindow();
    // As Ceres: a cost change (either way) below the tolerance ends the solve.
    const double change = lin->cost - next->cost;
    const bool converged = std::abs(change) <= enough;
    if (!(change >= 0.0)) {
      // Worse: back to the previous values (whose linearization `lin` still is), damped.
      for (const auto& [name, x] : saved) vars_.at(name).value = x;
      ++version_;
      lin->version = version_;
      damping = damping == 0.0 ? 1e-2 : 10.0 * damping;
      if (converged) break;
      if (damping > kMaxDamping) {
        report.failure = "damping exhausted";
        break;
      }
      continue;
    }
    const std::shared_ptr<Linearization> previous = lin;
    lin = next;
    damping = 0.0;
    ++report.iterations;
    if (converged || dx.norm() <= 1e-8 * (std::sqrt(x_norm) + 1e-8)) break;
    // Whether another step is worth taking, asked first of the factorization just made (the
    // Hessian barely moves over a step this late): if that step gains less than the tolerance,
    // the solve ends and the same factorization serves the covariances. Many epochs end here,
    // one factorization sooner.
    auto chord = std::make_shared<Linearization>(*previous);
    chord->b = lin->b;
    chord->cost = lin->cost;
    chord->version = version_;
    const Eigen::VectorXd dc = chord->step(0.0);
    if (dc.allFinite()) {
      const Eigen::VectorXd H_dc = chord->H.selfadjointView<Eigen::Lower>() * dc;
      if (-chord->b.dot(dc) - 0.5 * dc.dot(H_dc) <= enough) {
        lin = chord;
        break;
      }
    }
  }
  // The last linearization is at the current values: the covariances asked for next reuse it.
  linearization_ = lin;
  report.final_cost = lin->cost;
  return report;
}

}  // namespace giocal
