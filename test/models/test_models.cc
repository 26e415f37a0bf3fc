#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <functional>
#include <memory>
#include <random>

#include "common/geodesy/wgs84.h"
#include "common/math/kalman_update.h"
#include "common/math/whitening.h"
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
#include "common/models/random_walk_model.h"
#include "common/models/standstill_projection.h"
#include "common/models/tdcp_model.h"
#include "common/models/zupt_model.h"
#include "fgo/model_cost_function.h"
#include "fgo/right_quaternion_manifold.h"
#include "model_checks.h"

namespace giocal {
namespace {

std::mt19937 rng(31);

std::vector<Eigen::VectorXd> randomValues(const MeasurementModel& m) {
  std::vector<Eigen::VectorXd> values;
  for (const auto& b : m.blocks()) {
    // Scale factors stay small, biases small, everything else of ground-robot magnitude.
    double scale = 1.0;
    const Quantity q = b.key.what;
    if (q == Quantity::kSpeedScale || q == Quantity::kYawRateScale) scale = 0.05;
    if (q == Quantity::kAccelBias || q == Quantity::kGyroBias) scale = 0.02;
    if (q == Quantity::kOdometerDelay) scale = 0.05;
    if (q == Quantity::kGyroTilt) scale = 0.01;
    values.push_back(test::randomBlockValue(b, scale, rng));
  }
  return values;
}

std::vector<std::shared_ptr<MeasurementModel>> allModels() {
  const LocalFrame frame(ecefFromGeodetic({0.6, 2.4, 30}));
  auto imu = std::make_shared<ImuPreintegration>(ImuNoise{}, frame.gravity_n(), frame.omega_ie_n(),
                                                 Vec3(0.01, 0, 0), Vec3(0, 0.001, 0));
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 30; ++k) {
    imu->integrate(0.01, Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), 9.8 + u(rng)));
  }
  auto odo = std::make_shared<OdometerPreintegration>(OdometerPreintegrationNoise{}, 0.01, -0.01);
  for (int k = 0; k < 30; ++k) odo->integrate(0.02, 1.0 + 0.3 * u(rng), 0.5 * u(rng));
  PoseRates rates;  // the delay's Jacobian is not zero
  rates.v_n_i = Vec3(1.0, -0.3, 0.1);
  rates.w_b_i = Vec3(0.1, 0.2, -0.5);
  rates.v_n_j = Vec3(-0.7, 1.2, 0.0);
  rates.w_b_j = Vec3(-0.1, 0.05, 0.4);
  const std::vector<StateBlock> prior_blocks{vectorBlock(state::kSv, 1), vectorBlock(state::kPbm),
                                             rotationBlock(state::kQbm)};
  Eigen::VectorXd mean(8);
  mean << 0.01, 0.1, 0.2, 0.3, 1, 0, 0, 0;
  // Double differences: five satellites 20,000 km away above the horizon, a base 4 km off.
  std::vector<SdGeometry> geo;
  const Eigen::Vector3d base_e = frame.ecefFromEnu({3000, 2600, 5});
  for (int k = 0; k < 5; ++k) {
    const double az = 1.2 * k, el = 0.3 + 0.25 * k;
    const Eigen::Vector3d dir(std::cos(el) * std::sin(az), std::cos(el) * std::cos(az),
                              std::sin(el));
    SdGeometry g;
    g.sat = SatId{GnssSystem::kGps, 3 + k};
    g.sat_at_rover_e = frame.ecefFromEnu(2.0e7 * dir);
    g.base_range = (g.sat_at_rover_e - base_e).norm();
    g.el = el;
    geo.push_back(g);
  }
  std::vector<DdObservation> dd;
  for (int k = 1; k < 5; ++k) {
    for (bool phase : {true, false}) {
      DdObservation o;
      o.sat = geo[static_cast<size_t>(k)].sat;
      o.ref = geo[0].sat;
      o.phase = phase;
      o.lambda = 0.19;
      o.sat_index = k;
      o.ref_index = 0;
      o.value = 1000.0 * k;
      dd.push_back(o);
    }
  }
  std::vector<std::pair<double, double>> var(5, {0.18, 1.8e-5});
  // Doppler: the same five lines of sight, satellites moving at 3 km/s.
  std::vector<DopplerObservation> dop;
  for (const SdGeometry& g : geo) {
    DopplerObservation o;
    o.sat = g.sat;
    o.los_e = (g.sat_at_rover_e - frame.origin_e()).normalized();
    o.satellite_term = 800.0 * o.los_e.x();
    o.range_rate = 500.0;
    o.variance = 0.09;
    dop.push_back(o);
  }
  // Time-differenced phase: the same satellites a second later, 3.9 km along their orbits.
  TdcpPair pair;
  pair.t0 = 100.0;
  pair.t1 = 101.0;  // the drift's displacement is v_tdcp (t1 - t0)
  for (size_t k = 0; k < geo.size(); ++k) {
    TdcpSignal g;
    g.sat = geo[k].sat;
    g.lambda = 0.19;
    g.sat0_e = geo[k].sat_at_rover_e;
    g.sat1_e = g.sat0_e + 3900.0 * Eigen::Vector3d(0.3, -0.8, 0.5).normalized();
    g.sat_clock_change_m = 0.001 * static_cast<double>(k);
    g.phase_change_m = 300.0 * static_cast<double>(k);
    g.variance = 2e-5 * static_cast<double>(k + 1);
    g.el = geo[k].el;
    pair.signals.push_back(g);
    if (k > 0) pair.rows.push_back({static_cast<int>(k), 0});
  }
  const auto n = [](int prn) { return ambiguityKey(SatId{GnssSystem::kGps, prn}, '1'); };
  const std::vector<DdAmbiguityFix> fixes{{n(3), n(5), 12.0}, {n(4), n(5), -3.0}};
  return {std::make_shared<DdGnssModel>(frame, geo, dd, var),
          std::make_shared<DopplerModel>(frame.R_e_n(), Vec3(0.1, -0.2, 0.5), dop),
          std::make_shared<TdcpModel>(frame, pair),
          std::make_shared<TdcpModel>(frame, pair, true),  // with the drift
          std::make_shared<RandomWalkModel>(state::kSv, 1, 0.01),
          std::make_shared<RandomWalkModel>(state::kTdcpDrift, 0.9,  // Gauss-Markov
                                            Eigen::Matrix3d(Eigen::Vector3d(1, 2, 3).asDiagonal())),
          std::make_shared<HeadingChangeModel>(0.001),
          std::make_shared<AmbiguityFixModel>(fixes, 1e-3),
          std::make_shared<ZuptModel>(0.01),
          std::make_shared<PositionModel>(Vec3(3.0, -2.0, 1.0),
                                          Eigen::Vector3d(0.01, 0.02, 0.05).asDiagonal()),
          std::make_shared<PositionModel>(  // with the single point positions' bias
              PositionModel(Vec3(3.0, -2.0, 1.0), Eigen::Vector3d(0.01, 0.02, 0.05).asDiagonal())
                  .withBias()),
          std::make_shared<NhcModel>(Vec3(0.1, -0.2, 0.5), 0.05),
          std::make_shared<ImuPreintegrationModel>(imu),
          std::make_shared<ImuPreintegrationModel>(imu, true),  // with the gyro's tilt
          std::make_shared<OdometerPreintegrationModel>(odo),
          std::make_shared<OdometerPreintegrationModel>(odo, true),  // a speed-only odometer
          std::make_shared<OdometerPreintegrationModel>(odo, false, rates),  // with the delay
          std::make_shared<OdometerPreintegrationModel>(odo, true, rates),
          std::make_shared<PriorModel>(prior_blocks, mean, Eigen::MatrixXd::Identity(7, 7) * 0.01)};
}

