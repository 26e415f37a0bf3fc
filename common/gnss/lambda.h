// LAMBDA integer ambiguity resolution (Teunissen 1995; de Jonge & Tiberius 1996): LtDL
// factorization, integer Gauss decorrelation (Z-transform), search with a shrinking ellipsoid
// (depth-first with zig-zag enumeration), the ratio test, partial ambiguity resolution and the
// bootstrapped success rate.
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace giocal {

/// Q = L^T diag(D) L with L unit lower triangular.
struct LtDL {
  Eigen::MatrixXd L;
  Eigen::VectorXd D;
};
/// Throws std::invalid_argument when Q is not positive definite.
LtDL factorLtDL(const Eigen::MatrixXd& Q);

/// One elementary step of a Z-transform: an integer Gauss transformation (column j of Z minus mu
/// times column i) or, with i = -1, a swap of columns j and j + 1.
struct ZStep {
  int i = -1, j = 0;
  double mu = 0.0;
};

/// The decorrelating transformation: z = Z^T a has covariance Z^T Q Z = L^T diag(D) L. Z is kept
/// as its steps: applying them to a vector costs one operation each where forming Z and its
/// inverse cost a column each (most of the decorrelation's time on a 40-ambiguity epoch).
struct Decorrelation {
  std::vector<ZStep> steps;  // Z = I times each step, in order: integer, unimodular
  LtDL ltdl;                 // of Z^T Q Z
  /// Z^T a.
  Eigen::VectorXd toDecorrelated(const Eigen::VectorXd& a) const;
  /// (Z^T)^-1 z: the steps undone in reverse order (exact for integer z).
  Eigen::VectorXd fromDecorrelated(const Eigen::VectorXd& z) const;
  /// Z itself, formed from the steps (for checks).
  Eigen::MatrixXd Z() const;
};
/// The reduction's two elementary operations on Q = L^T diag(D) L, each recorded as a step of Z:
/// an integer Gauss transformation making |L(i, j)| <= 1/2 (none when it rounds to 0), and the
/// swap of ambiguities j and j + 1 (del: the new D[j + 1], D[j] + L(j + 1, j)^2 D[j + 1]).
void integerGaussStep(Eigen::MatrixXd& L, std::vector<ZStep>& steps, int i, int j);
void swapAdjacent(Eigen::MatrixXd& L, Eigen::VectorXd& D, int j, double del,
                  std::vector<ZStep>& steps);
Decorrelation decorrelate(const Eigen::MatrixXd& Q);

/// The m integer vectors closest to `a` in the metric of Q (ascending squared norms).
struct SearchResult {
  std::vector<Eigen::VectorXd> candidates;
  std::vector<double> squared_norms;
  Eigen::VectorXd conditional_variances;  // D of the decorrelated ambiguities (success rate)
};
SearchResult integerSearch(const Eigen::VectorXd& a, const Eigen::MatrixXd& Q, int m = 2);

/// Bootstrapped success rate from the decorrelated conditional variances.
double bootstrapSuccessRate(const Eigen::VectorXd& D);

struct LambdaOptions {
  double ratio_threshold = 3.0;  // second best / best squared norm
  int min_fixed = 4;             // partial AR keeps at least this many
};

struct AmbiguityFix {
  bool fixed = false;
  std::vector<int> indices;  // which of the input ambiguities are fixed
  Eigen::VectorXd values;    // their integer values, in `indices` order
  double ratio = 0.0;
  double success_rate = 0.0;
};

/// Covariance of the DD ambiguities N(sat) - N(ref), one per (sat, ref) pair of indices into the
/// single-difference ambiguities' covariance P (what every estimator hands to LAMBDA); an index of
/// -1 is a known SD ambiguity (no variance). Read from P's entries, lower triangle computed and
/// mirrored: exactly symmetric.
Eigen::MatrixXd ddAmbiguityCovariance(const Eigen::MatrixXd& P,
                                      const std::vector<std::pair<int, int>>& pairs);

/// The partial-AR drop order: indices sorted by rising elevation (the lowest dropped first).
std::vector<int> lowestElevationFirst(const std::vector<double>& elevation);

/// Full resolution, then partial: drops ambiguities in `drop_order` (first = dropped first, for
/// example the lowest elevation) until the ratio test passes or fewer than min_fixed remain.
AmbiguityFix resolveAmbiguities(const Eigen::VectorXd& a, const Eigen::MatrixXd& Q,
                                const std::vector<int>& drop_order, const LambdaOptions& options);

}  // namespace giocal
