#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "common/gnss/lambda.h"

namespace giocal {
namespace {

// A GNSS-like ambiguity covariance: strongly correlated (geometry shared by all) and
// ill-conditioned.
Eigen::MatrixXd randomCovariance(std::mt19937& rng, int n) {
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::MatrixXd A(n + 3, n);
  for (int i = 0; i < A.rows(); ++i)
    for (int j = 0; j < n; ++j) A(i, j) = g(rng);
  Eigen::MatrixXd geometry = Eigen::MatrixXd::Ones(n, n) * 4.0;
  return 0.05 * A.transpose() * A / n + geometry + 0.01 * Eigen::MatrixXd::Identity(n, n);
}

double qnorm(const Eigen::VectorXd& a, const Eigen::MatrixXd& Q, const Eigen::VectorXd& z) {
  return (a - z).dot(Q.ldlt().solve(a - z));
}

// Every integer vector within +-r of round(a): the two smallest squared norms.
std::pair<Eigen::VectorXd, double> bruteForce(const Eigen::VectorXd& a, const Eigen::MatrixXd& Q,
                                              int r, double& second) {
  const int n = static_cast<int>(a.size());
  Eigen::VectorXd base = a.array().round().matrix(), z(n), best(n);
  double best_norm = 1e300;
  second = 1e300;
  std::vector<int> off(static_cast<size_t>(n), -r);
  while (true) {
    for (int i = 0; i < n; ++i) z[i] = base[i] + off[static_cast<size_t>(i)];
    const double d = qnorm(a, Q, z);
    if (d < best_norm) {
      second = best_norm;
      best_norm = d;
      best = z;
    } else if (d < second) {
      second = d;
    }
    int i = 0;
    while (i < n && ++off[static_cast<size_t>(i)] > r) off[static_cast<size_t>(i++)] = -r;
    if (i == n) break;
  }
  return {best, best_norm};
}

TEST(Lambda, LtDLReconstructsTheCovariance) {
  std::mt19937 rng(1);
  for (int n = 1; n <= 8; ++n) {
    const Eigen::MatrixXd Q = randomCovariance(rng, n);
    const LtDL f = factorLtDL(Q);
    EXPECT_LT((f.L.transpose() * f.D.asDiagonal() * f.L - Q).norm(), 1e-10 * Q.norm());
    for (int i = 0; i < n; ++i) EXPECT_DOUBLE_EQ(f.L(i, i), 1.0);
    EXPECT_LT(f.L.triangularView<Eigen::StrictlyUpper>().toDenseMatrix().norm(), 1e-15);
  }
  EXPECT_THROW(factorLtDL(-Eigen::MatrixXd::Identity(2, 2)), std::invalid_argument);
}

TEST(Lambda, ZTransformIsUnimodularAndDecorrelates) {
  std::mt19937 rng(2);
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 2 + trial % 9;
    const Eigen::MatrixXd Q = randomCovariance(rng, n);
    const Decorrelation d = decorrelate(Q);
    const Eigen::MatrixXd Z = d.Z();
    // Integer entries, determinant +-1.
    EXPECT_LT((Z - Z.array().round().matrix()).norm(), 1e-12);
    EXPECT_NEAR(std::abs(Z.determinant()), 1.0, 1e-6);
    // The steps undone give the inverse of Z^T, integer and exact; done, Z^T itself.
    Eigen::MatrixXd Zt_inv(n, n);
    for (int k = 0; k < n; ++k) {
      Zt_inv.col(k) = d.fromDecorrelated(Eigen::VectorXd::Unit(n, k));
      EXPECT_EQ((d.toDecorrelated(Eigen::VectorXd::Unit(n, k)) - Z.transpose().col(k)).norm(), 0.0);
    }
    EXPECT_LT((Zt_inv - Zt_inv.array().round().matrix()).norm(), 1e-12);
    EXPECT_EQ((Z.transpose() * Zt_inv - Eigen::MatrixXd::Identity(n, n)).norm(), 0.0);
    const Eigen::VectorXd a = Eigen::VectorXd::LinSpaced(n, -3.3, 4.1);
    EXPECT_LT((d.toDecorrelated(a) - Z.transpose() * a).norm(), 1e-12 * (1.0 + Z.norm()));
    const Eigen::MatrixXd Qz = Z.transpose() * Q * Z;
    EXPECT_LT((d.ltdl.L.transpose() * d.ltdl.D.asDiagonal() * d.ltdl.L - Qz).norm(),
              1e-8 * Qz.norm());
    // Conditioning improves (the geometry-dominated Q has a condition number in the hundreds).
    auto cond = [](const Eigen::MatrixXd& M) {
      const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M).eigenvalues();
      return ev.maxCoeff() / ev.minCoeff();
    };
    EXPECT_LT(cond(Qz), cond(Q)) << "n " << n;
  }
}

