#include <doctest/doctest.h>

#include "station/clock.h"

using namespace tb;
using orbit::from_civil;

TEST_CASE("RTC is the source plus a stored offset") {
  orbit::UtcTime source = from_civil(2026, 11, 21, 12, 0, 0);
  station::RealTimeClock rtc([&] { return source; });
  CHECK(rtc.now() == source);
  rtc.set(from_civil(1993, 7, 17, 3, 3, 15));
  source += std::chrono::seconds(10);
  CHECK(rtc.now() == from_civil(1993, 7, 17, 3, 3, 25));
  // The offset is what persists; a new clock with it reads the same time.
  station::RealTimeClock again([&] { return source; });
  again.set_offset(rtc.offset());
  CHECK(again.now() == rtc.now());
}

TEST_CASE("Zero-second adjust rounds to the nearest minute") {
  orbit::UtcTime source = from_civil(2026, 1, 1, 5, 13, 4);
  station::RealTimeClock rtc([&] { return source; });
  rtc.zero_seconds();
  CHECK(rtc.now() == from_civil(2026, 1, 1, 5, 13, 0));
  source = from_civil(2026, 1, 1, 5, 13, 45);
  rtc.zero_seconds();
  // 5:13:45 + (-4 s offset) = 5:13:41 -> 5:14:00
  CHECK(rtc.now() == from_civil(2026, 1, 1, 5, 14, 0));
}

TEST_CASE("Start time and rate for demonstrations") {
  orbit::UtcTime source = from_civil(2026, 11, 21, 12, 0, 0);
  station::RealTimeClock rtc([&] { return source; });
  rtc.start_at(from_civil(2018, 1, 21, 0, 0, 0), 10.0);
  CHECK(rtc.now() == from_civil(2018, 1, 21, 0, 0, 0));
  source += std::chrono::seconds(6);
  CHECK(rtc.now() == from_civil(2018, 1, 21, 0, 1, 0));
}
