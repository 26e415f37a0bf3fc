#include <gtest/gtest.h>

#include <stdexcept>

#include "evaluation/validation.h"

namespace giocal {
namespace {

/// Inputs whose rover and IMU span [0, 600] s, and a reference with 1 Hz rows outside `gaps`.
struct Drive {
  CalibrationInputs in;
  std::vector<TruthSample> rows;
  explicit Drive(const std::vector<std::pair<double, double>>& gaps) {
    ObsEpoch e;
    e.t = 0.0;
    in.rover.epochs.push_back(e);
    for (double t = 0.0; t <= 600.0; t += 0.01) {
      ImuSample s;
      s.t = t;
      in.imu.push_back(s);
    }
    for (double t = 0.0; t <= 600.0; t += 1.0) {
      bool inside = false;
      for (const auto& [a, b] : gaps) inside = inside || (t > a && t < b);
      if (inside) continue;
      TruthSample r;
      r.t = t;
      r.lat_deg = 35.0;
      r.lon_deg = 137.0;
      rows.push_back(r);
    }
  }
};

TEST(ValidationWindows, AWindowPlannedInAReferenceGapStartsAtItsEnd) {
  ValidationJob job;  // 5 windows of 60 s
  // Without gaps: spread evenly from 10 s after the first calibration row (20 s) to 540 s.
  const Drive clean({});
  const std::vector<double> even =
      validationWindowStarts(clean.in, ReferenceTrajectory(clean.rows), 20.0, job);
  ASSERT_EQ(even.size(), 5u);
  EXPECT_DOUBLE_EQ(even[0], 30.0);
  EXPECT_NEAR(even[2], 285.0, 1e-6);
  EXPECT_NEAR(even[4], 540.0, 1e-6);

  // No fixes from 280 to 330 s (trees): the middle window starts at the gap's end, and the
  // next ones keep clear of it (no overlap).
  const Drive trees({{280.0, 330.0}});
  const std::vector<double> moved =
      validationWindowStarts(trees.in, ReferenceTrajectory(trees.rows), 20.0, job);
  ASSERT_EQ(moved.size(), 5u);
  EXPECT_DOUBLE_EQ(moved[1], even[1]);
  EXPECT_GE(moved[2], 330.0);
  EXPECT_LT(moved[2], 331.5);
  EXPECT_GE(moved[3], moved[2] + job.outage_s);
  EXPECT_NEAR(moved[4], 540.0, 1e-6);

  // A gap to near the end: the windows that no longer fit are left out.
  const Drive tail({{400.0, 560.0}});
  const std::vector<double> fewer =
      validationWindowStarts(tail.in, ReferenceTrajectory(tail.rows), 20.0, job);
  EXPECT_EQ(fewer.size(), 3u);
  for (double t : fewer) EXPECT_LE(t, 400.0);

  // No fix anywhere a window could start: said, not a dead-reckoning error.
  const Drive none({{25.0, 590.0}});
  try {
    validationWindowStarts(none.in, ReferenceTrajectory(none.rows), 20.0, job);
    FAIL() << "no window can start";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("has no solution where a window could start"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace giocal
