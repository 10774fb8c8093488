#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "orbit/time.h"

using namespace tb::orbit;

TEST_CASE("Julian date of known instants") {
  CHECK(julian_date(from_civil(2000, 1, 1, 12)).value() == doctest::Approx(2451545.0).epsilon(1e-15));
  CHECK(julian_date(from_civil(1970, 1, 1)).value() == 2440587.5);
  // Vallado example 3-4: 1996 Oct 26 14:20:00 UT -> JD 2450383.09722222
  CHECK(julian_date(from_civil(1996, 10, 26, 14, 20)).value() == doctest::Approx(2450383.09722222).epsilon(1e-13));
  const JulianDate jd = julian_date(from_civil(2026, 11, 21, 15, 16, 24.5));
  CHECK(jd.whole == 2461365.5);
  CHECK(jd.fraction == doctest::Approx((15 * 3600 + 16 * 60 + 24.5) / 86400.0).epsilon(1e-15));
}

TEST_CASE("Julian date round trip keeps microseconds") {
  const UtcTime t = from_civil(2026, 3, 1, 23, 59, 59.999999);
  CHECK(from_julian_date(julian_date(t)) == t);
  const UtcTime before = from_civil(1957, 10, 4, 19, 28, 34.123456);
  CHECK(from_julian_date(julian_date(before)) == before);
}

TEST_CASE("DUT1 offset renormalises across midnight") {
  const JulianDate jd = julian_date(from_civil(2020, 1, 1, 23, 59, 59.9), 0.5);
  CHECK(jd.whole == julian_date(from_civil(2020, 1, 2)).whole);
  CHECK(jd.fraction * 86400.0 == doctest::Approx(0.4).epsilon(1e-9));
}

TEST_CASE("GMST-82: Vallado example 3-5") {
  // 1992 Aug 20 12:14:00 UT1 -> GMST 152.578787886 deg in the book. Skyfield's theta_GMST1982,
  // which like ours keeps the Julian date split, gives 152.57878785165747; Vallado's gstime sums the
  // date into one double first and lands 4e-8 deg away (152.57878781032736).
  constexpr double deg = 180.0 / std::numbers::pi;
  const double g = gmst82(julian_date(from_civil(1992, 8, 20, 12, 14))) * deg;
  CHECK(std::abs(g - 152.57878785165747) < 1e-9);
  CHECK(std::abs(g - 152.578787886) < 1e-7);
  CHECK(std::abs(gmst82({2461365.5, 0.3}) * deg - 168.3063012452857) < 1e-9);
}

TEST_CASE("Element-set epochs") {
  CHECK(expand_two_digit_year(56) == 2056);
  CHECK(expand_two_digit_year(57) == 1957);
  CHECK(expand_two_digit_year(0) == 2000);
  CHECK(expand_two_digit_year(99) == 1999);
  // Day 1.5 is Jan 1 noon; day 366.0 of a leap year is Dec 31 00:00.
  CHECK(from_year_day(2024, 1.5) == from_civil(2024, 1, 1, 12));
  CHECK(from_year_day(2024, 366.0) == from_civil(2024, 12, 31));
  CHECK(day_of_year(from_civil(2024, 12, 31, 23)) == 366);
  CHECK(day_of_year(from_civil(1993, 7, 17)) == 198);
}

TEST_CASE("Civil time round trip and ISO 8601") {
  const UtcTime t = from_civil(1993, 7, 17, 4, 6, 58.25);
  const CivilTime c = to_civil(t);
  CHECK(c.year == 1993);
  CHECK(c.month == 7);
  CHECK(c.day == 17);
  CHECK(c.hour == 4);
  CHECK(c.minute == 6);
  CHECK(c.second == 58.25);
  CHECK(format_iso8601(t) == "1993-07-17T04:06:58Z");
  CHECK(format_iso8601(t, 3) == "1993-07-17T04:06:58.250Z");
  CHECK(format_iso8601(from_civil(1999, 12, 31, 23, 59, 59.6)) == "2000-01-01T00:00:00Z");
  CHECK(parse_iso8601("1993-07-17T04:06:58.25Z") == t);
  CHECK(parse_iso8601("1993-07-17 04:06:58.25") == t);
  CHECK(parse_iso8601("1993-07-17") == from_civil(1993, 7, 17));
  CHECK(parse_iso8601("2024-02-30T00:00:00Z") == std::nullopt);
  CHECK(parse_iso8601("2024-02-29T24:00:00Z") == std::nullopt);
  CHECK(parse_iso8601("2024-02-29T12:00:00+05:00") == std::nullopt);
  CHECK(parse_iso8601("yesterday") == std::nullopt);
  CHECK(minutes_between(from_civil(2024, 1, 1), from_civil(2024, 1, 2)) == 1440.0);
  CHECK(add_minutes(from_civil(2024, 1, 1), -0.5) == from_civil(2023, 12, 31, 23, 59, 30));
}
