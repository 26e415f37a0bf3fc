#include <gtest/gtest.h>

#include <Eigen/LU>

#include "common/math/kalman_update.h"
#include "common/math/rotation.h"
#include "common/math/so3.h"
#include "common/models/zupt_model.h"
#include "ekf/state_registry.h"

namespace giocal {
namespace {

const StateKey kN5 = ambiguityKey(SatId{GnssSystem::kGps, 5}, '1');

Eigen::MatrixXd spd(int n, double scale) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Random(n, n);
  return scale * (A * A.transpose() + Eigen::MatrixXd::Identity(n, n));
}

TEST(StateRegistry, AddRemoveKeepsTheCovarianceBlocks) {
  StateRegistry s;
  s.add(vectorBlock(state::kP), Eigen::Vector3d(1, 2, 3), spd(3, 1.0));
  Eigen::VectorXd q(4);
  q << 1, 0, 0, 0;
  s.add(rotationBlock(state::kQ), q, spd(3, 0.01));
  s.add(vectorBlock(kN5, 1), Eigen::VectorXd::Constant(1, 12.3),
        Eigen::MatrixXd::Constant(1, 1, 4.0));
  s.add(vectorBlock(state::kSv, 1), Eigen::VectorXd::Zero(1),
        Eigen::MatrixXd::Constant(1, 1, 1e-4));
  EXPECT_EQ(s.dim(), 8);
  EXPECT_EQ(s.offset(kN5), 6);
  EXPECT_EQ(s.offset(state::kSv), 7);
  // Correlate everything, then remove the ambiguity: the rest of the covariance is untouched.
  Eigen::MatrixXd P = spd(8, 0.1);
  s.covariance() = P;
  s.remove(kN5);
  EXPECT_EQ(s.dim(), 7);
  EXPECT_EQ(s.offset(state::kSv), 6);
  EXPECT_FALSE(s.has(kN5));
  std::vector<int> keep{0, 1, 2, 3, 4, 5, 7};
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j)
      EXPECT_EQ(s.covariance()(i, j),
                P(keep[static_cast<size_t>(i)], keep[static_cast<size_t>(j)]));
  EXPECT_EQ(s.keys(), (std::vector<StateKey>{state::kP, state::kQ, state::kSv}));
  EXPECT_THROW(
      s.add(vectorBlock(state::kSv, 1), Eigen::VectorXd::Zero(1), Eigen::MatrixXd::Identity(1, 1)),
      std::invalid_argument);
  EXPECT_THROW(s.offset(state::kTdOdo), std::out_of_range);
}

TEST(StateRegistry, CorrectionUsesBoxPlus) {
  StateRegistry s;
  s.add(vectorBlock(state::kV), Eigen::Vector3d(1, 0, 0), Eigen::Matrix3d::Identity());
  Eigen::VectorXd q(4);
  quatToWxyz(Quat(rotationFromRpy(Vec3(0.1, 0.2, 0.3))), q.data());
  s.add(rotationBlock(state::kQbm), q, Eigen::Matrix3d::Identity());
  Eigen::VectorXd dx(6);
  dx << 0.5, -0.5, 1.0, 0.01, -0.02, 0.03;
  s.correct(dx);
  EXPECT_LT((s.value(state::kV) - Eigen::Vector3d(1.5, -0.5, 1.0)).norm(), 1e-15);
  const Quat expected = boxPlus(quatFromWxyz(q.data()), Vec3(0.01, -0.02, 0.03));
  EXPECT_LT(quatFromWxyz(s.value(state::kQbm).data()).angularDistance(expected), 1e-14);
}

