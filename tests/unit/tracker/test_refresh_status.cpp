// The status line's word on the elements (issue 30): silent while they are current, and when every
// set is too old, how old and what to do, whatever state the refresh is in.
#include <doctest/doctest.h>

#include "tracker/elements_refresh.h"

using tb::tracker::RefreshState;
using tb::tracker::refresh_status_text;

TEST_CASE("refresh status: current elements say nothing unless a refresh just did something") {
  RefreshState s;
  s.has_sources = true;
  CHECK(refresh_status_text(s) == "");
  s.running = true;
  CHECK(refresh_status_text(s) == "");
  s.running = false;
  s.attempted = true;
  CHECK(refresh_status_text(s) == "");
  s.updated = 3;
  CHECK(refresh_status_text(s) == "ELEMENTS 3 UPDATED");
  s.failed = true;
  CHECK(refresh_status_text(s) == "ELEMENTS NOT REFRESHED, SEE MENU 3-5");
}

TEST_CASE("refresh status: old elements say their age and the refresh's state") {
  RefreshState s;
  s.stale_days = 190.3;
  CHECK(refresh_status_text(s) == "ELEMENTS 190 DAYS OLD, NO REFRESH SOURCE, SEE MENU 3-5");
  s.has_sources = true;
  CHECK(refresh_status_text(s) == "ELEMENTS 190 DAYS OLD, NO REFRESH SINCE START, SEE MENU 3-5");
  // Restarted within the interval of the last attempt: when the next one comes (whole hours, up).
  s.next_in_hours = 8.2;
  CHECK(refresh_status_text(s) == "ELEMENTS 190 DAYS OLD, NEXT REFRESH IN 9 H, SEE MENU 3-5");
  s.next_in_hours = 0.41;   // after a failed attempt: half an hour at most
  CHECK(refresh_status_text(s) == "ELEMENTS 190 DAYS OLD, NEXT REFRESH IN 25 MIN, SEE MENU 3-5");
  s.next_in_hours.reset();
  s.running = true;
  CHECK(refresh_status_text(s) == "ELEMENTS 190 DAYS OLD, REFRESHING");
  s.running = false;
  s.attempted = true;
  s.failed = true;
  CHECK(refresh_status_text(s) == "ELEMENTS 190 DAYS OLD, REFRESH FAILED, SEE MENU 3-5");
  s.failed = false;
  CHECK(refresh_status_text(s) == "ELEMENTS 190 DAYS OLD, SOURCE HAS NO NEWER, SEE MENU 3-5");
}
