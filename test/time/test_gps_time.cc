#include <gtest/gtest.h>

#include "common/time/gps_time.h"

namespace giocal {
namespace {

TEST(GpsTime, EpochIsZero) {
  EXPECT_EQ(daysSinceGpsEpoch(1980, 1, 6), 0);
  EXPECT_DOUBLE_EQ(gpsSecondsFromCalendar({1980, 1, 6, 0, 0, 0.0}), 0.0);
}

TEST(GpsTime, KnownWeeks) {
  // 2017-01-01 was the first day of GPS week 1930; 2005-04-02 (the GSI data) was day 6 of 1316.
  EXPECT_EQ(weekTimeFromGpsSeconds(gpsSecondsFromCalendar({2017, 1, 1, 0, 0, 0.0})).week, 1930);
  const GpsWeekTime wt = weekTimeFromGpsSeconds(gpsSecondsFromCalendar({2005, 4, 2, 12, 0, 0.0}));
  EXPECT_EQ(wt.week, 1316);
  EXPECT_DOUBLE_EQ(wt.tow, 6 * 86400.0 + 12 * 3600.0);
}

TEST(GpsTime, CalendarRoundTripOverDecades) {
  for (double t = 0.0; t < 3e9; t += 86400.0 * 37.3 + 1234.567) {
    const CalendarTime c = calendarFromGpsSeconds(t);
    EXPECT_NEAR(gpsSecondsFromCalendar(c), t, 1e-6);
    const GpsWeekTime wt = weekTimeFromGpsSeconds(t);
    EXPECT_NEAR(gpsSecondsFromWeekTime(wt), t, 1e-6);
    EXPECT_GE(wt.tow, 0.0);
    EXPECT_LT(wt.tow, kSecondsPerWeek);
  }
  const CalendarTime leap_day =
      calendarFromGpsSeconds(gpsSecondsFromCalendar({2024, 2, 29, 23, 59, 59.5}));
  EXPECT_EQ(leap_day.month, 2);
  EXPECT_EQ(leap_day.day, 29);
  EXPECT_NEAR(leap_day.second, 59.5, 1e-9);
}

TEST(GpsTime, LeapSecondCountsAndBoundary) {
  const double before = gpsSecondsFromCalendar({2016, 12, 31, 23, 59, 59.0});  // UTC scale count
  const double after = gpsSecondsFromCalendar({2017, 1, 1, 0, 0, 0.0});
  EXPECT_EQ(leapSecondsAtUtc(gpsSecondsFromCalendar({1980, 1, 6, 0, 0, 0.0})), 0);
  EXPECT_EQ(leapSecondsAtUtc(before), 17);
  EXPECT_EQ(leapSecondsAtUtc(after), 18);
  EXPECT_DOUBLE_EQ(gpsFromUtcSeconds(before), before + 17);
  EXPECT_DOUBLE_EQ(gpsFromUtcSeconds(after), after + 18);
  // UTC 00:00:00 is 18 s into GPS week 1930.
  EXPECT_DOUBLE_EQ(weekTimeFromGpsSeconds(gpsFromUtcSeconds(after)).tow, 18.0);
  // Round trip on both sides of the boundary at sub-second steps (the continuous UTC count has no
  // 23:59:60, so every count maps back to itself).
  for (double utc = before - 5.0; utc < after + 5.0; utc += 0.25) {
    EXPECT_NEAR(utcFromGpsSeconds(gpsFromUtcSeconds(utc)), utc, 1e-9) << utc - before;
  }
  EXPECT_EQ(leapSecondsAtGps(after + 18.0), 18);
  EXPECT_EQ(leapSecondsAtGps(after + 17.5), 17);
}

TEST(GpsTime, FormatRoundsWithoutSixtySeconds) {
  CalendarTime c{2020, 12, 31, 23, 59, 59.9996};
  EXPECT_EQ(formatCalendar(c), "2021/01/01 00:00:00.000");
  EXPECT_EQ(formatCalendar({2005, 4, 2, 0, 0, 30.0}), "2005/04/02 00:00:30.000");
}

}  // namespace
}  // namespace giocal

namespace giocal {
namespace {

TEST(GpsTime, TimeOfWeekNearAReferenceCrossesWeekEnds) {
  const double t = gpsSecondsFromWeekTime({2381, 604790.0});  // 10 s before the week ends
  EXPECT_DOUBLE_EQ(gpsSecondsNear(604790.0, t), t);
  EXPECT_DOUBLE_EQ(gpsSecondsNear(7200.0, t), gpsSecondsFromWeekTime({2382, 7200.0}));
  EXPECT_DOUBLE_EQ(gpsSecondsNear(590000.0, t + 20.0), gpsSecondsFromWeekTime({2381, 590000.0}));
}

}  // namespace
}  // namespace giocal

namespace giocal {
namespace {

TEST(GpsTime, CalendarTextWithoutDecimals) {
  const CalendarTime c{2024, 6, 24, 8, 20, 30.0};
  EXPECT_EQ(formatCalendar(c, 0), "2024/06/24 08:20:30");
  EXPECT_EQ(formatCalendar(c, 3), "2024/06/24 08:20:30.000");
}

}  // namespace
}  // namespace giocal
