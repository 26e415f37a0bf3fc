#include "common/gnss/lambda.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace giocal {

LtDL factorLtDL(const Eigen::MatrixXd& Qin) {
  const int n = static_cast<int>(Qin.rows());
  // Q's lower triangle is read, mirrored into the upper one, which is worked on: its columns are
  // contiguous where the rows of the lower one are strided.
  Eigen::MatrixXd Q = Qin;
  Q.triangularView<Eigen::StrictlyUpper>() = Q.transpose();
  LtDL f{Eigen::MatrixXd::Zero(n, n), Eigen::VectorXd::Zero(n)};
  Eigen::VectorXd l(n);  // row i of L before its scaling by L(i, i)
  // Eliminate from the last index down, so that the conditional variances D run last-to-first.
  for (int i = n - 1; i >= 0; --i) {
    f.D[i] = Q(i, i);
    if (!(f.D[i] > 0.0)) throw std::invalid_argument("LAMBDA: covariance is not positive definite");
    const double s = std::sqrt(Q(i, i));
    for (int j = 0; j <= i; ++j) l[j] = Q(j, i) / s;
    for (int j = 0; j < i; ++j) Q.col(j).head(j + 1) -= l.head(j + 1) * l[j];
    for (int j = 0; j <= i; ++j) f.L(i, j) = l[j] / l[i];
  }
  return f;
}

void integerGaussStep(Eigen::MatrixXd& L, std::vector<ZStep>& steps, int i, int j) {
  if (std::abs(L(i, j)) < 0.5) return;  // rounds to 0: most calls, without the rounding's cost
  const double mu = std::round(L(i, j));
  if (mu == 0.0) return;
  const int n = static_cast<int>(L.rows());
  for (int k = i; k < n; ++k) L(k, j) -= mu * L(k, i);
  steps.push_back({i, j, mu});
}

void swapAdjacent(Eigen::MatrixXd& L, Eigen::VectorXd& D, int j, double del,
                  std::vector<ZStep>& steps) {
  const int n = static_cast<int>(L.rows());
  const double eta = D[j] / del, lam = D[j + 1] * L(j + 1, j) / del;
  D[j] = eta * D[j + 1];
  D[j + 1] = del;
  for (int k = 0; k < j; ++k) {
    const double a0 = L(j, k), a1 = L(j + 1, k);
    L(j, k) = -L(j + 1, j) * a0 + a1;
    L(j + 1, k) = eta * a0 + lam * a1;
  }
  L(j + 1, j) = lam;
  for (int k = j + 2; k < n; ++k) std::swap(L(k, j), L(k, j + 1));
  steps.push_back({-1, j, 0.0});
}

namespace {

double sgn(double x) { return x <= 0.0 ? -1.0 : 1.0; }

}  // namespace

Eigen::VectorXd Decorrelation::toDecorrelated(const Eigen::VectorXd& a) const {
  // Z = G_1 ... G_m, so Z^T a = G_m^T ... G_1^T a: the first step first. A Gauss step's G^T takes
  // mu times entry i from entry j.
  Eigen::VectorXd z = a;
  for (const ZStep& s : steps) {
    if (s.i < 0) {
      std::swap(z[s.j], z[s.j + 1]);
    } else {
      z[s.j] -= s.mu * z[s.i];
    }
  }
  return z;
}

Eigen::VectorXd Decorrelation::fromDecorrelated(const Eigen::VectorXd& z) const {
  Eigen::VectorXd a = z;
  for (auto s = steps.rbegin(); s != steps.rend(); ++s) {
    if (s->i < 0) {
      std::swap(a[s->j], a[s->j + 1]);
    } else {
      a[s->j] += s->mu * a[s->i];
    }
  }
  return a;
}

Eigen::MatrixXd Decorrelation::Z() const {
  const auto n = ltdl.D.size();
  Eigen::MatrixXd Z = Eigen::MatrixXd::Identity(n, n);
  for (const ZStep& s : steps) {
    if (s.i < 0) {
      Z.col(s.j).swap(Z.col(s.j + 1));
    } else {
      Z.col(s.j) -= s.mu * Z.col(s.i);
    }
  }
  return Z;
}

