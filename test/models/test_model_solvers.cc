// The shared models inside the two estimators' solvers: an iterated Kalman update and a Ceres
// solve of the same problem reach the same estimate; the odometer's yaw scale fitted from noisy
// yaw rates is unbiased.
#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <functional>
#include <memory>
#include <random>

#include "common/geodesy/wgs84.h"
#include "common/math/kalman_update.h"
#include "common/models/ambiguity_fix_model.h"
#include "common/models/dd_gnss_model.h"
#include "common/models/doppler_model.h"
#include "common/models/heading_change_model.h"
#include "common/models/imu_preintegration_model.h"
#include "common/models/measurement_rows.h"
#include "common/models/nhc_model.h"
#include "common/models/odometer_preintegration_model.h"
#include "common/models/planar_motion_projection.h"
#include "common/models/position_model.h"
#include "common/models/prior_model.h"
#include "common/models/standstill_projection.h"
#include "common/models/zupt_model.h"
#include "fgo/model_cost_function.h"
#include "fgo/right_quaternion_manifold.h"
#include "model_checks.h"

namespace giocal {
namespace {

TEST(MeasurementModels, IteratedFilterAndCeresReachTheSameEstimate) {
  // A prior on the blocks of the NHC model plus one constraint: the MAP estimate
  // from iterated Kalman updates built on linearize() equals Ceres' on ModelCostFunction. One fixed
  // problem (its own generator): plain Gauss-Newton has no line search to rescue any draw.
  std::mt19937 gen(31);
  const Vec3 gyro(0.02, -0.01, 0.4);
  auto odo = std::make_shared<NhcModel>(gyro, 0.005);
  const auto& blocks = odo->blocks();
  int n = 0;
  std::vector<int> offsets;
  Eigen::VectorXd mean_ambient(0);
  std::vector<Eigen::VectorXd> x0;
  for (const auto& b : blocks) {
    offsets.push_back(n);
    n += b.tangentSize();
    Eigen::VectorXd v = test::randomBlockValue(b, b.size == 1 ? 0.02 : 0.3, gen);
    if (b.key == state::kV) v = Vec3(0.2, 1.2, 0.0);
    x0.push_back(v);
    mean_ambient.conservativeResize(mean_ambient.size() + v.size());
    mean_ambient.tail(v.size()) = v;
  }
  Eigen::VectorXd sd(n);
  sd << 0.1, 0.1, 0.1, 0.05, 0.05, 0.05, 0.01, 0.01, 0.01, 0.2, 0.2, 0.2, 0.1, 0.1, 0.1;
  const Eigen::MatrixXd P0 = sd.cwiseAbs2().asDiagonal();
  auto prior = std::make_shared<PriorModel>(blocks, mean_ambient, P0);

  // Iterated EKF: relinearize the measurement at the current iterate (Gauss-Newton on the MAP).
  std::vector<Eigen::VectorXd> x = x0;
  int iterations = 0;
  for (; iterations < 500; ++iterations) {
    std::vector<BlockBinding> bind;
    for (size_t k = 0; k < x.size(); ++k) bind.push_back({x[k].data(), offsets[k]});
    MeasurementRows rows = linearize(*odo, bind, n);
    // IEKF form: the prior re-expressed in the tangent space of the iterate x (through the prior
    // residual's Jacobian), then one linear update at x.
    Eigen::VectorXd pr;
    std::vector<Eigen::MatrixXd> Jp;
    prior->evaluate(test::pointers(x).data(), pr, &Jp);
    Eigen::MatrixXd Jp_full(n, n);
    for (size_t k = 0; k < x.size(); ++k) Jp_full.middleCols(offsets[k], Jp[k].cols()) = Jp[k];
    const Eigen::MatrixXd Jp_inv = Jp_full.inverse();
    const Eigen::VectorXd dx_prior = Jp_inv * pr;  // x minus the prior mean, in x's tangent
    rows.residual -= rows.H * dx_prior;
    Eigen::MatrixXd P = Jp_inv * P0 * Jp_inv.transpose();
    const UpdateResult up = kalmanUpdate(P, rows, std::numeric_limits<double>::infinity());
    ASSERT_TRUE(up.accepted);
    const Eigen::VectorXd step = up.dx - dx_prior;
    for (size_t k = 0; k < x.size(); ++k) {
      x[k] = test::perturbBlock(blocks[k], x[k], step.segment(offsets[k], blocks[k].tangentSize()));
    }
    if (step.norm() < 1e-13) break;
  }

  // Ceres on the same two models.
  std::vector<Eigen::VectorXd> y = x0;
  ceres::Problem problem;
  std::vector<double*> ptrs;
  for (auto& v : y) ptrs.push_back(v.data());
  problem.AddResidualBlock(new ModelCostFunction(odo), nullptr, ptrs);
  problem.AddResidualBlock(new ModelCostFunction(prior), nullptr, ptrs);
  for (size_t k = 0; k < y.size(); ++k) {
    if (blocks[k].kind == BlockKind::kRotation) {
      problem.SetManifold(ptrs[k], new RightQuaternionManifold);
    }
  }
  ceres::Solver::Options options;
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-16;
  options.max_num_iterations = 100;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  ASSERT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();

  auto cost = [&](std::vector<Eigen::VectorXd>& v) {
    double c = 0;
    for (const std::shared_ptr<const MeasurementModel>& m :
         {std::shared_ptr<const MeasurementModel>(odo),
          std::shared_ptr<const MeasurementModel>(prior)}) {
      ModelCostFunction cf(m);
      Eigen::VectorXd res(m->residualSize());
      cf.Evaluate(test::pointers(v).data(), res.data(), nullptr);
      c += res.squaredNorm();
    }
    return c;
  };
  EXPECT_LT(iterations, 500) << "the iterated filter did not converge";
  EXPECT_NEAR(cost(x), cost(y), 1e-9 * cost(y));
  double moved = 0.0;
  for (size_t k = 0; k < x.size(); ++k) {
    const StateBlock& b = blocks[k];
    Eigen::VectorXd diff =
        b.kind == BlockKind::kRotation
            ? Eigen::VectorXd(boxMinus(quatFromWxyz(x[k].data()), quatFromWxyz(y[k].data())))
            : Eigen::VectorXd(x[k] - y[k]);
    EXPECT_LT(diff.norm(), 1e-8) << b.key.str();
    moved += (b.kind == BlockKind::kRotation ? 0.0 : (x[k] - x0[k]).norm());
  }
  EXPECT_GT(moved, 1e-3) << "the measurement must actually move the estimate";
  // The estimate explains the odometer sample better than the prior mean did (how much better
  // depends on the random prior's strength).
  Eigen::VectorXd r, r0;
  odo->evaluate(test::pointers(x).data(), r, nullptr);
  odo->evaluate(test::pointers(x0).data(), r0, nullptr);
  EXPECT_LT(r.norm(), 0.5 * r0.norm());
}

/// Odometer intervals of 1 s between exactly known poses (b = m): 20 % turning at 0.15 rad/s, the
/// rest straight, 1.5 m/s, yaw rate read at 50 Hz with 3 deg/s white noise, true s_w 0.04.
struct NoisyYawRateIntervals {
  static constexpr double kSw = 0.04;
  std::vector<std::shared_ptr<OdometerPreintegration>> pre;
  std::vector<Vec3> p_j;
  std::vector<Eigen::Quaterniond> q_j;

