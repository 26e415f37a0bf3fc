#include "common/time/gps_time.h"

#include <array>
#include <cmath>
#include <cstdio>

namespace giocal {

namespace {

// Days since 1970-01-01 of a proleptic Gregorian date (H. Hinnant's days_from_civil).
long daysFromCivil(long y, long m, long d) {
  y -= m <= 2 ? 1 : 0;
  const long era = (y >= 0 ? y : y - 399) / 400;
  const long yoe = y - era * 400;
  const long doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const long doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + doe - 719468;
}

void civilFromDays(long z, int& y, int& m, int& d) {
  z += 719468;
  const long era = (z >= 0 ? z : z - 146096) / 146097;
  const long doe = z - era * 146097;
  const long yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const long doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const long mp = (5 * doy + 2) / 153;
  d = static_cast<int>(doy - (153 * mp + 2) / 5 + 1);
  m = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
  y = static_cast<int>(yoe + era * 400 + (m <= 2 ? 1 : 0));
}

const long kGpsEpochDays = daysFromCivil(1980, 1, 6);

struct LeapEntry {
  int year, month;  // UTC date (day 1, 00:00:00) from which the count applies
  int gps_minus_utc;
};

// IERS Bulletin C history of leap seconds since the GPS epoch; no leap second after 2017-01-01
// had been announced when this table was written.
constexpr std::array<LeapEntry, 18> kLeapTable{{{1981, 7, 1},
                                                {1982, 7, 2},
                                                {1983, 7, 3},
                                                {1985, 7, 4},
                                                {1988, 1, 5},
                                                {1990, 1, 6},
                                                {1991, 1, 7},
                                                {1992, 7, 8},
                                                {1993, 7, 9},
                                                {1994, 7, 10},
                                                {1996, 1, 11},
                                                {1997, 7, 12},
                                                {1999, 1, 13},
                                                {2006, 1, 14},
                                                {2009, 1, 15},
                                                {2012, 7, 16},
                                                {2015, 7, 17},
                                                {2017, 1, 18}}};

double utcStartSeconds(const LeapEntry& e) {
  return static_cast<double>(daysSinceGpsEpoch(e.year, e.month, 1)) * kSecondsPerDay;
}

}  // namespace

long daysSinceGpsEpoch(int year, int month, int day) {
  return daysFromCivil(year, month, day) - kGpsEpochDays;
}

double gpsSecondsFromCalendar(const CalendarTime& c) {
  return static_cast<double>(daysSinceGpsEpoch(c.year, c.month, c.day)) * kSecondsPerDay +
         c.hour * 3600.0 + c.minute * 60.0 + c.second;
}

CalendarTime calendarFromGpsSeconds(double t) {
  const double days = std::floor(t / kSecondsPerDay);
  double sod = t - days * kSecondsPerDay;
  CalendarTime c;
  civilFromDays(static_cast<long>(days) + kGpsEpochDays, c.year, c.month, c.day);
  c.hour = static_cast<int>(sod / 3600.0);
  sod -= c.hour * 3600.0;
  c.minute = static_cast<int>(sod / 60.0);
  c.second = sod - c.minute * 60.0;
  return c;
}

GpsWeekTime weekTimeFromGpsSeconds(double t) {
  GpsWeekTime wt;
  wt.week = static_cast<int>(std::floor(t / kSecondsPerWeek));
  wt.tow = t - wt.week * kSecondsPerWeek;
  return wt;
}

double gpsSecondsFromWeekTime(const GpsWeekTime& wt) { return wt.week * kSecondsPerWeek + wt.tow; }

int leapSecondsAtUtc(double utc_seconds) {
  int leap = 0;
  for (const auto& e : kLeapTable) {
    if (utc_seconds >= utcStartSeconds(e)) leap = e.gps_minus_utc;
  }
  return leap;
}

int leapSecondsAtGps(double gps_seconds) {
  int leap = 0;
  for (const auto& e : kLeapTable) {
    // The new count starts at the UTC instant utcStart, which is GPS utcStart + new count.
    if (gps_seconds >= utcStartSeconds(e) + e.gps_minus_utc) leap = e.gps_minus_utc;
  }
  return leap;
}

double gpsFromUtcSeconds(double utc_seconds) { return utc_seconds + leapSecondsAtUtc(utc_seconds); }

double utcFromGpsSeconds(double gps_seconds) { return gps_seconds - leapSecondsAtGps(gps_seconds); }

std::string formatCalendar(const CalendarTime& c, int decimals) {
  // Round once on the total so that 59.9996 s becomes the next minute rather than "60.000".
  const double scale = std::pow(10.0, decimals);
  const double t = std::round(gpsSecondsFromCalendar(c) * scale) / scale;
  const CalendarTime r = calendarFromGpsSeconds(t);
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%04d/%02d/%02d %02d:%02d:%0*.*f", r.year, r.month, r.day, r.hour,
                r.minute, decimals > 0 ? decimals + 3 : 2, decimals,
                std::fabs(r.second) < 0.5 / scale ? 0.0 : r.second);
  return buf;
}

double gpsSecondsNear(double sow, double t_near) {
  const double t = gpsSecondsFromWeekTime({weekTimeFromGpsSeconds(t_near).week, sow});
  return t - kSecondsPerWeek * std::round((t - t_near) / kSecondsPerWeek);
}

}  // namespace giocal
