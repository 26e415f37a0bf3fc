#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <limits>
#include <memory>

#include "common/math/rotation.h"
#include "common/math/so3.h"
#include "common/math/whitening.h"
#include "common/models/prior_model.h"
#include "common/models/random_walk_model.h"
#include "fgo/sliding_window.h"

namespace giocal {
namespace {

// Test variables: x(k) and y(k), vectors of 3 at epoch k.
StateKey x(int k) { return atEpoch(state::kP, k); }
StateKey y(int k) { return atEpoch(state::kV, k); }
const StateKey kLonely = state::kPbg;

std::shared_ptr<PriorModel> prior(const StateKey& key, const Eigen::Vector3d& mean, double sigma) {
  return std::make_shared<PriorModel>(std::vector<StateBlock>{vectorBlock(key)}, mean,
                                      Eigen::Matrix3d::Identity() * sigma * sigma);
}

/// A chain x0 - x1 - x2 with priors at both ends: linear and Gaussian, so marginalizing x0 must
/// leave exactly the same estimate and covariance of x1 and x2.
SlidingWindow chain() {
  SlidingWindow w;
  for (int k = 0; k < 3; ++k) w.addVariable(vectorBlock(x(k)), Eigen::Vector3d::Zero());
  w.addFactor({prior(x(0), Eigen::Vector3d(1, 2, 3), 0.5), {x(0)}, 0.0, "p0"});
  w.addFactor({std::make_shared<RandomWalkModel>(state::kP, 3, 0.3), {x(0), x(1)}, 0.0, "rw"});
  w.addFactor({std::make_shared<RandomWalkModel>(state::kP, 3, 0.2), {x(1), x(2)}, 0.0, "rw"});
  w.addFactor({prior(x(2), Eigen::Vector3d(1.5, 1.0, 3.2), 0.4), {x(2)}, 0.0, "p2"});
  return w;
}

TEST(SlidingWindow, MarginalizationKeepsTheEstimateAndCovariance) {
  SlidingWindow full = chain();
  ASSERT_TRUE(full.solve(50, 1e-14).usable);
  const Eigen::MatrixXd C_full = full.covariance({x(1), x(2)});

  SlidingWindow w = chain();
  w.solve(50, 1e-14);
  w.marginalize({x(0)});
  EXPECT_FALSE(w.has(x(0)));
  ASSERT_EQ(w.factors().size(), 3u);  // marginal prior, rw x1-x2, prior x2
  // Move the estimate away and solve again: the marginal prior brings it back.
  w.value(x(1)) += Eigen::Vector3d(0.3, -0.2, 0.1);
  w.value(x(2)) -= Eigen::Vector3d(0.1, 0.1, 0.1);
  ASSERT_TRUE(w.solve(50, 1e-14).usable);
  EXPECT_LT((w.value(x(1)) - full.value(x(1))).norm(), 1e-6);  // solver precision
  EXPECT_LT((w.value(x(2)) - full.value(x(2))).norm(), 1e-6);
  EXPECT_LT((w.covariance({x(1), x(2)}) - C_full).norm(), 1e-10);
}

// A 50-sigma outlier on x0 that the robust (Huber) solve down-weights must not enter the marginal
// prior at full weight when x0 is marginalized: the kept estimate stays where the solve put it.
TEST(SlidingWindow, MarginalizationKeepsTheRobustWeightsOfTheSolve) {
  SlidingWindow w = chain();
  w.addFactor({prior(x(0), Eigen::Vector3d(26, 2, 3), 0.5), {x(0)}, 1.0, "outlier"});
  ASSERT_TRUE(w.solve(100, 1e-14).usable);
  const Eigen::Vector3d x1 = w.value(x(1)), x2 = w.value(x(2));
  SlidingWindow plain = chain();  // without the outlier
  ASSERT_TRUE(plain.solve(50, 1e-14).usable);
  EXPECT_LT(std::abs(x1.x() - plain.value(x(1)).x()), 1.0);  // down-weighted, not ignored
  w.marginalize({x(0)});
  ASSERT_TRUE(w.solve(100, 1e-14).usable);
  EXPECT_LT((w.value(x(1)) - x1).norm(), 1e-6);
  EXPECT_LT((w.value(x(2)) - x2).norm(), 1e-6);
}

// Marginalizing x0 that ties a weakly observed x1 (random walk of 30 m) and a strongly observed x2
// (1 um): the Schur complement's eigenvalues span 14 orders; judged on the Jacobi-scaled matrix,
// x1's weak information is kept instead of dropped as numerically zero.
TEST(SlidingWindow, MarginalizationKeepsWeakDirectionsNextToStrongOnes) {
  SlidingWindow w;
  for (int k = 0; k < 3; ++k) w.addVariable(vectorBlock(x(k)), Eigen::Vector3d::Zero());
  w.addFactor({prior(x(0), Eigen::Vector3d::Zero(), 1e-6), {x(0)}, 0.0, "p0"});
  w.addFactor({std::make_shared<RandomWalkModel>(state::kP, 3, 30.0), {x(0), x(1)}, 0.0, "weak"});
  w.addFactor({std::make_shared<RandomWalkModel>(state::kP, 3, 1e-6), {x(0), x(2)}, 0.0, "strong"});
  ASSERT_TRUE(w.solve(20, 1e-14).usable);
  const double var_x1 = w.covariance({x(1)})(0, 0);
  EXPECT_NEAR(var_x1, 900.0, 1e-3);
  w.marginalize({x(0)});
  const Eigen::MatrixXd C = w.covariance({x(1), x(2)});
  EXPECT_NEAR(C(0, 0), var_x1, 1e-3 * var_x1);
  EXPECT_NEAR(C(3, 3), 2e-12, 1e-14);
}

TEST(SlidingWindow, CovarianceIsTheInverseHessian) {
  // The chain is linear with the same information on each axis: per axis, H over (x0, x1, x2) is
  // tridiagonal from the priors (1/0.5^2, 1/0.4^2) and the random walks (1/0.3^2, 1/0.2^2).
  const SlidingWindow w = chain();
  const double p0 = 1 / 0.25, p2 = 1 / 0.16, r01 = 1 / 0.09, r12 = 1 / 0.04;
  Eigen::Matrix3d H;
  H << p0 + r01, -r01, 0, -r01, r01 + r12, -r12, 0, -r12, r12 + p2;
  const Eigen::Matrix3d P = H.inverse();
  const Eigen::MatrixXd C = w.covariance({x(2), x(0), x(1)});  // any order of the names
  const int at[3] = {1, 2, 0};                                 // x0, x1, x2 in C
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) {
          const double expected = a == b ? P(i, j) : 0.0;
          EXPECT_NEAR(C(3 * at[i] + a, 3 * at[j] + b), expected, 1e-12);
        }
      }
    }
  }
}

