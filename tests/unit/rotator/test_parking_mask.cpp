// Parking into the horizon mask (issue 57): the warning when the operator's parking position lies
// below the station's mask where it points; nothing with parking off, no mask, or above it.
#include <doctest/doctest.h>

#include "orbit/horizon_mask.h"
#include "rotator/parking_mask.h"

using tb::orbit::read_horizon_mask;
using tb::rotator::parking_mask_warning;
using tb::rotator::RotatorConfig;

namespace {

RotatorConfig parked_at(double az, double el, bool enabled = true) {
  RotatorConfig c;
  c.parking_enabled = enabled;
  c.parking = {az, el};
  return c;
}

// A roof to the south-west, 25 deg high from 190 to 230 (the step list of docs/rotator.md).
const tb::orbit::HorizonMask kRoof = *read_horizon_mask("0 0 190 25 230 0 360").mask;

}  // namespace

TEST_CASE("parking below the horizon mask is said, with where and how high the mask is there") {
  const auto w = parking_mask_warning(parked_at(200, 0), &kRoof);
  REQUIRE(w);
  CHECK(*w == "parking at azimuth 200.0, elevation 0.0 points into the horizon mask (25.0 there)");
  // Just under the roof's edge still counts; at its height it does not.
  CHECK(parking_mask_warning(parked_at(229.9, 24.9), &kRoof));
  CHECK_FALSE(parking_mask_warning(parked_at(200, 25), &kRoof));
}

TEST_CASE("parking clear of the mask, parking off, or no mask: nothing said") {
  CHECK_FALSE(parking_mask_warning(parked_at(230, 0), &kRoof));  // the roof ends at 230
  CHECK_FALSE(parking_mask_warning(parked_at(0, 0), &kRoof));
  CHECK_FALSE(parking_mask_warning(parked_at(200, 0, false), &kRoof));
  CHECK_FALSE(parking_mask_warning(parked_at(200, 0), nullptr));
}

TEST_CASE("an interpolated mask is read where the parking azimuth falls between its points") {
  const auto trees = *read_horizon_mask("0 25; 60 25; 90 0; 350 0").mask;
  const auto w = parking_mask_warning(parked_at(75, 10), &trees);  // 12.5 there
  REQUIRE(w);
  CHECK(*w == "parking at azimuth 75.0, elevation 10.0 points into the horizon mask (12.5 there)");
  CHECK_FALSE(parking_mask_warning(parked_at(75, 13), &trees));
}

TEST_CASE("a parking elevation over 90 on a flip rotator points over the top") {
  RotatorConfig c = parked_at(20, 175);  // looks at azimuth 200, elevation 5: into the roof
  c.el_flip_allowed = true;
  const auto w = parking_mask_warning(c, &kRoof);
  REQUIRE(w);
  CHECK(*w == "parking at azimuth 20.0, elevation 175.0 points into the horizon mask (25.0 there, at azimuth "
              "200.0 over the top)");
  c.parking.el = 150;  // elevation 30 over the top: above the roof
  CHECK_FALSE(parking_mask_warning(c, &kRoof));
}
