#include "orbit/time.h"

#include <cmath>
#include <cstdio>

#include "orbit/constants.h"
#include "util/civil_date.h"
#include "util/text.h"

namespace tb::orbit {
namespace {

constexpr double kUsPerDay = 86400.0e6;

using civil::days_from_civil;
using Ymd = civil::Date;
using civil::civil_from_days;

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  std::int64_t q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return q;
}

}  // namespace

JulianDate julian_date(UtcTime t) {
  const std::int64_t us = t.time_since_epoch().count();
  const std::int64_t day = floor_div(us, static_cast<std::int64_t>(kUsPerDay));
  const std::int64_t rem = us - day * static_cast<std::int64_t>(kUsPerDay);
  return {kJdUnixEpoch + static_cast<double>(day), static_cast<double>(rem) / kUsPerDay};
}

JulianDate julian_date(UtcTime t, double offset_s) {
  JulianDate jd = julian_date(t);
  jd.fraction += offset_s / kSecondsPerDay;
  const double shift = std::floor(jd.fraction);
  jd.whole += shift;
  jd.fraction -= shift;
  return jd;
}

UtcTime from_julian_date(JulianDate jd) {
  const double days = (jd.whole - kJdUnixEpoch) + jd.fraction;
  const double whole_days = std::floor(days);
  const double frac = days - whole_days;
  const auto us = static_cast<std::int64_t>(whole_days) * static_cast<std::int64_t>(kUsPerDay) +
                  static_cast<std::int64_t>(std::llround(frac * kUsPerDay));
  return UtcTime(std::chrono::microseconds(us));
}

double minutes_between(UtcTime a, UtcTime b) {
  return static_cast<double>((b - a).count()) / 60.0e6;
}

UtcTime add_minutes(UtcTime t, double minutes) {
  return t + std::chrono::microseconds(std::llround(minutes * 60.0e6));
}

UtcTime add_seconds(UtcTime t, double seconds) {
  return t + std::chrono::microseconds(std::llround(seconds * 1.0e6));
}

UtcTime from_civil(const CivilTime& c) {
  const std::int64_t days = days_from_civil(c.year, static_cast<unsigned>(c.month), static_cast<unsigned>(c.day));
  const std::int64_t us = days * static_cast<std::int64_t>(kUsPerDay) +
                          (static_cast<std::int64_t>(c.hour) * 3600 + c.minute * 60) * 1000000LL +
                          std::llround(c.second * 1.0e6);
  return UtcTime(std::chrono::microseconds(us));
}

UtcTime from_civil(int year, int month, int day, int hour, int minute, double second) {
  return from_civil(CivilTime{year, month, day, hour, minute, second});
}

CivilTime to_civil(UtcTime t) {
  const std::int64_t us = t.time_since_epoch().count();
  const std::int64_t day = floor_div(us, static_cast<std::int64_t>(kUsPerDay));
  std::int64_t rem = us - day * static_cast<std::int64_t>(kUsPerDay);
  const Ymd ymd = civil_from_days(day);
  CivilTime c;
  c.year = static_cast<int>(ymd.y);
  c.month = static_cast<int>(ymd.m);
  c.day = static_cast<int>(ymd.d);
  c.hour = static_cast<int>(rem / 3600000000LL);
  rem -= static_cast<std::int64_t>(c.hour) * 3600000000LL;
  c.minute = static_cast<int>(rem / 60000000LL);
  rem -= static_cast<std::int64_t>(c.minute) * 60000000LL;
  c.second = static_cast<double>(rem) / 1.0e6;
  return c;
}

int day_of_year(UtcTime t) {
  const CivilTime c = to_civil(t);
  return static_cast<int>(days_from_civil(c.year, static_cast<unsigned>(c.month), static_cast<unsigned>(c.day)) -
                          days_from_civil(c.year, 1, 1)) + 1;
}

UtcTime from_year_day(int year, double day_of_year) {
  const std::int64_t jan1 = days_from_civil(year, 1, 1);
  const double us = (day_of_year - 1.0) * kUsPerDay;
  return UtcTime(std::chrono::microseconds(jan1 * static_cast<std::int64_t>(kUsPerDay) + std::llround(us)));
}