TEST(SlidingWindow, GroupsOfRowsWhitenedApartGiveTheSameSolveAsOneDenseWhitener) {
  // A factor whose covariance has two independent groups of rows, each on its own variable (as
  // a DD factor's groups on their satellites' ambiguities), with a Huber loss that is active:
  // whitened group by group (the blocked path) and with a dense square root of the same
  // information (a rotation times the whitener), the solves and covariances are the same.
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(6, 6);
  C.topLeftCorner<3, 3>() << 0.04, 0.01, 0.0, 0.01, 0.09, 0.02, 0.0, 0.02, 0.05;
  C.bottomRightCorner<3, 3>() << 0.02, -0.005, 0.0, -0.005, 0.03, 0.0, 0.0, 0.0, 0.01;
  Eigen::VectorXd mean(6);
  mean << 1, 2, 3, -1, 0.5, 4;
  const auto grouped = std::make_shared<PriorModel>(
      std::vector<StateBlock>{vectorBlock(x(0)), vectorBlock(x(1))}, mean, C);
  auto window = [&](bool dense) {
    SlidingWindow w = chain();
    Factor f{grouped, {x(0), x(1)}, 1.0, "grouped"};
    if (dense) {
      const Eigen::MatrixXd S = whitener(C, "grouped");
      const Eigen::MatrixXd Q =
          Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
      Eigen::MatrixXd R6 = Eigen::MatrixXd::Identity(6, 6);
      R6.block<3, 3>(1, 1) = Q;  // mixes the two groups' rows
      f.sqrt_info = std::make_shared<const Eigen::MatrixXd>(R6 * S);
    }
    w.addFactor(f);
    return w;
  };
  SlidingWindow blocked = window(false), dense = window(true);
  ASSERT_TRUE(blocked.solve(50, 1e-14).usable);
  ASSERT_TRUE(dense.solve(50, 1e-14).usable);
  for (int k = 0; k < 3; ++k) EXPECT_LT((blocked.value(x(k)) - dense.value(x(k))).norm(), 1e-9);
  const std::vector<StateKey> all{x(0), x(1), x(2)};
  const Eigen::MatrixXd Cb = blocked.covariance(all), Cd = dense.covariance(all);
  EXPECT_LT((Cb - Cd).norm(), 1e-10 * Cd.norm());
}

