#include <gtest/gtest.h>

#include "common/math/null_space.h"

namespace giocal {
namespace {

// A Hessian over a position [m] and an ambiguity [cycles] with information 14 orders apart, and
// a pair tied only to each other: only the pair's common offset (and a column with nothing) is
// unobserved, however the units differ.
TEST(NullSpace, UnobservedIndicesAreJudgedInEachUnitAlike) {
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(5, 5);
  H(0, 0) = 1e12;                               // well observed
  H(1, 1) = 1e-2;                               // weakly observed, but observed
  H.block(2, 2, 2, 2) << 1.0, -1.0, -1.0, 1.0;  // only the difference of 2 and 3
  // index 4: nothing at all
  const std::vector<int> none = unobservedIndices(H, {0, 1, 2, 3, 4});
  EXPECT_EQ(none, (std::vector<int>{2, 3, 4}));
  EXPECT_TRUE(unobservedIndices(H, {0, 1}).empty());
  const Eigen::VectorXd d = jacobiScale(H);
  EXPECT_DOUBLE_EQ(d[0], 1e-6);
  EXPECT_DOUBLE_EQ(d[4], 1.0);
}

}  // namespace
}  // namespace giocal
