#include "fgo/sliding_window.h"

#include <ceres/ceres.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <set>
#include <stdexcept>

#include "common/math/null_space.h"
#include "common/math/whitening.h"
#include "fgo/marginal_prior_model.h"
#include "fgo/model_cost_function.h"
#include "fgo/right_quaternion_manifold.h"

namespace giocal {

void SlidingWindow::addVariable(const StateBlock& block, const Eigen::VectorXd& value) {
  ++version_;
  ++structure_;
  if (has(block.key))
    throw std::invalid_argument("window variable '" + block.key.str() + "' exists");
  if (value.size() != block.ambientSize()) {
    throw std::invalid_argument("window variable '" + block.key.str() + "': value size");
  }
  vars_[block.key] = {block, value, false, {}};
}

void SlidingWindow::removeVariable(const StateKey& name) {
  ++version_;
  ++structure_;
  vars_.erase(name);
  factors_.erase(std::remove_if(factors_.begin(), factors_.end(),
                                [&](const Factor& f) {
                                  return std::find(f.vars.begin(), f.vars.end(), name) !=
                                         f.vars.end();
                                }),
                 factors_.end());
}

Eigen::VectorXd& SlidingWindow::value(const StateKey& name) {
  ++version_;
  const auto it = vars_.find(name);
  if (it == vars_.end()) throw std::out_of_range("no window variable '" + name.str() + "'");
  return it->second.value;
}

const Eigen::VectorXd& SlidingWindow::value(const StateKey& name) const {
  const auto it = vars_.find(name);
  if (it == vars_.end()) throw std::out_of_range("no window variable '" + name.str() + "'");
  return it->second.value;
}

const StateBlock& SlidingWindow::block(const StateKey& name) const {
  const auto it = vars_.find(name);
  if (it == vars_.end()) throw std::out_of_range("no window variable '" + name.str() + "'");
  return it->second.block;
}

void SlidingWindow::setConstant(const StateKey& name, bool constant) {
  ++version_;
  ++structure_;
  value(name);
  vars_[name].constant = constant;
}

void SlidingWindow::holdComponents(const StateKey& name, const std::vector<int>& components) {
  ++version_;
  ++structure_;
  value(name);
  vars_[name].held = components;
}

void SlidingWindow::addFactor(Factor f) {
  ++version_;
  ++structure_;
  if (!f.sqrt_info) {
    f.sqrt_info =
        std::make_shared<const Eigen::MatrixXd>(whitener(f.model->covariance(), f.model->name()));
  }
  const Eigen::MatrixXd& S = *f.sqrt_info;
  f.sqrt_info_shape = S.isDiagonal(0.0)          ? Factor::Shape::kDiagonal
                      : S.isLowerTriangular(0.0) ? Factor::Shape::kLower
                                                 : Factor::Shape::kDense;
  f.sqrt_info_blocks.clear();
  if (f.sqrt_info_shape == Factor::Shape::kLower) {
    // A block ends before row i when no row from i on has an entry left of column i.
    const int m = static_cast<int>(S.rows());
    std::vector<int> first(static_cast<size_t>(m) + 1, m);  // min first nonzero col of rows >= i
    for (int i = m - 1; i >= 0; --i) {
      int j = 0;
      while (j < i && S(i, j) == 0.0) ++j;
      first[static_cast<size_t>(i)] = std::min(j, first[static_cast<size_t>(i) + 1]);
    }
    int start = 0;
    for (int i = 1; i <= m; ++i) {
      if (i == m || first[static_cast<size_t>(i)] >= i) {
        f.sqrt_info_blocks.push_back({start, i - start});
        start = i;
      }
    }
  }
  factors_.push_back(std::move(f));
}

int SlidingWindow::removeFactors(const std::string& tag) {
  ++version_;
  ++structure_;
  const auto n = factors_.size();
  factors_.erase(std::remove_if(factors_.begin(), factors_.end(),
                                [&](const Factor& f) { return f.tag == tag; }),
                 factors_.end());
  return static_cast<int>(n - factors_.size());
}

std::vector<StateKey> SlidingWindow::estimatedVariables() const {
  std::set<StateKey> used;
  for (const Factor& f : factors_) used.insert(f.vars.begin(), f.vars.end());
  std::vector<StateKey> out;
  for (const StateKey& n : used) {
    if (!vars_.at(n).constant) out.push_back(n);
  }
  return out;
}

SlidingWindow::SolveReport SlidingWindow::solveWithCeres(int max_iterations,
                                                         double function_tolerance) {
  ++version_;
  ceres::Problem::Options po;
  po.manifold_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem problem(po);
  std::set<StateKey> added;
  for (const Factor& f : factors_) {
    std::vector<double*> ptrs;
    for (const StateKey& n : f.vars) {
      Variable& v = vars_.at(n);
      ptrs.push_back(v.value.data());
      if (added.insert(n).second) {
        problem.AddParameterBlock(v.value.data(), static_cast<int>(v.value.size()));
      }
    }
    ceres::LossFunction* loss = f.huber > 0.0 ? new ceres::HuberLoss(f.huber) : nullptr;
    problem.AddResidualBlock(new ModelCostFunction(f.model, f.sqrt_info), loss, ptrs);
  }
  for (const StateKey& n : added) {
    Variable& v = vars_.at(n);
    if (v.block.kind == BlockKind::kRotation) {
      problem.SetManifold(v.value.data(), new RightQuaternionManifold);
    } else if (!v.held.empty() && static_cast<int>(v.held.size()) < v.block.size) {
      problem.SetManifold(v.value.data(), new ceres::SubsetManifold(v.block.size, v.held));
    }
    if (v.constant || static_cast<int>(v.held.size()) == v.block.size) {
      problem.SetParameterBlockConstant(v.value.data());
    }
  }
  ceres::Solver::Options options;
  // The window is a chain of epochs: sparse normal equations are ~3x faster than dense ones at
  // window 30 (docs/results.md). Dense only where Ceres was built without a sparse library.
  options.linear_solver_type =
      ceres::IsSparseLinearAlgebraLibraryTypeAvailable(options.sparse_linear_algebra_library_type)
          ? ceres::SPARSE_NORMAL_CHOLESKY
          : ceres::DENSE_NORMAL_CHOLESKY;
  options.max_num_iterations = max_iterations;
  options.function_tolerance = function_tolerance;
  // Start as Gauss-Newton: from Ceres' default radius (1e4), Levenberg-Marquardt's damping held
  // back the per-epoch scale chain (stiff random walk, weak information) for the whole solve,
  // and the function tolerance then stopped it with s_w near the initial guess.
  options.initial_trust_region_radius = 1e12;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  // Rotations stay unit quaternions.
  for (const StateKey& n : added) {
    Variable& v = vars_.at(n);
    if (v.block.kind == BlockKind::kRotation) v.value.normalize();
  }
  return {summary.IsSolutionUsable(), static_cast<int>(summary.iterations.size()),
          summary.final_cost, summary.IsSolutionUsable() ? "" : summary.message};
}

std::map<StateKey, int> SlidingWindow::tangentOffsets(const std::vector<StateKey>& order,
                                                      int* size) const {
  std::map<StateKey, int> offset;
  int n = 0;
  for (const StateKey& name : order) {
    offset[name] = n;
    n += vars_.at(name).block.tangentSize();
  }
  if (size) *size = n;
  return offset;
}

std::vector<SlidingWindow::FactorLayout> SlidingWindow::layouts(
    const std::map<StateKey, int>& offset, const std::vector<const Factor*>& factors) const {
  std::vector<FactorLayout> out;
  out.reserve(factors.size());
  for (const Factor* f : factors) {
    FactorLayout l;
    l.factor = f;
    for (size_t k = 0; k < f->vars.size(); ++k) {
      const Variable& v = vars_.at(f->vars[k]);
      l.vars.push_back(&v);
      const auto it = offset.find(f->vars[k]);
      if (it == offset.end()) continue;
      l.segments.push_back({it->second, l.cols, v.block.tangentSize()});
      l.blocks.push_back(k);
      l.cols += v.block.tangentSize();
    }
    if (!l.segments.empty()) out.push_back(std::move(l));
  }
  return out;
}

void SlidingWindow::forEachWhitenedFactor(const std::vector<FactorLayout>& factors,
                                          const FactorVisitor& visit, Eigen::VectorXd* b,
                                          bool robust, double* cost) const {
  std::vector<const double*> params;
  Eigen::VectorXd r;
  std::vector<Eigen::MatrixXd> J;
  Eigen::MatrixXd Hf, Jg, Hg;
  std::vector<Eigen::Index> cols;
  for (size_t n = 0; n < factors.size(); ++n) {
    const FactorLayout& l = factors[n];
    const Factor* f = l.factor;
    params.clear();
    for (const Variable* v : l.vars) params.push_back(v->value.data());
    f->model->evaluate(params.data(), r, &J);
    // One whitened Jacobian and one product per factor: per-block products cost more in
    // allocations than in arithmetic (window 30: 37.6 -> 29.4 ms per epoch).
    Eigen::MatrixXd Jf(r.size(), l.cols);
    for (size_t i = 0; i < l.segments.size(); ++i) {
      Jf.middleCols(l.segments[i].local, l.segments[i].size) = J[l.blocks[i]];
    }
    // A lower-triangular S takes half the products of a dense one, a diagonal one none.
    const Eigen::MatrixXd& S = *f->sqrt_info;
    Eigen::MatrixXd Jw;
    Eigen::VectorXd rw;
    if (f->sqrt_info_shape == Factor::Shape::kDiagonal) {
      Jw = S.diagonal().asDiagonal() * Jf;
      rw = S.diagonal().cwiseProduct(r);
    } else if (f->sqrt_info_shape == Factor::Shape::kLower) {
      Jw.resize(Jf.rows(), Jf.cols());
      rw.resize(r.size());
      for (const auto& [s0, k] : f->sqrt_info_blocks) {
        const auto L = S.block(s0, s0, k, k);
        rw.segment(s0, k).noalias() = L.triangularView<Eigen::Lower>() * r.segment(s0, k);
        if (k <= 8) {  // a DD group: the triangular kernel's set-up costs more than its savings
          Jw.middleRows(s0, k).noalias() = L.lazyProduct(Jf.middleRows(s0, k));
        } else {
          Jw.middleRows(s0, k).noalias() = L.triangularView<Eigen::Lower>() * Jf.middleRows(s0, k);
        }
      }
    } else {
      Jw.noalias() = S * Jf;
      rw.noalias() = S * r;
    }
    const double s2 = rw.squaredNorm();
    if (robust && f->huber > 0.0 && s2 > f->huber * f->huber) {
      const double weight = std::sqrt(f->huber / std::sqrt(s2));
      Jw *= weight;
      rw *= weight;
      if (cost) *cost += 0.5 * (2.0 * f->huber * std::sqrt(s2) - f->huber * f->huber);
    } else if (cost) {
      *cost += 0.5 * s2;
    }
    if (b) {
      const Eigen::VectorXd g = Jw.transpose() * rw;
      for (const Segment& seg : l.segments)
        b->segment(seg.global, seg.size) += g.segment(seg.local, seg.size);
    }
    Hf.setZero(l.cols, l.cols);
    if (f->sqrt_info_blocks.size() > 1) {
      // Rows whitened apart touch only their group's columns (a DD group: the pose and its
      // satellites' ambiguities): each group's J^T J on those alone, a tenth of the dense one.
      for (const auto& [s0, k] : f->sqrt_info_blocks) {
        cols.clear();
        for (Eigen::Index j = 0; j < Jw.cols(); ++j) {
          if (!(Jw.col(j).segment(s0, k).array() == 0.0).all()) cols.push_back(j);
        }
        const auto c = static_cast<Eigen::Index>(cols.size());
        Jg.resize(k, c);
        for (Eigen::Index a = 0; a < c; ++a) Jg.col(a) = Jw.col(cols[a]).segment(s0, k);
        Hg.setZero(c, c);
        Hg.selfadjointView<Eigen::Lower>().rankUpdate(Jg.transpose());
        for (Eigen::Index j = 0; j < c; ++j) {
          for (Eigen::Index i = j; i < c; ++i) Hf(cols[i], cols[j]) += Hg(i, j);
        }
      }
    } else {
      Hf.selfadjointView<Eigen::Lower>().rankUpdate(Jw.transpose());
    }
    visit(n, l, Hf);
  }
}

void SlidingWindow::linearize(const std::vector<StateKey>& order,
                              const std::vector<const Factor*>& factors, Eigen::MatrixXd& H,
                              Eigen::VectorXd& b) const {
  int n = 0;
  const std::map<StateKey, int> offset = tangentOffsets(order, &n);
  H = Eigen::MatrixXd::Zero(n, n);
  b = Eigen::VectorXd::Zero(n);
  forEachWhitenedFactor(
      layouts(offset, factors),
      [&](size_t, const FactorLayout& l, const Eigen::MatrixXd& Hf_lower) {
        const Eigen::MatrixXd Hf = Hf_lower.selfadjointView<Eigen::Lower>();
        for (const Segment& u : l.segments) {
          for (const Segment& v : l.segments) {
            H.block(u.global, v.global, u.size, v.size) +=
                Hf.block(u.local, v.local, u.size, v.size);
          }
        }
      },
      &b, /*robust=*/true);  // the weights of the solve: a down-weighted outlier stays so
}

void SlidingWindow::marginalize(const std::vector<StateKey>& names) {
  ++version_;
  ++structure_;
  const std::set<StateKey> drop(names.begin(), names.end());
  std::vector<const Factor*> touching;
  std::set<StateKey> keep_set;
  for (const Factor& f : factors_) {
    const bool t = std::any_of(f.vars.begin(), f.vars.end(),
                               [&](const StateKey& v) { return drop.count(v) != 0; });
    if (!t) continue;
    touching.push_back(&f);
    for (const StateKey& v : f.vars) {
      if (!drop.count(v) && !vars_.at(v).constant) keep_set.insert(v);
    }
  }
  std::vector<StateKey> m_order, k_order(keep_set.begin(), keep_set.end());
  for (const StateKey& v : names) {
    if (has(v) && !vars_.at(v).constant) m_order.push_back(v);
  }
  if (!touching.empty() && !k_order.empty()) {
    std::vector<StateKey> order = m_order;
    order.insert(order.end(), k_order.begin(), k_order.end());
    Eigen::MatrixXd H;
    Eigen::VectorXd b;
    linearize(order, touching, H, b);
    long nm = 0;
    for (const StateKey& v : m_order) nm += vars_.at(v).block.tangentSize();
    const long nk = H.rows() - nm;
    // Schur complement with a pseudo-inverse of the marginalized block (it may be singular along
    // directions nothing observed). Both eigen-decompositions are of the Jacobi-scaled matrix
    // (unit diagonal): the Hessian mixes metres, radians and cycles, and a threshold relative to
    // its largest eigenvalue would drop well-observed directions of small units.
    const Eigen::VectorXd dm = jacobiScale(H.topLeftCorner(nm, nm));
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> em(
        dm.asDiagonal() * H.topLeftCorner(nm, nm) * dm.asDiagonal());
    const double tol_m = kNullEigenvalue * std::max(1.0, em.eigenvalues().cwiseAbs().maxCoeff());
    const Eigen::VectorXd inv =
        em.eigenvalues().unaryExpr([&](double l) { return l > tol_m ? 1.0 / l : 0.0; });
    const Eigen::MatrixXd Hmm_inv = dm.asDiagonal() * em.eigenvectors() * inv.asDiagonal() *
                                    em.eigenvectors().transpose() * dm.asDiagonal();
    const Eigen::MatrixXd Hkm = H.bottomLeftCorner(nk, nm);
    Eigen::MatrixXd L = H.bottomRightCorner(nk, nk) - Hkm * Hmm_inv * Hkm.transpose();
    L = 0.5 * (L + L.transpose());
    const Eigen::VectorXd g = b.tail(nk) - Hkm * Hmm_inv * b.head(nm);
    const Eigen::VectorXd dk = jacobiScale(L);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ek(dk.asDiagonal() * L * dk.asDiagonal());
    const double tol_k = kNullEigenvalue * std::max(1.0, ek.eigenvalues().cwiseAbs().maxCoeff());
    std::vector<long> kept;
    for (long i = 0; i < nk; ++i) {
      if (ek.eigenvalues()[i] > tol_k) kept.push_back(i);
    }
    if (!kept.empty()) {
      Eigen::MatrixXd J(static_cast<long>(kept.size()), nk);
      Eigen::VectorXd r0(static_cast<long>(kept.size()));
      // L = S^-1 U diag(l) U^T S^-1 with S = diag(dk): rows sqrt(l) u^T S^-1, and J^T r0 = g.
      for (size_t a = 0; a < kept.size(); ++a) {
        const double l = ek.eigenvalues()[kept[a]];
        const Eigen::VectorXd u = ek.eigenvectors().col(kept[a]);
        J.row(static_cast<long>(a)) = std::sqrt(l) * u.cwiseQuotient(dk).transpose();
        r0[static_cast<long>(a)] = u.dot(dk.cwiseProduct(g)) / std::sqrt(l);
      }
      std::vector<StateBlock> blocks;
      Eigen::VectorXd x_lin(0);
      for (const StateKey& v : k_order) {
        StateBlock blk = vars_.at(v).block;
        blocks.push_back(blk);
        const Eigen::VectorXd& x = vars_.at(v).value;
        x_lin.conservativeResize(x_lin.size() + x.size());
        x_lin.tail(x.size()) = x;
      }
      Factor prior{std::make_shared<MarginalPriorModel>(blocks, x_lin, J, r0), k_order, 0.0,
                   "marginal_prior"};
      // Drop the old factors and variables, then add the new prior.
      for (const StateKey& v : names) removeVariable(v);
      addFactor(std::move(prior));
      return;
    }
  }
  for (const StateKey& v : names) removeVariable(v);
}

}  // namespace giocal
