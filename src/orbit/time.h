// UTC time points, Julian dates, sidereal time.
// A UtcTime is POSIX time (UTC without leap seconds) at microsecond resolution: what the system
// clock gives, what an element set's epoch means, what every display shows.
#pragma once
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace tb::orbit {

using UtcTime = std::chrono::sys_time<std::chrono::microseconds>;
using Seconds = std::chrono::duration<double>;

// A Julian date split in two so that sums keep sub-microsecond precision:
// whole is a day boundary (ends in .5), fraction is in [0, 1).
struct JulianDate {
  double whole = 0.0;
  double fraction = 0.0;
  double value() const { return whole + fraction; }
};

inline constexpr double kJdUnixEpoch = 2440587.5;   // 1970-01-01T00:00:00Z
inline constexpr double kJdJ2000 = 2451545.0;       // 2000-01-01T12:00:00 TT (used as UT1 here)
inline constexpr double kMinutesPerDay = 1440.0;
inline constexpr double kSecondsPerDay = 86400.0;

JulianDate julian_date(UtcTime t);
// Adds an offset in seconds (DUT1 = UT1 - UTC) and renormalises.
JulianDate julian_date(UtcTime t, double offset_s);
UtcTime from_julian_date(JulianDate jd);
// Minutes from a to b (b - a).
double minutes_between(UtcTime a, UtcTime b);
UtcTime add_minutes(UtcTime t, double minutes);
UtcTime add_seconds(UtcTime t, double seconds);

struct CivilTime {
  int year = 1970, month = 1, day = 1, hour = 0, minute = 0;
  double second = 0.0;  // [0, 60)
};
UtcTime from_civil(const CivilTime& c);
UtcTime from_civil(int year, int month, int day, int hour = 0, int minute = 0, double second = 0.0);
CivilTime to_civil(UtcTime t);
int day_of_year(UtcTime t);  // 1 = January 1
// Gregorian leap years (2000 is one, 1900 is not).
constexpr bool is_leap_year(int year) { return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0; }

// An element-set epoch: four-digit year and day of year with fraction (1.0 = Jan 1 00:00:00).
UtcTime from_year_day(int year, double day_of_year);
// Expands a two-digit element-set year: < 57 is 20YY, otherwise 19YY.
int expand_two_digit_year(int yy);

// Greenwich mean sidereal time, IAU-82 (as used with SGP4's TEME frame), in radians [0, 2pi).
double gmst82(JulianDate jd_ut1);

// ISO 8601: "2026-11-21T15:16:24Z" (decimals > 0 adds fractional seconds).
std::string format_iso8601(UtcTime t, int decimals = 0);
// Accepts YYYY-MM-DD, YYYY-MM-DDTHH:MM[:SS[.fff]] with optional Z or +00:00, space for T.
std::optional<UtcTime> parse_iso8601(std::string_view text);

}  // namespace tb::orbit
