#include <gtest/gtest.h>

#include "common/calibration/rejection_share.h"

namespace giocal {
namespace {

CalibrationRun runWith(long intervals, long odometer_rejected, long dd_rows, long rows_rejected,
                       int gnss_epochs = 0) {
  CalibrationRun run;
  run.count(Counter::kOdometerIntervals, intervals);
  run.count(Counter::kOdometerRejected, odometer_rejected);
  run.count(Counter::kDdRows, dd_rows);
  run.count(Counter::kGnssRowsRejected, rows_rejected);
  run.gnss_epochs = gnss_epochs;
  return run;
}

// The counts of field-preset runs (docs/results.md, "The factor graph's own solver with a
// near-perfect IMU"): a healthy EKF run and the factor graph's diverged one on the same data.
TEST(RejectionShare, ADivergedRunIsToldAndAHealthyOneIsNot) {
  EXPECT_TRUE(rejectionShareWarnings(runWith(1237, 28, 21037, 24), false).empty());
  const std::vector<std::string> w =
      rejectionShareWarnings(runWith(1237, 1102, 7311, 13725), false);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NE(w[0].find("1102 of 1237 odometer intervals"), std::string::npos) << w[0];
  EXPECT_NE(w[1].find("13725 of 21036 double-difference GNSS rows"), std::string::npos) << w[1];
  EXPECT_NE(w[1].find("likely wrong"), std::string::npos) << w[1];
}

TEST(RejectionShare, TheShareIsOfAllAndOnlyBeyondTheFraction) {
  // Exactly half is not more than half; one more is.
  EXPECT_TRUE(rejectionShareWarnings(runWith(100, 50, 0, 0), false).empty());
  EXPECT_EQ(rejectionShareWarnings(runWith(100, 51, 0, 0), false).size(), 1u);
  EXPECT_EQ(rejectionShareWarnings(runWith(100, 21, 0, 0), false, 0.2).size(), 1u);
  // Nothing counted: nothing to say.
  EXPECT_TRUE(rejectionShareWarnings(runWith(0, 0, 0, 0), false).empty());
}

TEST(RejectionShare, PositionFixesCountThreeRowsEach) {
  // LC: 100 fixes used (300 rows), 20 rejected (60 rows): 17 %, not a DD run with no rows used.
  EXPECT_TRUE(rejectionShareWarnings(runWith(100, 0, 0, 60, 100), true).empty());
  const std::vector<std::string> w = rejectionShareWarnings(runWith(100, 0, 0, 330, 100), true);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("330 of 630 GNSS position rows"), std::string::npos) << w[0];
}

// The status a run ends with: suspect once more than half of a kind of data was turned away.
TEST(RejectionShare, MoreThanHalfRejectedOrUnusedMakesTheRunSuspect) {
  EXPECT_EQ(suspectReason(runWith(1237, 28, 21037, 24), false, false), "");
  EXPECT_EQ(suspectReason(runWith(1237, 1102, 7311, 13725), false, false),
            "1102 of 1237 odometer intervals rejected by the gates");
  EXPECT_EQ(suspectReason(runWith(100, 0, 100, 101), false, false),
            "101 of 201 double-difference GNSS rows rejected by the gates");
  CalibrationRun lc = runWith(100, 0, 0, 0, 378);
  lc.count(Counter::kGnssEpochsUnused, 2325);
  EXPECT_EQ(suspectReason(lc, true, true), "2325 of 2703 position fixes updated nothing");
  EXPECT_EQ(suspectReason(lc, false, false), "");  // not the LC scheme: not counted
}

}  // namespace
}  // namespace giocal