Decorrelation decorrelate(const Eigen::MatrixXd& Q) {
  const int n = static_cast<int>(Q.rows());
  Decorrelation d{{}, factorLtDL(Q)};
  Eigen::MatrixXd& L = d.ltdl.L;
  Eigen::VectorXd& D = d.ltdl.D;
  int j = n - 2, k = n - 2;
  while (j >= 0) {
    if (j <= k) {
      for (int i = j + 1; i < n; ++i) integerGaussStep(L, d.steps, i, j);
    }
    const double del = D[j] + L(j + 1, j) * L(j + 1, j) * D[j + 1];
    if (del + 1e-6 < D[j + 1]) {
      swapAdjacent(L, D, j, del, d.steps);
      k = j;
      // The classic reduction starts again at n - 2, but a swap at j changes no D or L term of
      // the tests above j + 1, which all passed on the way down: the walk would test them again
      // and do nothing (no transformation above k), so it resumes at j + 1, the same steps.
      j = std::min(j + 1, n - 2);
    } else {
      --j;
    }
  }
  return d;
}

namespace {

// Depth-first search of the m best integer vectors for z ~ N(zs, L^T D L).
SearchResult searchDecorrelated(const Eigen::MatrixXd& L, const Eigen::VectorXd& D,
                                const Eigen::VectorXd& zs, int m) {
  const int n = static_cast<int>(zs.size());
  // zb[k] = zs[k] + C(k + 1, k), where C(r, k) sums (z - zb) * L(., k) over the levels r..n-1,
  // from the top down (C(n, k) = 0). A step of z at level j makes rows r <= j of every lower
  // column stale; path[k] is the highest stale row of column k, so a descent redoes only the
  // rows below the highest level that moved, not all k of them (Chang, Yang & Zhou 2005).
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n + 1, n);
  std::vector<int> path(static_cast<size_t>(n), n - 1);
  Eigen::VectorXd dist(n), zb(n), z(n), step(n);
  std::vector<Eigen::VectorXd> cand;
  std::vector<double> norms;
  double maxdist = std::numeric_limits<double>::infinity();
  int k = n - 1;
  dist[k] = 0.0;
  zb[k] = zs[k];
  z[k] = std::round(zb[k]);
  double y = zb[k] - z[k];
  step[k] = sgn(y);
  for (int guard = 0; guard < 10000000; ++guard) {
    const double newdist = dist[k] + y * y / D[k];
    if (newdist < maxdist) {
      if (k != 0) {
        --k;
        dist[k] = newdist;
        for (int r = path[static_cast<size_t>(k)]; r > k; --r)
          C(r, k) = C(r + 1, k) + (z[r] - zb[r]) * L(r, k);
        path[static_cast<size_t>(k)] = k;
        zb[k] = zs[k] + C(k + 1, k);
        z[k] = std::round(zb[k]);
        y = zb[k] - z[k];
        step[k] = sgn(y);
      } else {
        if (static_cast<int>(cand.size()) < m) {
          cand.push_back(z);
          norms.push_back(newdist);
        } else {
          const auto worst = std::max_element(norms.begin(), norms.end()) - norms.begin();
          cand[static_cast<size_t>(worst)] = z;
          norms[static_cast<size_t>(worst)] = newdist;
        }
        if (static_cast<int>(cand.size()) == m)
          maxdist = *std::max_element(norms.begin(), norms.end());
        z[0] += step[0];
        y = zb[0] - z[0];
        step[0] = -step[0] - sgn(step[0]);
      }
    } else {
      if (k == n - 1) break;
      ++k;
      z[k] += step[k];
      y = zb[k] - z[k];
      step[k] = -step[k] - sgn(step[k]);
      // Rows <= k of the lower columns are stale now. Where one already is, so are those below
      // it (a column is refreshed only after the one above it), hence the early stop.
      for (int i = k - 1; i >= 0 && path[static_cast<size_t>(i)] < k; --i) {
        path[static_cast<size_t>(i)] = k;
      }
    }
  }
  std::vector<size_t> order(cand.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return norms[a] < norms[b]; });
  SearchResult r;
  for (size_t i : order) {
    r.candidates.push_back(cand[i]);
    r.squared_norms.push_back(norms[i]);
  }
  return r;
}

}  // namespace