TEST(StateRegistry, ModelsBindByNameAndUpdate) {
  StateRegistry s;
  s.add(vectorBlock(state::kP), Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  s.add(vectorBlock(state::kV), Eigen::Vector3d(0.3, -0.2, 0.1),
        Eigen::Matrix3d::Identity() * 0.25);
  const ZuptModel zupt(0.01);
  const MeasurementRows rows = linearize(zupt, s.bind({state::kV}), s.dim());
  EXPECT_EQ(rows.H.block(0, 3, 3, 3), Eigen::Matrix3d::Identity());
  EXPECT_EQ(rows.H.block(0, 0, 3, 3), Eigen::Matrix3d::Zero());
  const UpdateResult up = kalmanUpdate(s.covariance(), rows, 1e9);
  ASSERT_TRUE(up.accepted);
  s.correct(up.dx);
  // The velocity moves to zero by the weight 0.25 / (0.25 + 1e-4); the position is untouched.
  EXPECT_LT(s.value(state::kV).norm(), 0.3 * 1e-4 / 0.25 * 2);
  EXPECT_EQ(s.value(state::kP), Eigen::Vector3d::Zero());
  EXPECT_LT(s.marginal(state::kV)(0, 0), 1.01e-4);
  EXPECT_THROW(s.bind({state::kBg}), std::out_of_range);
}

TEST(StateRegistry, CloneIsFullyCorrelatedAndMinusInvertsCorrect) {
  StateRegistry s;
  s.add(vectorBlock(state::kP), Eigen::Vector3d(1, 2, 3), spd(3, 1.0));
  Eigen::VectorXd q(4);
  quatToWxyz(Quat(expSO3(Vec3(0.1, -0.2, 0.3))), q.data());
  s.add(rotationBlock(state::kQ), q, spd(3, 0.01));
  s.covariance() = spd(6, 0.1);
  const Eigen::MatrixXd P = s.covariance();
  s.clone(state::kQ, at(state::kQ, Copy::kStill));
  ASSERT_EQ(s.dim(), 9);
  EXPECT_TRUE(s.value(at(state::kQ, Copy::kStill)).isApprox(s.value(state::kQ)));
  // The clone's rows and columns equal the original's: the difference has zero variance.
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(3, 9);
  D.middleCols(3, 3).setIdentity();
  D.middleCols(6, 3) = -Eigen::Matrix3d::Identity();
  EXPECT_LT((D * s.covariance() * D.transpose()).norm(), 1e-15);
  EXPECT_TRUE(s.covariance().topLeftCorner(6, 6).isApprox(P));
  // minus() is the inverse of correct().
  const StateRegistry base = s;
  Eigen::VectorXd dx(9);
  dx << 0.1, -0.2, 0.3, 0.01, 0.02, -0.03, -0.02, 0.01, 0.005;
  s.correct(dx);
  Eigen::VectorXd back;
  s.minus(base, back);
  EXPECT_LT((back - dx).norm(), 1e-12);
}

TEST(StateRegistry, CloningOverAnExistingCopyIsRemovingItAndCloningAgainInPlace) {
  // Two registries with a clone of p, moved on by a correlated update: one re-clones in place,
  // the other removes the clone and clones again (which puts it at the end of the state).
  StateRegistry in_place, again;
  const Eigen::MatrixXd P = spd(10, 0.2);
  for (StateRegistry* s : {&in_place, &again}) {
    s->add(vectorBlock(state::kP), Eigen::Vector3d(1, 2, 3), spd(3, 1.0));
    s->add(vectorBlock(state::kV), Eigen::Vector3d(0.1, 0.2, 0.3), spd(3, 0.1));
    s->clone(state::kP, at(state::kP, Copy::kOdo));
    s->add(vectorBlock(kN5, 1), Eigen::VectorXd::Constant(1, 7.0), spd(1, 4.0));
    s->covariance() = P;
    s->value(state::kP) = Eigen::Vector3d(4, 5, 6);
  }
  const int before = in_place.offset(at(state::kP, Copy::kOdo));
  in_place.clone(state::kP, at(state::kP, Copy::kOdo));
  again.remove(at(state::kP, Copy::kOdo));
  again.clone(state::kP, at(state::kP, Copy::kOdo));
  EXPECT_EQ(in_place.offset(at(state::kP, Copy::kOdo)), before);  // no resize, no move
  EXPECT_EQ(in_place.value(at(state::kP, Copy::kOdo)), Eigen::Vector3d(4, 5, 6));
  // The same joint covariance, variable by variable.
  const std::vector<StateKey> keys{state::kP, state::kV, at(state::kP, Copy::kOdo), kN5};
  for (const StateKey& a : keys) {
    for (const StateKey& b : keys) {
      const auto block = [&](const StateRegistry& s) {
        return Eigen::MatrixXd(s.covariance().block(
            s.offset(a), s.offset(b), s.block(a).tangentSize(), s.block(b).tangentSize()));
      };
      EXPECT_EQ(block(in_place), block(again)) << a.str() << " " << b.str();
    }
  }
}

TEST(StateRegistry, ConditionedVariablesAreKnownConstantsWithTheJointSchurComplement) {
  const StateKey kN7 = ambiguityKey(SatId{GnssSystem::kGps, 7}, '1');
  StateRegistry s;
  s.add(vectorBlock(state::kP), Eigen::Vector3d(1, 2, 3), Eigen::Matrix3d::Identity());
  s.add(vectorBlock(kN5, 1), Eigen::VectorXd::Constant(1, 12.3), Eigen::MatrixXd::Identity(1, 1));
  s.add(vectorBlock(state::kSv, 1), Eigen::VectorXd::Zero(1), Eigen::MatrixXd::Identity(1, 1));
  s.add(vectorBlock(kN7, 1), Eigen::VectorXd::Constant(1, -4.0), Eigen::MatrixXd::Identity(1, 1));
  const Eigen::MatrixXd P = spd(6, 0.1);
  s.covariance() = P;
  s.condition({kN7, kN5});
  // The rest's covariance is the joint Schur complement over both, whatever their order.
  const std::vector<int> rest{0, 1, 2, 4}, cond{3, 5};
  Eigen::MatrixXd Prr(4, 4), Prc(4, 2), Pcc(2, 2);
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) Prr(i, j) = P(rest[size_t(i)], rest[size_t(j)]);
    for (int j = 0; j < 2; ++j) Prc(i, j) = P(rest[size_t(i)], cond[size_t(j)]);
  }
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) Pcc(i, j) = P(cond[size_t(i)], cond[size_t(j)]);
  ASSERT_EQ(s.dim(), 4);
  EXPECT_LT((s.covariance() - (Prr - Prc * Pcc.inverse() * Prc.transpose())).norm(), 1e-12);
  EXPECT_EQ(s.keys(), (std::vector<StateKey>{state::kP, state::kSv}));
  EXPECT_TRUE(s.has(kN5) && s.isKnown(kN5) && !s.isKnown(state::kSv));
  EXPECT_EQ(s.offset(kN7), -1);
  EXPECT_EQ(s.offset(state::kSv), 3);
  EXPECT_THROW(s.marginal(kN5), std::invalid_argument);
  // A known variable keeps its value through corrections and binds as a constant.
  s.correct(Eigen::Vector4d(0.1, 0.2, 0.3, 0.4));
  EXPECT_EQ(s.value(kN5)[0], 12.3);
  const std::vector<BlockBinding> b = s.bind({state::kSv, kN7});
  EXPECT_EQ(b[0].error_offset, 3);
  EXPECT_EQ(b[1].error_offset, -1);
  EXPECT_EQ(b[1].value[0], -4.0);
  // A known variable is removed (it leaves no column) or estimated again after removal.
  s.remove(kN7);
  EXPECT_FALSE(s.has(kN7));
  s.add(vectorBlock(kN7, 1), Eigen::VectorXd::Constant(1, 3.0), Eigen::MatrixXd::Identity(1, 1));
  EXPECT_EQ(s.offset(kN7), 4);
  EXPECT_EQ(s.dim(), 5);
}