// The classic reduction (de Jonge & Tiberius 1996, as RTKLIB's LD/reduction): after every swap
// it starts its walk again at n - 2: the test's oracle for decorrelate()'s loop, which resumes at
// j + 1 (the elementary steps are the library's).
Decorrelation classicReduction(const Eigen::MatrixXd& Q) {
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
      j = n - 2;
    } else {
      --j;
    }
  }
  return d;
}

TEST(Lambda, ResumingAfterASwapTakesTheClassicReductionsSteps) {
  // decorrelate() skips the classic walk's re-tests above a swap; the steps, L and D must be
  // the classic ones exactly, on problems that swap many times (40 ambiguities).
  std::mt19937 rng(7);
  size_t swaps = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 2 + (trial * 7) % 39;
    const Eigen::MatrixXd Q = randomCovariance(rng, n);
    const Decorrelation fast = decorrelate(Q), classic = classicReduction(Q);
    ASSERT_EQ(fast.steps.size(), classic.steps.size()) << "n " << n;
    for (size_t s = 0; s < fast.steps.size(); ++s) {
      EXPECT_EQ(fast.steps[s].i, classic.steps[s].i);
      EXPECT_EQ(fast.steps[s].j, classic.steps[s].j);
      EXPECT_EQ(fast.steps[s].mu, classic.steps[s].mu);
      swaps += classic.steps[s].i < 0;
    }
    EXPECT_EQ((fast.ltdl.L - classic.ltdl.L).norm(), 0.0);
    EXPECT_EQ((fast.ltdl.D - classic.ltdl.D).norm(), 0.0);
  }
  EXPECT_GT(swaps, 200u);
}

TEST(Lambda, SearchEqualsBruteForceOnRandomProblems) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-20.0, 20.0);
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 2 + trial % 3;  // 2..4: brute force over +-4 stays small
    const Eigen::MatrixXd Q = 0.05 * randomCovariance(rng, n);
    Eigen::VectorXd a(n);
    for (int i = 0; i < n; ++i) a[i] = u(rng);
    double second = 0.0;
    const auto [best, best_norm] = bruteForce(a, Q, 4, second);
    const SearchResult r = integerSearch(a, Q, 2);
    ASSERT_EQ(r.candidates.size(), 2u);
    EXPECT_LT((r.candidates[0] - best).norm(), 1e-9) << "trial " << trial;
    EXPECT_NEAR(r.squared_norms[0], best_norm, 1e-6 * (1 + best_norm));
    EXPECT_NEAR(r.squared_norms[1], second, 1e-6 * (1 + second));
    EXPECT_NEAR(qnorm(a, Q, r.candidates[1]), r.squared_norms[1], 1e-6 * (1 + second));
  }
}

// At the sizes of a multi-system epoch (12-40 ambiguities, floats far from integers so that the
// search backtracks) brute force is out of reach: the norms the search reports must be those of
// the vectors it returns (a stale partial sum in the search breaks this: checked by leaving out
// the search's staleness marks), the two must differ, and no vector one step away from the best
// may be better than the second.
TEST(Lambda, SearchOnFortyAmbiguitiesReportsTrueNormsAndIsLocallyOptimal) {
  std::mt19937 rng(4);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    const int n = 12 + 28 * trial / 11;
    const Eigen::MatrixXd Q = 0.05 * randomCovariance(rng, n);
    Eigen::VectorXd a(n);
    for (int i = 0; i < n; ++i) a[i] = 30.0 * g(rng);
    const SearchResult r = integerSearch(a, Q, 2);
    ASSERT_EQ(r.candidates.size(), 2u);
    EXPECT_GT((r.candidates[0] - r.candidates[1]).norm(), 0.5);
    for (int c = 0; c < 2; ++c) {
      const double q = qnorm(a, Q, r.candidates[static_cast<size_t>(c)]);
      EXPECT_NEAR(r.squared_norms[static_cast<size_t>(c)], q, 1e-6 * (1.0 + q)) << n;
    }
    for (int i = 0; i < n; ++i) {
      for (const double s : {-1.0, 1.0}) {
        Eigen::VectorXd z = r.candidates[0];
        z[i] += s;
        EXPECT_GE(qnorm(a, Q, z), r.squared_norms[1] * (1.0 - 1e-9)) << n << " " << i;
      }
    }
  }
}

