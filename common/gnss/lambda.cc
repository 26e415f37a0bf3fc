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

namespace {

// Integer Gauss transformation making |L(i, j)| <= 1/2. Z^T's inverse follows each elementary
// step (its inverse applied from the other side), exactly in integers, instead of a general
// inversion at the end (which cost as much as the decorrelation itself).
void gauss(Eigen::MatrixXd& L, Eigen::MatrixXd& Z, Eigen::MatrixXd& Zt_inv, int i, int j) {
  if (std::abs(L(i, j)) < 0.5) return;  // rounds to 0: most calls, without the rounding's cost
  const double mu = std::round(L(i, j));
  if (mu == 0.0) return;
  const int n = static_cast<int>(L.rows());
  for (int k = i; k < n; ++k) L(k, j) -= mu * L(k, i);
  Z.col(j) -= mu * Z.col(i);
  Zt_inv.col(i) += mu * Zt_inv.col(j);
}

// Swaps ambiguities j and j+1, updating L and D so that Q stays L^T D L.
void permute(Eigen::MatrixXd& L, Eigen::VectorXd& D, int j, double del, Eigen::MatrixXd& Z,
             Eigen::MatrixXd& Zt_inv) {
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
  Z.col(j).swap(Z.col(j + 1));
  Zt_inv.col(j).swap(Zt_inv.col(j + 1));
}

double sgn(double x) { return x <= 0.0 ? -1.0 : 1.0; }

}  // namespace

Decorrelation decorrelate(const Eigen::MatrixXd& Q) {
  const int n = static_cast<int>(Q.rows());
  Decorrelation d{Eigen::MatrixXd::Identity(n, n), Eigen::MatrixXd::Identity(n, n), factorLtDL(Q)};
  Eigen::MatrixXd& L = d.ltdl.L;
  Eigen::VectorXd& D = d.ltdl.D;
  int j = n - 2, k = n - 2;
  while (j >= 0) {
    if (j <= k) {
      for (int i = j + 1; i < n; ++i) gauss(L, d.Z, d.Zt_inv, i, j);
    }
    const double del = D[j] + L(j + 1, j) * L(j + 1, j) * D[j + 1];
    if (del + 1e-6 < D[j + 1]) {
      permute(L, D, j, del, d.Z, d.Zt_inv);
      k = j;
      j = n - 2;
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
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(n, n);
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
        for (int i = 0; i <= k; ++i) S(k, i) = S(k + 1, i) + (z[k + 1] - zb[k + 1]) * L(k + 1, i);
        zb[k] = zs[k] + S(k, k);
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
  const Eigen::VectorXd zs = d.Z.transpose() * (a - a_int);
  SearchResult r = searchDecorrelated(d.ltdl.L, d.ltdl.D, zs, m);
  r.conditional_variances = d.ltdl.D;
  for (auto& c : r.candidates) c = (d.Zt_inv * c).array().round().matrix() + a_int;
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
