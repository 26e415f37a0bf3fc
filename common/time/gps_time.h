// GPS time: continuous seconds since 1980-01-06 00:00:00, week/seconds-of-week, calendar and UTC.
#pragma once

#include <string>

namespace giocal {

/// A calendar date and time of day in one time scale (GPS or UTC; the caller knows which).
struct CalendarTime {
  int year = 1980;
  int month = 1;
  int day = 6;
  int hour = 0;
  int minute = 0;
  double second = 0.0;
};

/// GPS week number (continuous, not modulo 1024) and seconds of week.
struct GpsWeekTime {
  int week = 0;
  double tow = 0.0;
};

constexpr double kSecondsPerWeek = 604800.0;
constexpr double kSecondsPerDay = 86400.0;

/// Days from 1980-01-06 to the given date of the proleptic Gregorian calendar.
long daysSinceGpsEpoch(int year, int month, int day);

/// Seconds since the GPS epoch of a calendar time expressed in the GPS time scale.
double gpsSecondsFromCalendar(const CalendarTime& c);

/// Calendar time in the GPS time scale of seconds since the GPS epoch.
CalendarTime calendarFromGpsSeconds(double t);

GpsWeekTime weekTimeFromGpsSeconds(double t);
double gpsSecondsFromWeekTime(const GpsWeekTime& wt);

/// The GPS time of a time of week `sow` in the week that puts it within half a week of `t_near`
/// (navigation messages give times of week whose week the receiver's time tells).
double gpsSecondsNear(double sow, double t_near);

/// GPS - UTC in seconds (leap seconds since 1980) at a UTC instant, given as seconds since
/// 1980-01-06 00:00:00 counted in the UTC scale.
int leapSecondsAtUtc(double utc_seconds);

/// GPS - UTC at a GPS instant. Inside an inserted leap second the UTC clock reads 23:59:60,
/// which the continuous UTC count cannot express; such instants map to the following 00:00:00.
int leapSecondsAtGps(double gps_seconds);

double gpsFromUtcSeconds(double utc_seconds);
double utcFromGpsSeconds(double gps_seconds);

/// "yyyy/mm/dd hh:mm:ss.sss" of a calendar time (RTKLIB solution format), rounded to ms.
std::string formatCalendar(const CalendarTime& c, int decimals = 3);

}  // namespace giocal