TEST(MeasurementModels, EveryJacobianMatchesNumericDifferentiation) {
  for (const auto& model : allModels()) {
    const bool gnss = model->name() == "dd_gnss" || model->name() == "tdcp";
    for (int trial = 0; trial < 10; ++trial) {
      test::expectJacobiansMatchNumeric(*model, randomValues(*model), gnss ? 1e-5 : 1e-6,
                                        gnss ? 1e-3 : 1e-6);
    }
    // Covariances are symmetric positive definite.
    const Eigen::MatrixXd C = model->covariance();
    ASSERT_EQ(C.rows(), model->residualSize()) << model->name();
    EXPECT_LT((C - C.transpose()).norm(), 1e-15) << model->name();
    EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(C).info(), Eigen::Success) << model->name();
  }
}

/// The inner model's and the projected model's Jacobians at `values`; the residuals must agree.
std::pair<std::vector<Eigen::MatrixXd>, std::vector<Eigen::MatrixXd>> jacobiansWithAndWithout(
    const ProjectedModel& projected, const std::vector<Eigen::VectorXd>& values) {
  Eigen::VectorXd r0, r1;
  std::vector<Eigen::MatrixXd> J0, J1;
  projected.innerModel().evaluate(test::pointers(values).data(), r0, &J0);
  projected.evaluate(test::pointers(values).data(), r1, &J1);
  EXPECT_EQ(r0, r1) << projected.name();
  return {J0, J1};
}

