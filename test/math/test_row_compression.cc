#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "common/math/kalman_update.h"
#include "common/math/row_compression.h"

namespace giocal {
namespace {

Eigen::MatrixXd randomCovariance(std::mt19937& rng, int n) {
  std::normal_distribution<double> g;
  Eigen::MatrixXd A(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) A(i, j) = g(rng);
  return A * A.transpose() + 0.1 * Eigen::MatrixXd::Identity(n, n);
}

// Rows 0-3 touch any column; rows 4-9 (the subset, correlated among themselves, not with 0-3)
// touch columns 1, 4 and 7 only.
MeasurementRows randomRows(std::mt19937& rng, int n) {
  std::normal_distribution<double> g;
  MeasurementRows rows;
  rows.H = Eigen::MatrixXd::Zero(10, n);
  rows.residual.resize(10);
  for (int i = 0; i < 10; ++i) {
    rows.residual[i] = g(rng);
    if (i < 4) {
      for (int j = 0; j < n; ++j) rows.H(i, j) = g(rng);
    } else {
      for (int j : {1, 4, 7}) rows.H(i, j) = g(rng);
    }
  }
  rows.R = Eigen::MatrixXd::Zero(10, 10);
  rows.R.topLeftCorner(4, 4) = randomCovariance(rng, 4);
  rows.R.bottomRightCorner(6, 6) = randomCovariance(rng, 6);
  return rows;
}

TEST(RowCompression, SameUpdateWithFewerRowsHeldStatesIncluded) {
  std::mt19937 rng(11);
  const std::vector<int> subset{4, 5, 6, 7, 8, 9};
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 12;
    const Eigen::MatrixXd P0 = randomCovariance(rng, n);
    const MeasurementRows rows = randomRows(rng, n);
    const MeasurementRows small = compressRows(rows, subset);
    ASSERT_EQ(small.H.rows(), 4 + 3);  // the subset's six rows became three
    for (const std::vector<int>& held : {std::vector<int>{}, std::vector<int>{2, 4}}) {
      Eigen::MatrixXd P_full = P0, P_small = P0;
      const UpdateResult full = kalmanUpdate(P_full, rows, INFINITY, held);
      const UpdateResult comp = kalmanUpdate(P_small, small, INFINITY, held);
      ASSERT_TRUE(full.accepted && comp.accepted);
      EXPECT_LT((full.dx - comp.dx).norm(), 1e-10 * (1.0 + full.dx.norm()));
      EXPECT_LT((P_full - P_small).norm(), 1e-10 * P0.norm());
      // The dropped part of the innovation is the subset's own least-squares misfit.
      EXPECT_LE(comp.nis, full.nis + 1e-9);
    }
  }
}

TEST(RowCompression, UncorrelatedGroupsOfTheSubsetAreWhitenedApartWithTheSameResult) {
  // The subset's rows form two groups, interleaved (4, 6, 8 and 5, 7, 9), correlated within a
  // group only, and a single row (as a Doppler row) on its own.
  std::mt19937 rng(13);
  for (int trial = 0; trial < 10; ++trial) {
    const int n = 12;
    const Eigen::MatrixXd P0 = randomCovariance(rng, n);
    MeasurementRows rows = randomRows(rng, n);
    const Eigen::MatrixXd Ra = randomCovariance(rng, 3), Rb = randomCovariance(rng, 2);
    rows.R.bottomRightCorner(6, 6).setZero();
    const std::vector<int> a{4, 6, 8}, b{5, 7};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) rows.R(a[size_t(i)], a[size_t(j)]) = Ra(i, j);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) rows.R(b[size_t(i)], b[size_t(j)]) = Rb(i, j);
    rows.R(9, 9) = 0.3;
    const MeasurementRows small = compressRows(rows, {4, 5, 6, 7, 8, 9});
    ASSERT_EQ(small.H.rows(), 4 + 3);
    Eigen::MatrixXd P_full = P0, P_small = P0;
    const UpdateResult full = kalmanUpdate(P_full, rows, INFINITY);
    const UpdateResult comp = kalmanUpdate(P_small, small, INFINITY);
    ASSERT_TRUE(full.accepted && comp.accepted);
    EXPECT_LT((full.dx - comp.dx).norm(), 1e-10 * (1.0 + full.dx.norm()));
    EXPECT_LT((P_full - P_small).norm(), 1e-10 * P0.norm());
  }
}

TEST(RowCompression, LeavesRowsAloneWhereItCannotHelpOrWouldBeWrong) {
  std::mt19937 rng(12);
  const MeasurementRows rows = randomRows(rng, 12);
  // Three rows on three columns: nothing to gain.
  EXPECT_EQ(compressRows(rows, {4, 5, 6}).H.rows(), 10);
  // A subset correlated with a row outside it.
  MeasurementRows correlated = rows;
  correlated.R(0, 5) = correlated.R(5, 0) = 0.01;
  EXPECT_EQ(compressRows(correlated, {4, 5, 6, 7, 8, 9}).H.rows(), 10);
  // A subset whose covariance is not positive definite.
  MeasurementRows singular = rows;
  singular.R.bottomRightCorner(6, 6).setZero();
  EXPECT_EQ(compressRows(singular, {4, 5, 6, 7, 8, 9}).H.rows(), 10);
}

// normalizedInnovations against |r_i| / sqrt(h_i P h_i^T + R_ii) formed densely: rows that
// touch every column, rows sharing a few columns (taken as one group), a row with as many
// columns but other ones after them, the first group's columns again, and a row of zeros.
TEST(NormalizedInnovations, EqualTheDenseFormulaRowByRow) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  const int n = 12;
  const Eigen::MatrixXd P = randomCovariance(rng, n);
  MeasurementRows rows = randomRows(rng, n);
  rows.H.conservativeResize(13, n);
  rows.H.bottomRows(3).setZero();
  for (int j : {2, 5, 9}) rows.H(10, j) = g(rng);  // as many columns as rows 4-9, others
  rows.H(11, 1) = g(rng);                          // the subset's columns again, after the break
  rows.H(11, 4) = g(rng);
  rows.H(11, 7) = g(rng);
  rows.residual.conservativeResize(13);
  rows.residual.tail(3) << g(rng), g(rng), g(rng);
  Eigen::MatrixXd R = Eigen::MatrixXd::Identity(13, 13);
  R.topLeftCorner(10, 10) = rows.R;
  rows.R = R;
  const Eigen::VectorXd z = normalizedInnovations(P, rows);
  ASSERT_EQ(z.size(), 13);
  for (int i = 0; i < 13; ++i) {
    const double s = rows.H.row(i) * P * rows.H.row(i).transpose() + rows.R(i, i);
    EXPECT_NEAR(z[i], std::abs(rows.residual[i]) / std::sqrt(s), 1e-12 * z[i]) << i;
  }
  EXPECT_NEAR(z[12], std::abs(rows.residual[12]), 1e-15);  // no state: R alone
}

}  // namespace
}  // namespace giocal