TEST(Lambda, PublishedThreeDimensionalExample) {
  // de Jonge & Tiberius (1996), the LAMBDA method's 3-D example: float ambiguities and covariance.
  Eigen::Matrix3d Q;
  Q << 6.290, 5.978, 0.544, 5.978, 6.292, 2.340, 0.544, 2.340, 6.288;
  const Eigen::Vector3d a(5.45, 3.10, 2.97);
  const SearchResult r = integerSearch(a, Q, 2);
  EXPECT_EQ(r.candidates[0], Eigen::Vector3d(5, 3, 4));
  double second = 0.0;
  const auto [best, best_norm] = bruteForce(a, Q, 6, second);
  EXPECT_EQ(best, Eigen::Vector3d(5, 3, 4));
  EXPECT_NEAR(r.squared_norms[0], best_norm, 1e-9);
  EXPECT_NEAR(r.squared_norms[1], second, 1e-9);
}

TEST(Lambda, RatioTestAndPartialResolution) {
  // Six precise ambiguities near integers, the last two noisy: full AR fails the ratio test,
  // partial AR dropping the noisy ones first fixes the remaining four to the truth.
  Eigen::VectorXd truth(6);
  truth << 3, -7, 12, 0, 5, -2;
  Eigen::VectorXd a = truth;
  a += (Eigen::VectorXd(6) << 0.02, -0.03, 0.01, 0.02, 0.48, -0.45).finished();
  Eigen::MatrixXd Q = Eigen::MatrixXd::Identity(6, 6) * 0.003 + Eigen::MatrixXd::Ones(6, 6) * 0.001;
  Q(4, 4) = Q(5, 5) = 1.0;
  LambdaOptions opt;
  const AmbiguityFix full = resolveAmbiguities(a, Q, {}, opt);
  EXPECT_FALSE(full.fixed);
  const AmbiguityFix partial = resolveAmbiguities(a, Q, {5, 4, 3, 2}, opt);
  ASSERT_TRUE(partial.fixed);
  EXPECT_EQ(partial.indices, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(partial.values, truth.head(4));
  EXPECT_GE(partial.ratio, 3.0);
  EXPECT_GT(partial.success_rate, 0.999);
  // No more than min_fixed are dropped.
  opt.min_fixed = 5;
  EXPECT_FALSE(resolveAmbiguities(a, Q, {5, 4, 3, 2}, opt).fixed);
}

TEST(Lambda, DdAmbiguityCovarianceIsADPDtAndAKnownAmbiguityHasNoVariance) {
  std::mt19937 rng(21);
  std::normal_distribution<double> g;
  Eigen::MatrixXd A(4, 4);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) A(i, j) = g(rng);
  const Eigen::MatrixXd P = A * A.transpose() + Eigen::MatrixXd::Identity(4, 4);
  // Pairs (sat, ref) of SD indices; -1 is a known SD ambiguity.
  const std::vector<std::pair<int, int>> pairs{{1, 0}, {2, 0}, {3, -1}, {-1, 2}};
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(4, 4);
  for (int k = 0; k < 4; ++k) {
    if (pairs[size_t(k)].first >= 0) D(k, pairs[size_t(k)].first) += 1.0;
    if (pairs[size_t(k)].second >= 0) D(k, pairs[size_t(k)].second) -= 1.0;
  }
  const Eigen::MatrixXd Q = ddAmbiguityCovariance(P, pairs);
  EXPECT_LT((Q - D * P * D.transpose()).norm(), 1e-12);
  EXPECT_EQ(Q, Q.transpose());
  EXPECT_EQ(ddAmbiguityCovariance(P, {{-1, -1}})(0, 0), 0.0);
}

TEST(Lambda, BootstrapSuccessRate) {
  // One ambiguity with sigma 0.1 cycle: P = 2 Phi(0.5 / 0.1) - 1.
  EXPECT_NEAR(bootstrapSuccessRate(Eigen::VectorXd::Constant(1, 0.01)),
              std::erf(5.0 / std::sqrt(2.0)), 1e-12);
  EXPECT_LT(bootstrapSuccessRate(Eigen::VectorXd::Constant(3, 1.0)), 0.1);
}

}  // namespace
}  // namespace giocal