SearchResult integerSearch(const Eigen::VectorXd& a, const Eigen::MatrixXd& Q, int m) {
  const Decorrelation d = decorrelate(Q);
  // Shift by the rounded float first: integer translations commute with the search and keep
  // the numbers small.
  const Eigen::VectorXd a_int = a.array().round().matrix();
  const Eigen::VectorXd zs = d.toDecorrelated(a - a_int);
  SearchResult r = searchDecorrelated(d.ltdl.L, d.ltdl.D, zs, m);
  r.conditional_variances = d.ltdl.D;
  for (auto& c : r.candidates) c = d.fromDecorrelated(c).array().round().matrix() + a_int;
  return r;
}

double bootstrapSuccessRate(const Eigen::VectorXd& D) {
  double p = 1.0;
  for (int i = 0; i < D.size(); ++i) p *= std::erf(1.0 / (2.0 * std::sqrt(2.0 * D[i])));
  return p;
}

Eigen::MatrixXd ddAmbiguityCovariance(const Eigen::MatrixXd& P,
                                      const std::vector<std::pair<int, int>>& pairs) {
  const auto na = static_cast<long>(pairs.size());
  const auto p = [&P](int i, int j) { return i < 0 || j < 0 ? 0.0 : P(i, j); };
  Eigen::MatrixXd Q(na, na);
  for (long k = 0; k < na; ++k) {
    const auto [sk, rk] = pairs[static_cast<size_t>(k)];
    for (long l = 0; l <= k; ++l) {
      const auto [sl, rl] = pairs[static_cast<size_t>(l)];
      Q(k, l) = (p(sk, sl) - p(sk, rl)) - (p(rk, sl) - p(rk, rl));
      Q(l, k) = Q(k, l);
    }
  }
  return Q;
}

std::vector<int> lowestElevationFirst(const std::vector<double>& elevation) {
  std::vector<int> order(elevation.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    return elevation[static_cast<size_t>(i)] < elevation[static_cast<size_t>(j)];
  });
  return order;
}

AmbiguityFix resolveAmbiguities(const Eigen::VectorXd& a, const Eigen::MatrixXd& Q,
                                const std::vector<int>& drop_order, const LambdaOptions& options) {
  std::vector<int> keep(static_cast<size_t>(a.size()));
  std::iota(keep.begin(), keep.end(), 0);
  AmbiguityFix out;
  size_t next_drop = 0;
  while (static_cast<int>(keep.size()) >= std::max(options.min_fixed, 1)) {
    const int n = static_cast<int>(keep.size());
    Eigen::VectorXd as(n);
    Eigen::MatrixXd Qs(n, n);
    for (int i = 0; i < n; ++i) {
      as[i] = a[keep[static_cast<size_t>(i)]];
      for (int j = 0; j < n; ++j)
        Qs(i, j) = Q(keep[static_cast<size_t>(i)], keep[static_cast<size_t>(j)]);
    }
    const SearchResult r = integerSearch(as, Qs, 2);
    if (r.candidates.size() == 2) {
      out.ratio = r.squared_norms[1] / std::max(r.squared_norms[0], 1e-12);
      if (out.ratio >= options.ratio_threshold) {
        out.fixed = true;
        out.indices = keep;
        out.values = r.candidates[0];
        out.success_rate = bootstrapSuccessRate(r.conditional_variances);
        return out;
      }
    }
    // Partial AR: drop the next ambiguity in the caller's order that is still kept.
    while (next_drop < drop_order.size() &&
           std::find(keep.begin(), keep.end(), drop_order[next_drop]) == keep.end()) {
      ++next_drop;
    }
    if (next_drop >= drop_order.size()) break;
    keep.erase(std::find(keep.begin(), keep.end(), drop_order[next_drop]));
  }
  return out;
}

}  // namespace giocal