TEST(KalmanUpdate, HeldStatesKeepValueAndVarianceAndTheUpdateIsJoseph) {
  // A Schmidt (consider) update: the held state's gain is zero; the covariance must equal the
  // dense Joseph form with that gain.
  Eigen::MatrixXd P = spd(5, 0.2);
  MeasurementRows rows;
  rows.H = Eigen::MatrixXd::Random(2, 5);
  rows.residual = Eigen::Vector2d(0.3, -0.1);
  rows.R = Eigen::Matrix2d::Identity() * 0.05;
  const Eigen::MatrixXd P0 = P;
  const UpdateResult r = kalmanUpdate(P, rows, 1e9, {2});
  ASSERT_TRUE(r.accepted);
  EXPECT_EQ(r.dx[2], 0.0);
  EXPECT_DOUBLE_EQ(P(2, 2), P0(2, 2));
  const Eigen::MatrixXd S = rows.H * P0 * rows.H.transpose() + rows.R;
  Eigen::MatrixXd K = P0 * rows.H.transpose() * S.inverse();
  K.row(2).setZero();
  const Eigen::MatrixXd IKH = Eigen::MatrixXd::Identity(5, 5) - K * rows.H;
  const Eigen::MatrixXd joseph = IKH * P0 * IKH.transpose() + K * rows.R * K.transpose();
  EXPECT_LT((P - joseph).norm(), 1e-12);
  EXPECT_LT((r.dx - K * (-rows.residual)).norm(), 1e-12);
  // Without held states it is the optimal update.
  Eigen::MatrixXd P2 = P0;
  kalmanUpdate(P2, rows, 1e9);
  const Eigen::MatrixXd K0 = P0 * rows.H.transpose() * S.inverse();
  EXPECT_LT((P2 - (P0 - K0 * S * K0.transpose())).norm(), 1e-12);
}

