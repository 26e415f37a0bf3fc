#include <gtest/gtest.h>

#include <cmath>

#include "common/gnss/fix_validation.h"

namespace giocal {
namespace {

DdObservation row(int sat, int ref) {
  DdObservation o;
  o.sat = {GnssSystem::kGps, sat};
  o.ref = {GnssSystem::kGps, ref};
  o.phase = true;
  return o;
}

// Rows within the limit pass; the worst row's satellite is named once; a second failure, or a
// NaN residual, names nothing.
TEST(FixValidation, TheWorstRowsSatelliteIsNamedOnce) {
  const std::vector<DdObservation> rows{row(3, 1), row(5, 1), row(7, 1)};
  EXPECT_TRUE(checkFixResiduals(rows, Eigen::Vector3d(1.0, 3.9, 0.5), 4.0, {}).ok);

  const FixCheck bad = checkFixResiduals(rows, Eigen::Vector3d(4.5, 9.0, 0.5), 4.0, {});
  EXPECT_FALSE(bad.ok);
  ASSERT_TRUE(bad.exclude.has_value());
  EXPECT_EQ(*bad.exclude, rows[1].sat);
  EXPECT_TRUE(rowExcluded(rows[1], {*bad.exclude}));
  EXPECT_FALSE(rowExcluded(rows[0], {*bad.exclude}));

  const FixCheck again =
      checkFixResiduals(rows, Eigen::Vector3d(4.5, 0.0, 0.5), 4.0, {rows[1].sat});
  EXPECT_FALSE(again.ok);
  EXPECT_FALSE(again.exclude.has_value());

  const FixCheck nan = checkFixResiduals(rows, Eigen::Vector3d(1.0, NAN, 9.0), 4.0, {});
  EXPECT_FALSE(nan.ok);
  EXPECT_FALSE(nan.exclude.has_value());
}

}  // namespace
}  // namespace giocal
