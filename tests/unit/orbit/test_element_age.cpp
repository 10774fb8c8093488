// Element age and its warning (orbit/element_age.h).
#include <doctest/doctest.h>

#include "orbit/element_age.h"

using namespace tb::orbit;

namespace {
Elements at_epoch(double mean_motion) {
  Elements e;
  e.epoch_year = 2026;
  e.epoch_day = 141.0;  // 2026-05-21 00:00 UTC
  e.mean_motion_rev_per_day = mean_motion;
  return e;
}
}  // namespace

TEST_CASE("A low orbit's set is trusted for 14 days either side of its epoch, a high orbit's for 30") {
  const Elements iss = at_epoch(15.49), qo100 = at_epoch(1.0027);
  const UtcTime epoch = from_civil(2026, 5, 21, 0, 0, 0);
  CHECK(element_age(iss, epoch).days == 0.0);
  CHECK(element_age(iss, add_seconds(epoch, 14 * 86400.0)).stale() == false);
  CHECK(element_age(iss, add_seconds(epoch, 14 * 86400.0 + 1)).stale());
  CHECK(element_age(iss, add_seconds(epoch, -15 * 86400.0)).stale());
  CHECK(element_age(qo100, add_seconds(epoch, 29 * 86400.0)).stale() == false);
  CHECK(element_age(qo100, add_seconds(epoch, 31 * 86400.0)).stale());
  // The boundary is SGP4's: a period of 225 minutes (6.4 rev/day) is no longer low.
  CHECK(element_age(at_epoch(6.41), epoch).low_orbit);
  CHECK_FALSE(element_age(at_epoch(6.4), epoch).low_orbit);
}

TEST_CASE("The age says itself, and its warning names the limit") {
  const Elements iss = at_epoch(15.49);
  const UtcTime epoch = from_civil(2026, 5, 21, 0, 0, 0);
  CHECK(element_age(iss, add_seconds(epoch, 0.3 * 86400)).text() == "0.3 days");
  CHECK(element_age(iss, add_seconds(epoch, 0.3 * 86400)).warning().empty());
  CHECK(element_age(iss, add_seconds(epoch, -5 * 86400.0)).text() == "5.0 days before epoch");
  // Five years on, as the issue measured: 1826 days.
  const auto old = element_age(iss, from_civil(2031, 5, 21, 0, 0, 0));
  CHECK(old.days == 1826.0);
  CHECK(old.warning() == "elements 1826.0 days old (more than 14 for a low orbit): positions are unreliable");
  CHECK(element_age(at_epoch(1.0027), from_civil(2021, 5, 21, 0, 0, 0)).warning() ==
        "elements 1826.0 days before their epoch (more than 30 for a high orbit): positions are unreliable");
}
