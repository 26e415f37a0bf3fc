// The window's own Gauss-Newton solve and its covariances, from one sparse robust Hessian
// (fgo/window_linearization.h).
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
#include "fgo/window_linearization.h"

namespace giocal {

namespace {

// Levenberg damping beyond which a step that raises the cost is given up: the values stay at the
// last ones that lowered it, and the solve reports it.
constexpr double kMaxDamping = 1e2;

}  // namespace

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