bool hasBlock(const MeasurementModel& m, const std::function<bool(const StateBlock&)>& which) {
  return std::any_of(m.blocks().begin(), m.blocks().end(), which);
}

TEST(PlanarMotionProjection, ResidualUnchangedAndBlindAlongTheVehicleVertical) {
  for (const auto& model : allModels()) {
    const auto& b = model->blocks();
    const bool has = hasBlock(*model, [](const StateBlock& x) { return x.key == state::kPbm; }) &&
                     hasBlock(*model, [](const StateBlock& x) { return x.key == state::kQbm; });
    if (!has) {
      EXPECT_THROW(PlanarMotionProjection{model}, std::invalid_argument) << model->name();
      continue;
    }
    const std::vector<Eigen::VectorXd> values = randomValues(*model);
    const auto [J0, J1] = jacobiansWithAndWithout(PlanarMotionProjection(model), values);
    for (size_t k = 0; k < b.size(); ++k) {
      if (b[k].key == state::kQbm) {
        const Vec3 u = quatFromWxyz(values[k].data()) * Vec3::UnitZ();
        for (size_t p = 0; p < b.size(); ++p) {
          if (b[p].key != state::kPbm) continue;
          EXPECT_LT((J1[p] * u).norm(), 1e-12) << model->name();
          // Moves across the vertical keep the model's own derivative.
          const Vec3 across = u.cross(Vec3::UnitX()).normalized();
          EXPECT_LT((J1[p] * across - J0[p] * across).norm(), 1e-12) << model->name();
        }
      }
    }
  }
}

TEST(StandstillProjection, ResidualUnchangedAndBlindToTheCalibration) {
  for (const auto& model : allModels()) {
    const auto& b = model->blocks();
    auto isCalibration = [](const StateBlock& x) {
      // Any copy of a calibration state ("s_v@i" in a two-state model).
      for (const StateKey& n : {state::kSv, state::kSw, state::kPbm, state::kQbm, state::kTdOdo}) {
        if (x.key.what == n.what) return true;
      }
      return false;
    };
    if (!hasBlock(*model, isCalibration)) {
      EXPECT_THROW(StandstillProjection{model}, std::invalid_argument) << model->name();
      continue;
    }
    const std::vector<Eigen::VectorXd> values = randomValues(*model);
    const auto [J0, J1] = jacobiansWithAndWithout(StandstillProjection(model), values);
    for (size_t k = 0; k < b.size(); ++k) {
      if (isCalibration(b[k])) {
        EXPECT_EQ(J1[k].norm(), 0.0) << model->name() << " " << b[k].key.str();
      } else {
        EXPECT_EQ(J1[k], J0[k]) << model->name() << " " << b[k].key.str();
      }
    }
  }
}

TEST(OdometerPreintegrationModel, SpeedOnlyIsThePositionRowsAtTheYawScaleOfTheIntervalStart) {
  auto odo = std::make_shared<OdometerPreintegration>(OdometerPreintegrationNoise{}, 0.02, -0.03);
  for (int k = 0; k < 25; ++k) odo->integrate(0.04, 2.0, 0.2 + 0.01 * k);
  const OdometerPreintegrationModel full(odo), speed(odo, true);
  ASSERT_EQ(speed.residualSize(), 3);
  std::vector<Eigen::VectorXd> values = randomValues(full);
  Eigen::VectorXd r_speed, r_other_sw;
  speed.evaluate(test::pointers(values).data(), r_speed, nullptr);
  // The position rows of the integral at s_w = -0.03, whitened by their own covariance.
  OdometerCalibration c;
  c.s_v = values[4][0];
  c.s_w = -0.03;
  c.p_b_m = values[6];
  c.q_b_m = quatFromWxyz(values[7].data());
  const OdometerResidual raw = odo->evaluate(values[0], quatFromWxyz(values[1].data()), values[2],
                                             quatFromWxyz(values[3].data()), c);
  const Eigen::MatrixXd W = whitener(odo->covarianceAt(c.s_v, c.s_w).topLeftCorner(3, 3), "p");
  EXPECT_LT((r_speed - W * raw.r.head(3)).norm(), 1e-9 * (1.0 + r_speed.norm()));
  // Whatever the s_w block holds.
  values[5][0] = 0.04;
  speed.evaluate(test::pointers(values).data(), r_other_sw, nullptr);
  EXPECT_EQ(r_other_sw, r_speed);
}