// A numerical failure is not a gate's rejection: an innovation covariance that is not positive
// definite, or a downdate that leaves a negative variance (here from a covariance that is not
// positive semidefinite), fails with P unchanged and says so; a gated row only rejects.
TEST(KalmanUpdate, NumericalFailuresAreToldApartFromRejectionsAndLeavePUnchanged) {
  MeasurementRows rows;
  rows.H = Eigen::RowVector2d(1.0, 0.0);
  rows.residual = Eigen::VectorXd::Constant(1, 0.1);
  rows.R = Eigen::MatrixXd::Constant(1, 1, -5.0);  // S = 1 - 5 < 0
  Eigen::MatrixXd P = Eigen::Matrix2d::Identity();
  UpdateResult r = kalmanUpdate(P, rows, 1e9);
  EXPECT_FALSE(r.accepted);
  EXPECT_TRUE(r.numerical_failure);
  EXPECT_EQ(P, Eigen::MatrixXd(Eigen::Matrix2d::Identity()));

  rows.R(0, 0) = 0.01;
  Eigen::MatrixXd indefinite(2, 2);
  indefinite << 1.0, 2.0, 2.0, 1.0;  // eigenvalues 3 and -1: x2's variance goes 1 - 4/1.01 < 0
  P = indefinite;
  r = kalmanUpdate(P, rows, 1e9);
  EXPECT_FALSE(r.accepted);
  EXPECT_TRUE(r.numerical_failure);
  EXPECT_EQ(P, indefinite);

  P = Eigen::Matrix2d::Identity();
  rows.residual(0) = 100.0;  // far outside the gate
  r = kalmanUpdate(P, rows, 9.0);
  EXPECT_FALSE(r.accepted);
  EXPECT_FALSE(r.numerical_failure);
}

// The iterated update's halves: the gain leaves P as it was, and gain then downdate (with
// another update's use of the workspace in between undone by a new gain) is kalmanUpdateInto to
// the bit, held states included.
TEST(KalmanUpdate, GainThenDowndateIsTheWholeUpdateToTheBit) {
  const Eigen::MatrixXd P0 = spd(7, 0.3);
  MeasurementRows rows;
  rows.H = Eigen::MatrixXd::Random(3, 7);
  rows.H.col(4).setZero();  // a column no row touches, as in a long state
  rows.residual = Eigen::Vector3d(0.2, -0.4, 0.1);
  rows.R = Eigen::Matrix3d::Identity() * 0.02;
  const std::vector<int> held{5};
  Eigen::MatrixXd P_whole = P0;
  KalmanWorkspace ws_whole;
  UpdateResult whole;
  kalmanUpdateInto(P_whole, rows, 1e9, held, ws_whole, whole);
  ASSERT_TRUE(whole.accepted);
  // Both are checked against the dense form too (a fault shared by both would pass the above):
  // P - K0 S K0^T, the held x held block kept.
  const Eigen::MatrixXd S = rows.H * P0 * rows.H.transpose() + rows.R;
  const Eigen::MatrixXd K0 = P0 * rows.H.transpose() * S.inverse();
  Eigen::MatrixXd dense = P0 - K0 * S * K0.transpose();
  dense(5, 5) = P0(5, 5);
  EXPECT_LT((P_whole - dense).norm(), 1e-12);

  Eigen::MatrixXd P = P0;
  KalmanWorkspace ws;
  UpdateResult halves;
  MeasurementRows other;  // an earlier iteration's gain, at other rows (fewer of them)
  other.H = 2.0 * rows.H.topRows(2);
  other.residual = rows.residual.head(2);
  other.R = rows.R.topLeftCorner(2, 2);
  kalmanGainInto(P, other, 1e9, held, ws, halves);
  ASSERT_TRUE(halves.accepted);
  EXPECT_EQ(P, P0);  // the gain alone leaves P
  EXPECT_FALSE(halves.dx.isApprox(whole.dx));
  kalmanGainInto(P, rows, 1e9, held, ws, halves);
  ASSERT_TRUE(halves.accepted);
  EXPECT_EQ(P, P0);
  EXPECT_EQ(halves.dx, whole.dx);
  EXPECT_EQ(halves.nis, whole.nis);
  kalmanDowndate(P, held, ws, halves);
  EXPECT_TRUE(halves.accepted);
  EXPECT_EQ(P, P_whole);
  // A gated gain is refused and leaves P.
  kalmanGainInto(P, rows, 1e-6, held, ws, halves);
  EXPECT_FALSE(halves.accepted);
  EXPECT_FALSE(halves.numerical_failure);
}

}  // namespace
}  // namespace giocal
