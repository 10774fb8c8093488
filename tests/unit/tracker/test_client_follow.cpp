// ClientPassMatcher (tracker/client_follow.h): an outside client's targets matched with where the
// database's satellites are, the pass recognised after kRecogniseS of matching targets, a target
// matching none ending it. The sky positions are made up for the rule: the great-circle angles
// below are those of rotator::pointing_error_deg (tested against skyfield's separation in
// unit_rotator).
#include <doctest/doctest.h>

#include <vector>

#include "tracker/client_follow.h"

using namespace tb;
using tracker::ClientPassMatcher;
using tracker::SkyPosition;
using tracker::SkyTarget;

namespace {

const orbit::UtcTime kT0 = orbit::from_civil(2026, 5, 21, 3, 30, 0);
orbit::UtcTime at(double s) { return orbit::add_seconds(kT0, s); }

std::vector<SkyPosition> sky_with(double iss_az, double iss_el) {
  return {{0, "AO-07", 120.0, 40.0}, {3, "ISS", iss_az, iss_el}, {5, "SO-50", 300.0, -10.0}};
}

}  // namespace

TEST_CASE("client follow: an over-the-top target is the sky's direction az + 180, 180 - el") {
  const SkyTarget a = tracker::sky_target(100.0, 120.0);
  CHECK(a.az_deg == doctest::Approx(280.0));
  CHECK(a.el_deg == doctest::Approx(60.0));
  const SkyTarget b = tracker::sky_target(350.0, 100.0);
  CHECK(b.az_deg == doctest::Approx(170.0));
  CHECK(b.el_deg == doctest::Approx(80.0));
  const SkyTarget c = tracker::sky_target(350.0, 90.0);  // straight up: as it is
  CHECK(c.az_deg == doctest::Approx(350.0));
  CHECK(c.el_deg == doctest::Approx(90.0));
}

TEST_CASE("client follow: matched from the first target, recognised after 5 s and two targets, said once") {
  ClientPassMatcher m;
  auto r = m.feed("rotctld 127.0.0.1:4000", at(0), {10.0, 20.0}, sky_with(11.0, 21.0));
  REQUIRE(r);
  CHECK(r->db_index == 3);
  CHECK(r->name == "ISS");
  CHECK_FALSE(r->recognised);
  r = m.feed("rotctld 127.0.0.1:4000", at(4), {5.0, 25.0}, sky_with(5.5, 25.5));
  REQUIRE(r);
  CHECK_FALSE(r->recognised);  // 4 s only
  r = m.feed("rotctld 127.0.0.1:4000", at(8), {0.0, 28.0}, sky_with(359.0, 28.5));
  REQUIRE(r);
  CHECK(r->recognised);
  CHECK(r->newly_recognised);
  r = m.feed("rotctld 127.0.0.1:4000", at(12), {355.0, 30.0}, sky_with(355.0, 30.0));
  REQUIRE(r);
  CHECK(r->recognised);
  CHECK_FALSE(r->newly_recognised);
  CHECK(m.current()->name == "ISS");
}

TEST_CASE("client follow: the nearest satellite within 3 degrees; none beyond; a target matching none ends it") {
  ClientPassMatcher m;
  // AO-07 at 120/40 and ISS at 122/40 (1.53 deg apart at 40 deg elevation): the target 121.8/40 is ISS's.
  std::vector<SkyPosition> sky{{0, "AO-07", 120.0, 40.0}, {3, "ISS", 122.0, 40.0}};
  auto r = m.feed("c", at(0), {121.8, 40.0}, sky);
  REQUIRE(r);
  CHECK(r->name == "ISS");
  // 4 degrees off in elevation: no satellite's.
  CHECK_FALSE(m.feed("c", at(1), {122.0, 44.0}, sky));
  CHECK_FALSE(m.current());
  // Below -2 degrees a satellite is not matched; just below the horizon it is, at elevation 0.
  CHECK_FALSE(m.feed("c", at(2), {300.0, 0.0}, sky_with(10.0, 10.0)));
  sky = {{7, "FO-29", 45.0, -1.5}};
  r = m.feed("c", at(3), {45.0, 0.0}, sky);
  REQUIRE(r);
  CHECK(r->name == "FO-29");
}

TEST_CASE("client follow: near the zenith any azimuth matches") {
  ClientPassMatcher m;
  // 10/89.5 and 190/89.0 are 1.5 deg apart over the top.
  const std::vector<SkyPosition> sky{{2, "AO-91", 190.0, 89.0}};
  const auto r = m.feed("c", at(0), {10.0, 89.5}, sky);
  REQUIRE(r);
  CHECK(r->name == "AO-91");
}

TEST_CASE("client follow: another client, another satellite or a long silence starts the count again") {
  ClientPassMatcher m;
  m.feed("a", at(0), {10.0, 20.0}, sky_with(10.0, 20.0));
  CHECK(m.feed("a", at(6), {10.0, 20.0}, sky_with(10.0, 20.0))->recognised);
  auto r = m.feed("b", at(7), {10.0, 20.0}, sky_with(10.0, 20.0));
  CHECK_FALSE(r->recognised);
  CHECK(m.client() == "b");
  CHECK(m.feed("b", at(13), {10.0, 20.0}, sky_with(10.0, 20.0))->recognised);
  r = m.feed("b", at(14), {120.0, 40.0}, sky_with(10.0, 20.0));  // AO-07's now
  CHECK(r->name == "AO-07");
  CHECK_FALSE(r->recognised);
  CHECK(m.feed("b", at(20), {120.0, 40.0}, sky_with(10.0, 20.0))->recognised);
  r = m.feed("b", at(20 + ClientPassMatcher::kGapS + 1), {120.0, 40.0}, sky_with(10.0, 20.0));
  CHECK_FALSE(r->recognised);
}

TEST_CASE("client follow: a SatNOGS job's own elements are matched first") {
  ClientPassMatcher m;
  // The database's ISS 0.5 deg from the target, the job's ISS (older elements) 2 deg: the job's.
  std::vector<SkyPosition> sky{{3, "ISS", 100.5, 30.0}, {-2, "ISS", 102.0, 30.0, true}};
  auto r = m.feed("c", at(0), {100.0, 30.0}, sky);
  REQUIRE(r);
  CHECK(r->db_index == -2);
  // Beyond the tolerance a preferred one is not matched.
  sky[1].az_deg = 110.0;
  r = m.feed("c", at(1), {100.0, 30.0}, sky);
  REQUIRE(r);
  CHECK(r->db_index == 3);
}
