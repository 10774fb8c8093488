// Passes above a horizon mask (orbit::find_passes_masked): HO-113's pass of 2026-05-21 at the
// factory station (27.391 N, 128.657 E, 50 m) with a 25-degree sector from 190 to 230 degrees. The
// expected times are skyfield 1.49's (EarthSatellite from the same two lines, wgs84.latlon, altaz;
// the crossing of el - mask(az) = 0 by scipy's brentq): AOS 03:27:11.394 at azimuth 8.09 (the mask
// is 0 there), LOS 03:37:20.080 at azimuth 208.38, elevation 25.0, where the satellite goes behind
// the sector (without the mask it sets at 03:41:41).
#include <doctest/doctest.h>

#include <cmath>

#include "orbit/elements.h"
#include "orbit/horizon_mask.h"
#include "orbit/passes.h"

using namespace tb::orbit;

namespace {

constexpr const char* kHo113 =
    "HO-113\n"
    "1 50466U 21131B   26141.25853896  .00000178  00000-0  68719-4 0  9990\n"
    "2 50466  98.4967 233.7959 0004412 162.6945 197.4396 14.41327977231233\n";  // data/amateur.tle

double seconds_from(UtcTime a, UtcTime b) { return minutes_between(a, b) * 60.0; }

}  // namespace

TEST_CASE("masked passes: AOS and LOS at the mask, the sector cuts the pass short") {
  const auto sets = parse_nasa(kHo113);
  REQUIRE(sets.sets.size() == 1);
  const Sgp4 sat(sets.sets[0]);
  const Observer here{27.391, 128.657, 50.0};
  const auto mask = read_horizon_mask("0 0 190 25 230 0 360");
  REQUIRE(mask.mask);
  PassOptions po;
  po.horizon_deg = 0.0;
  const UtcTime from = from_civil(2026, 5, 21, 3, 20, 0), to = from_civil(2026, 5, 21, 3, 50, 0);
  const auto plain = find_passes(sat, here, from, to, po);
  REQUIRE(plain.size() == 1);
  CHECK(std::abs(seconds_from(from_civil(2026, 5, 21, 3, 41, 41), plain[0].los)) < 1.0);
  const auto masked = find_passes_masked(sat, here, from, to, *mask.mask, po);
  REQUIRE(masked.size() == 1);
  const Pass& p = masked[0];
  CHECK(std::abs(seconds_from(from_civil(2026, 5, 21, 3, 27, 11.394), p.aos)) < 0.5);
  CHECK(std::abs(seconds_from(from_civil(2026, 5, 21, 3, 37, 20.080), p.los)) < 0.5);
  CHECK(p.aos_az_deg == doctest::Approx(8.09).epsilon(0.002));
  CHECK(p.los_az_deg == doctest::Approx(208.38).epsilon(0.001));
  CHECK(p.tca == plain[0].tca);  // the culmination is inside what the mask leaves
  CHECK(p.max_el_deg == doctest::Approx(plain[0].max_el_deg));
}

TEST_CASE("masked passes: a mask above the whole pass leaves none; a minimum culmination drops low pieces") {
  const auto sets = parse_nasa(kHo113);
  const Sgp4 sat(sets.sets[0]);
  const Observer here{27.391, 128.657, 50.0};
  const UtcTime from = from_civil(2026, 5, 21, 3, 20, 0), to = from_civil(2026, 5, 21, 3, 50, 0);
  const auto high = read_horizon_mask("0 70\n180 70\n");
  REQUIRE(high.mask);
  CHECK(find_passes_masked(sat, here, from, to, *high.mask).empty());
  const auto low = read_horizon_mask("0 0\n180 0\n");
  PassOptions po;
  po.min_max_elevation_deg = 70.0;  // the pass culminates at 66.6
  CHECK(find_passes_masked(sat, here, from, to, *low.mask, po).empty());
}

TEST_CASE("masked passes: next_pass and find_passes take the mask from the options (the station's one path)") {
  const auto sets = parse_nasa(kHo113);
  const Sgp4 sat(sets.sets[0]);
  const Observer here{27.391, 128.657, 50.0};
  const auto mask = read_horizon_mask("0 0 190 25 230 0 360");
  REQUIRE(mask.mask);
  PassOptions po;
  po.horizon_deg = 0.0;
  po.mask = std::make_shared<const HorizonMask>(*mask.mask);
  const UtcTime from = from_civil(2026, 5, 21, 3, 20, 0);
  const auto next = next_pass(sat, here, from, 1.0, po);
  REQUIRE(next);
  // The same skyfield crossings as above.
  CHECK(std::abs(seconds_from(from_civil(2026, 5, 21, 3, 27, 11.394), next->aos)) < 0.5);
  CHECK(std::abs(seconds_from(from_civil(2026, 5, 21, 3, 37, 20.080), next->los)) < 0.5);
  const auto found = find_passes(sat, here, from, from_civil(2026, 5, 21, 3, 50, 0), po);
  REQUIRE(found.size() == 1);
  CHECK(found[0].los == next->los);
  // The horizon at an azimuth: the mask where it is higher, the scalar horizon elsewhere.
  CHECK(horizon_at(po, 210.0) == doctest::Approx(25.0));
  CHECK(horizon_at(po, 100.0) == doctest::Approx(0.0));
  po.mask.reset();
  CHECK(horizon_at(po, 210.0) == doctest::Approx(0.0));
  // From inside the masked pass (behind nothing yet): the piece left, from then.
  po.mask = std::make_shared<const HorizonMask>(*mask.mask);
  const auto inside = next_pass(sat, here, from_civil(2026, 5, 21, 3, 30, 0), 1.0, po);
  REQUIRE(inside);
  CHECK(inside->up_at_start);
  CHECK(std::abs(seconds_from(from_civil(2026, 5, 21, 3, 37, 20.080), inside->los)) < 0.5);
}