TEST(StandstillProjection, IsTheOdometerJacobianAtTheTruthOfAStillVehicle) {
  // Noise-free still readings and a pose that did not move: the model's own calibration
  // Jacobians are zero there, which is what the projection imposes at any estimate.
  auto odo = std::make_shared<OdometerPreintegration>(OdometerPreintegrationNoise{}, 0.02, -0.03);
  for (int k = 0; k < 25; ++k) odo->integrate(0.04, 0.0, 0.0);
  const OdometerPreintegrationModel model(odo, false, PoseRates{});  // still: no velocity, no turn
  std::vector<Eigen::VectorXd> values = randomValues(model);
  values[2] = values[0];  // p_j = p_i
  values[3] = values[1];  // q_j = q_i
  Eigen::VectorXd r;
  std::vector<Eigen::MatrixXd> J;
  model.evaluate(test::pointers(values).data(), r, &J);
  EXPECT_LT(r.norm(), 1e-12);
  for (size_t k = 4; k < J.size(); ++k)
    EXPECT_LT(J[k].norm(), 1e-12) << model.blocks()[k].key.str();
}

TEST(MeasurementModels, FilterRowsAreTheModelJacobiansAtTheStateOffsets) {
  for (const auto& model : allModels()) {
    const auto values = randomValues(*model);
    std::vector<BlockBinding> bindings;
    int offset = 2;  // some unrelated states first
    for (size_t k = 0; k < values.size(); ++k) {
      // Every third block is held fixed by the filter and must leave no columns.
      const bool fixed = k % 3 == 2;
      bindings.push_back({values[k].data(), fixed ? -1 : offset});
      if (!fixed) offset += model->blocks()[k].tangentSize();
    }
    const int n = offset + 4;
    const MeasurementRows rows = linearize(*model, bindings, n);
    Eigen::VectorXd r;
    std::vector<Eigen::MatrixXd> J;
    model->evaluate(test::pointers(values).data(), r, &J);
    EXPECT_EQ(rows.residual, r);
    EXPECT_EQ(rows.R, model->covariance());
    Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(model->residualSize(), n);
    for (size_t k = 0; k < values.size(); ++k) {
      if (bindings[k].error_offset >= 0) {
        expected.middleCols(bindings[k].error_offset, J[k].cols()) = J[k];
      }
    }
    EXPECT_EQ(rows.H, expected) << model->name();
  }
}

TEST(MeasurementModels, CeresCostIsTheWhitenedModelWithTangentJacobians) {
  RightQuaternionManifold manifold;
  for (const auto& model : allModels()) {
    const auto values = randomValues(*model);
    ModelCostFunction cost(model);
    const auto params = test::pointers(values);
    const int m = model->residualSize();
    Eigen::VectorXd residual(m);
    std::vector<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> J;
    std::vector<double*> J_ptr;
    for (const auto& b : model->blocks()) J.emplace_back(m, b.ambientSize());
    for (auto& j : J) J_ptr.push_back(j.data());
    ASSERT_TRUE(cost.Evaluate(params.data(), residual.data(), J_ptr.data()));
    Eigen::VectorXd r;
    model->evaluate(params.data(), r, nullptr);
    const Eigen::MatrixXd S = cost.sqrtInformation();
    EXPECT_LT((S.transpose() * S - model->covariance().inverse()).norm(),
              1e-9 * model->covariance().inverse().norm());
    EXPECT_LT((residual - S * r).norm(), 1e-12 * (1.0 + residual.norm()));
    // Ceres' tangent Jacobian (ambient Jacobian times PlusJacobian) against numeric
    // differentiation of the cost through the manifold's Plus.
    for (size_t k = 0; k < values.size(); ++k) {
      const StateBlock& b = model->blocks()[k];
      Eigen::MatrixXd tangent = J[k];
      if (b.kind == BlockKind::kRotation) {
        Eigen::Matrix<double, 4, 3, Eigen::RowMajor> plus_j;
        manifold.PlusJacobian(values[k].data(), plus_j.data());
        tangent = J[k] * plus_j;
      }
      const auto f = [&](const Eigen::VectorXd& d) -> Eigen::VectorXd {
        std::vector<Eigen::VectorXd> v = values;
        if (b.kind == BlockKind::kRotation) {
          manifold.Plus(values[k].data(), d.data(), v[k].data());
        } else {
          v[k] += d;
        }
        Eigen::VectorXd out(m);
        cost.Evaluate(test::pointers(v).data(), out.data(), nullptr);
        return out;
      };
      // Large ranges: see expectJacobiansMatchNumeric.
      const bool gnss = model->name() == "dd_gnss" || model->name() == "tdcp";
      EXPECT_LT(test::relativeDifference(
                    tangent, test::numericJacobian(f, b.tangentSize(), gnss ? 1e-3 : 1e-6)),
                gnss ? 1e-5 : 1e-6)
          << model->name() << " " << b.key.str();
    }
  }
}

}  // namespace
}  // namespace giocal