TEST(SlidingWindow, AnUnobservedDirectionHasAnInfiniteVarianceAndTheObservedPartItsOwn) {
  // Two variables tied only to each other: their common offset is unobserved, so the Hessian is
  // singular. Their variances are infinite (the pseudo-inverse's 0 read as perfectly known); the
  // observed difference keeps its sigma, and a variable with a prior stays finite.
  SlidingWindow w;
  w.addVariable(vectorBlock(x(0)), Eigen::Vector3d::Zero());
  w.addVariable(vectorBlock(x(1)), Eigen::Vector3d::Zero());
  w.addFactor({std::make_shared<RandomWalkModel>(state::kP, 3, 0.3), {x(0), x(1)}, 0.0, "rw"});
  w.addVariable(vectorBlock(y(0)), Eigen::Vector3d::Zero());
  w.addFactor({prior(y(0), Eigen::Vector3d::Zero(), 2.0), {y(0)}, 0.0, "py"});
  const Eigen::MatrixXd C = w.covariance({x(0), x(1), y(0)});
  for (int i = 0; i < 6; ++i) EXPECT_EQ(C(i, i), std::numeric_limits<double>::infinity()) << i;
  EXPECT_NEAR(C(6, 6), 4.0, 1e-9);
  Eigen::MatrixXd D(3, 6);
  D << -Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Identity();
  // Along the observed difference: var(b - a) = 0.3^2 along each axis.
  const Eigen::MatrixXd Cd = w.covarianceAlong({x(0), x(1)}, D.transpose());
  EXPECT_NEAR((Cd - 0.09 * Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-9);
}

TEST(SlidingWindow, AStiffChainMovesInOneSolve) {
  // The scale factors' shape: one value per epoch, tied by a nearly rigid random walk (sigma
  // 1e-5), seen weakly (sigma 0.1 per epoch) next to precise, already-satisfied residuals. The
  // least-squares solution is linear (x = 1 everywhere) and Gauss-Newton reaches it in one step;
  // Levenberg-Marquardt from Ceres' default trust region (1e4) barely moved it in 10 iterations,
  // which froze the factor graph's s_w near the initial guess (docs/results.md).
  SlidingWindow w;
  for (int k = 0; k < 5; ++k) {
    w.addVariable(vectorBlock(x(k)), Eigen::Vector3d::Zero());
    w.addVariable(vectorBlock(y(k)), Eigen::Vector3d::Zero());
    w.addFactor({prior(x(k), Eigen::Vector3d::Ones(), 0.1), {x(k)}, 0.0, "weak"});
    w.addFactor({prior(y(k), Eigen::Vector3d::Zero(), 1e-3), {y(k)}, 0.0, "precise"});
    if (k > 0) {
      w.addFactor(
          {std::make_shared<RandomWalkModel>(state::kP, 3, 1e-5), {x(k - 1), x(k)}, 0.0, "rw"});
    }
  }
  ASSERT_TRUE(w.solve(10).usable);
  for (int k = 0; k < 5; ++k) {
    EXPECT_LT((w.value(x(k)) - Eigen::Vector3d::Ones()).norm(), 1e-3) << k;
  }
}

TEST(SlidingWindow, AVariableThatLosesAllItsFactorsIsNoFailure) {
  SlidingWindow w = chain();
  w.addVariable(vectorBlock(kLonely), Eigen::Vector3d(5, 5, 5));
  w.addFactor({prior(kLonely, Eigen::Vector3d(5, 5, 5), 1.0), {kLonely}, 0.0, "only"});
  EXPECT_EQ(w.removeFactors("only"), 1);
  EXPECT_TRUE(w.solve(10).usable);  // not in the problem, no error
  EXPECT_EQ(w.value(kLonely), Eigen::Vector3d(5, 5, 5));
  // Marginalizing a variable without factors just drops it.
  w.marginalize({kLonely});
  EXPECT_FALSE(w.has(kLonely));
  EXPECT_TRUE(w.solve(10).usable);
}

TEST(SlidingWindow, AWindowOfTheLastShapeReusesItsAnalysisAndSolvesAsAFreshOne) {
  // A chain that slides an epoch at a time; epochs 6 and 10 also tie x(k) to x(k-2), which
  // changes the window's shape for a while. After each slide the window must give what a window
  // built afresh from the same variables and factors gives, whether or not its analysis was reused.
  SlidingWindow w;
  w.addVariable(vectorBlock(x(0)), Eigen::Vector3d::Zero());
  w.addFactor({prior(x(0), Eigen::Vector3d(1, 2, 3), 0.5), {x(0)}, 0.0, "p"});
  int solves = 0;
  for (int k = 1; k < 14; ++k) {
    w.addVariable(vectorBlock(x(k)), w.value(x(k - 1)));
    w.addFactor(
        {std::make_shared<RandomWalkModel>(state::kP, 3, 0.3), {x(k - 1), x(k)}, 0.0, "rw"});
    const Eigen::Vector3d seen(1.0 + 0.1 * k, 2.0 - 0.05 * k * k, 3.0 + std::sin(k));
    w.addFactor({prior(x(k), seen, 0.4), {x(k)}, 0.0, "p"});
    if (k == 6 || k == 10) {
      w.addFactor(
          {std::make_shared<RandomWalkModel>(state::kP, 3, 0.5), {x(k - 2), x(k)}, 0.0, "tie"});
    }
    if (k >= 3) w.marginalize({x(k - 3)});
    ASSERT_TRUE(w.solve(20, 1e-12).usable);
    ++solves;
    const std::vector<StateKey> vars = w.estimatedVariables();
    SlidingWindow fresh;
    for (const StateKey& n : vars) fresh.addVariable(w.block(n), w.value(n));
    for (const Factor& f : w.factors()) fresh.addFactor(f);
    const Eigen::MatrixXd C = w.covariance(vars);
    EXPECT_LT((fresh.covariance(vars) - C).norm(), 1e-12 * C.norm()) << "epoch " << k;
    EXPECT_EQ(fresh.symbolicAnalyses(), 1);
  }
  // Reused in the steady state, analysed anew as the window fills and when a tie comes or goes.
  EXPECT_LT(w.symbolicAnalyses(), solves);
  EXPECT_GE(w.symbolicAnalyses(), 6);
}

/// A point of a rigid body seen at y: residual = R(q) a + p - y, nonlinear in the rotation.
class PointModel : public MeasurementModel {
 public:
  PointModel(Eigen::Vector3d a, Eigen::Vector3d y, double sigma)
      : a_(std::move(a)), y_(std::move(y)), sigma_(sigma) {}
  std::string name() const override { return "point"; }
  const std::vector<StateBlock>& blocks() const override { return blocks_; }
  int residualSize() const override { return 3; }
  void evaluate(const double* const* params, Eigen::VectorXd& r,
                std::vector<Eigen::MatrixXd>* J) const override {
    const Eigen::Matrix3d R = quatFromWxyz(params[0]).toRotationMatrix();
    r = R * a_ + Eigen::Map<const Eigen::Vector3d>(params[1]) - y_;
    if (J) *J = {-R * skew(a_), Eigen::Matrix3d::Identity()};
  }
  Eigen::MatrixXd covariance() const override {
    return Eigen::Matrix3d::Identity() * sigma_ * sigma_;
  }

 private:
  std::vector<StateBlock> blocks_{rotationBlock(state::kQ), vectorBlock(state::kP)};
  Eigen::Vector3d a_, y_;
  double sigma_;
};

/// A body turned by (0.4, -0.3, 1.2) rad and moved by (1, 2, 3), seen at six points, one of them
/// 50 sigma off (down-weighted by its Huber loss), p.z held at its true value.
SlidingWindow bodyWindow(WindowSolver solver) {
  SlidingWindow w;
  w.setSolver(solver);
  Eigen::Vector4d q0;
  quatToWxyz(Quat::Identity(), q0.data());
  w.addVariable(rotationBlock(state::kQ), q0);
  w.addVariable(vectorBlock(state::kP), Eigen::Vector3d(0.0, 0.0, 3.0));
  w.holdComponents(state::kP, {2});
  const Eigen::Matrix3d R = rotationFromRpy(Eigen::Vector3d(0.4, -0.3, 1.2));
  const Eigen::Vector3d t(1, 2, 3);
  const Eigen::Vector3d a[6] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {-1, 0, 2}, {0, -2, 1}};
  for (int k = 0; k < 6; ++k) {
    const Eigen::Vector3d y =
        R * a[k] + t + (k == 5 ? Eigen::Vector3d(0.5, 0, 0) : Eigen::Vector3d::Zero());
    w.addFactor(
        {std::make_shared<PointModel>(a[k], y, 0.01), {state::kQ, state::kP}, 3.0, "point"});
  }
  w.addFactor({prior(state::kP, Eigen::Vector3d(1, 2, 3), 1.0), {state::kP}, 0.0, "prior"});
  return w;
}