int expand_two_digit_year(int yy) { return yy < 57 ? 2000 + yy : 1900 + yy; }

double gmst82(JulianDate jd_ut1) {
  // Vallado, "Fundamentals of Astrodynamics and Applications", eq. 3-47 (IAU-82), as in SGP4's gstime.
  const double tut1 = ((jd_ut1.whole - kJdJ2000) + jd_ut1.fraction) / 36525.0;
  double temp = -6.2e-6 * tut1 * tut1 * tut1 + 0.093104 * tut1 * tut1 +
                (876600.0 * 3600.0 + 8640184.812866) * tut1 + 67310.54841;  // seconds
  temp = std::fmod(temp * kDegToRad / 240.0, kTwoPi);
  if (temp < 0.0) temp += kTwoPi;
  return temp;
}

std::string format_iso8601(UtcTime t, int decimals) {
  const CivilTime c = to_civil(t);
  char buf[64];
  if (decimals <= 0) {
    const auto us = t.time_since_epoch().count();
    // Round to the nearest second without carrying into minutes by hand: reformat the rounded time.
    const std::int64_t rounded = floor_div(us + 500000, 1000000) * 1000000;
    if (rounded != us) return format_iso8601(UtcTime(std::chrono::microseconds(rounded)), 0);
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02dZ", c.year, c.month, c.day, c.hour, c.minute,
                  static_cast<int>(c.second));
  } else {
    const int width = 3 + decimals;
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%0*.*fZ", c.year, c.month, c.day, c.hour, c.minute,
                  width, decimals, c.second);
  }
  return buf;
}

std::optional<UtcTime> parse_iso8601(std::string_view s) {
  auto digits = [&](std::size_t pos, std::size_t n, int& out) {
    if (pos + n > s.size()) return false;
    int v = 0;
    for (std::size_t i = pos; i < pos + n; ++i) {
      if (!text::is_digit(s[i])) return false;
      v = v * 10 + (s[i] - '0');
    }
    out = v;
    return true;
  };
  CivilTime c;
  if (!digits(0, 4, c.year) || s.size() < 10 || s[4] != '-' || !digits(5, 2, c.month) || s[7] != '-' ||
      !digits(8, 2, c.day))
    return std::nullopt;
  std::size_t pos = 10;
  if (pos < s.size() && (s[pos] == 'T' || s[pos] == 't' || s[pos] == ' ')) {
    ++pos;
    if (!digits(pos, 2, c.hour) || pos + 2 >= s.size() || s[pos + 2] != ':' || !digits(pos + 3, 2, c.minute))
      return std::nullopt;
    pos += 5;
    if (pos < s.size() && s[pos] == ':') {
      int sec = 0;
      if (!digits(pos + 1, 2, sec)) return std::nullopt;
      pos += 3;
      double frac = 0.0, scale = 0.1;
      if (pos < s.size() && s[pos] == '.') {
        ++pos;
        const std::size_t start = pos;
        while (pos < s.size() && text::is_digit(s[pos])) {
          frac += (s[pos] - '0') * scale;
          scale /= 10.0;
          ++pos;
        }
        if (pos == start) return std::nullopt;
      }
      c.second = sec + frac;
    }
  }
  if (pos < s.size()) {
    const std::string_view zone = s.substr(pos);
    if (zone != "Z" && zone != "z" && zone != "+00:00" && zone != "+0000" && zone != "-00:00") return std::nullopt;
  }
  auto days_in_month = [](int y, int m) {
    static constexpr int d[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    return m == 2 && is_leap_year(y) ? 29 : d[m - 1];
  };
  if (c.month < 1 || c.month > 12 || c.day < 1 || c.day > days_in_month(c.year, c.month) || c.hour > 23 ||
      c.minute > 59 || c.second >= 60.0)
    return std::nullopt;
  return from_civil(c);
}

}  // namespace tb::orbit