  explicit NoisyYawRateIntervals(std::uint64_t seed) {
    OdometerPreintegrationNoise noise;
    noise.yaw_rate_sigma = 3.0 * kDegToRad;
    std::mt19937_64 draws(seed);
    std::normal_distribution<double> n01(0.0, 1.0);
    for (int k = 0; k < 2000; ++k) {
      const double w = (k % 5 == 0 ? 0.15 : 0.0) / (1.0 + kSw);  // as read, noise-free
      OdometerPreintegration truth(noise, 0.0, kSw);
      auto measured = std::make_shared<OdometerPreintegration>(noise, 0.0, 0.0);
      for (int i = 0; i < 50; ++i) {
        truth.integrate(0.02, 1.5, w);
        measured->integrate(0.02, 1.5, w + noise.yaw_rate_sigma * n01(draws));
      }
      pre.push_back(measured);
      p_j.push_back(truth.deltaP_m(0.0, kSw));
      q_j.push_back(Eigen::Quaterniond(Eigen::AngleAxisd(truth.yaw(kSw), Vec3::UnitZ())));
    }
  }

  /// Gauss-Newton on s_w alone from 0; (estimate, sigma). frozen_weight: whiten with the
  /// covariance at the preintegration's linearization point instead of at the current s_w.
  std::pair<double, double> fitYawScale(bool frozen_weight) const {
    double s = 0.0, H = 0.0;
    for (int it = 0; it < 6; ++it) {
      double g = 0.0;
      H = 0.0;
      for (size_t k = 0; k < pre.size(); ++k) {
        const OdometerCalibration c{0.0, s, Vec3::Zero(), Eigen::Quaterniond::Identity()};
        Eigen::Matrix<double, 6, 1> r, J;
        if (frozen_weight) {
          const OdometerResidual raw =
              pre[k]->evaluate(Vec3::Zero(), Eigen::Quaterniond::Identity(), p_j[k], q_j[k], c);
          const Eigen::Matrix<double, 6, 6> L =
              Eigen::LLT<Eigen::Matrix<double, 6, 6>>(pre[k]->covariance()).matrixL();
          r = L.triangularView<Eigen::Lower>().solve(raw.r);
          J = L.triangularView<Eigen::Lower>().solve(raw.J_s_w);
        } else {
          const OdometerPreintegrationModel model(pre[k]);
          Eigen::VectorXd q_i(4), qj(4), q_bm(4);
          quatToWxyz(Eigen::Quaterniond::Identity(), q_i.data());
          quatToWxyz(q_j[k], qj.data());
          q_bm = q_i;
          const std::vector<Eigen::VectorXd> values{Eigen::Vector3d::Zero(),
                                                    q_i,
                                                    p_j[k],
                                                    qj,
                                                    Eigen::VectorXd::Zero(1),
                                                    Eigen::VectorXd::Constant(1, s),
                                                    Eigen::Vector3d::Zero(),
                                                    q_bm};
          Eigen::VectorXd rv;
          std::vector<Eigen::MatrixXd> Js;
          model.evaluate(test::pointers(values).data(), rv, &Js);
          r = rv;
          J = Js[5];
        }
        g += J.dot(r);
        H += J.dot(J);
      }
      s -= g / H;
    }
    return {s, 1.0 / std::sqrt(H)};
  }
};

TEST(OdometerPreintegrationModel, YawScaleFromNoisyYawRatesIsUnbiased) {
  // Errors in variables: the residual multiplies the noisy integral of the yaw rate by the
  // unknown (1 + s_w). With a fixed weight least squares shrinks the estimate by about
  // sigma^2 / E[(int w dt)^2] (here 0.18 / 14.8 deg^2: 1.2e-2, about 5 sigma); whitened at the
  // current scale, as the model is, the estimate is unbiased.
  for (std::uint64_t seed : {7u, 8u, 9u}) {
    const NoisyYawRateIntervals data(seed);
    const auto [s, sd] = data.fitYawScale(false);
    const auto [s_frozen, sd_frozen] = data.fitYawScale(true);
    std::printf("seed %d: s_w whitened %.4f +- %.4f, frozen weight %.4f +- %.4f (truth %.2f)\n",
                static_cast<int>(seed), s, sd, s_frozen, sd_frozen, NoisyYawRateIntervals::kSw);
    EXPECT_LT(std::abs(s - NoisyYawRateIntervals::kSw), 3.0 * sd) << seed;
    // The data can tell the two apart: the frozen weight is biased low by several sigma.
    EXPECT_LT(s_frozen - NoisyYawRateIntervals::kSw, -3.0 * sd_frozen) << seed;
  }
}

}  // namespace
}  // namespace giocal