TEST(SlidingWindow, OwnGaussNewtonAgreesWithCeres) {
  // Rotations on the right-perturbation manifold, a held component and a robust loss: the own
  // solver must reach Ceres' minimum and its covariance.
  SlidingWindow own = bodyWindow(WindowSolver::kGaussNewton);
  SlidingWindow ceres = bodyWindow(WindowSolver::kCeres);
  const SlidingWindow::SolveReport a = own.solve(50, 1e-14);
  const SlidingWindow::SolveReport b = ceres.solve(50, 1e-14);
  ASSERT_TRUE(a.usable);
  ASSERT_TRUE(b.usable);
  EXPECT_NEAR(a.final_cost, b.final_cost, 1e-9 * b.final_cost);
  EXPECT_EQ(own.value(state::kP)[2], 3.0);  // held
  EXPECT_EQ(ceres.value(state::kP)[2], 3.0);
  EXPECT_LT((own.value(state::kP) - ceres.value(state::kP)).norm(), 1e-9);
  EXPECT_LT(boxMinus(quatFromWxyz(own.value(state::kQ).data()),
                     quatFromWxyz(ceres.value(state::kQ).data()))
                .norm(),
            1e-9);
  // Near the truth despite the outlier (without the Huber loss it pulls p.x 0.11 m off).
  EXPECT_LT(std::abs(own.value(state::kP)[0] - 1.0), 0.02);
  EXPECT_NEAR(own.value(state::kQ).norm(), 1.0, 1e-12);
  // The covariance after the own solve reuses its last factorization: the same as one made
  // afresh at the solution.
  const Eigen::MatrixXd C = own.covariance({state::kQ, state::kP});
  SlidingWindow fresh = bodyWindow(WindowSolver::kGaussNewton);
  fresh.value(state::kQ) = own.value(state::kQ);
  fresh.value(state::kP) = own.value(state::kP);
  EXPECT_LT((fresh.covariance({state::kQ, state::kP}) - C).norm(), 1e-12 * C.norm());
  EXPECT_LT((ceres.covariance({state::kQ, state::kP}) - C).norm(), 1e-6 * C.norm());
}

}  // namespace
}  // namespace giocal
