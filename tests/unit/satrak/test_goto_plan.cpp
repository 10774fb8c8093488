// Issue 57 on the Satrak unit: a GOTO stream that follows a pass goes the pass plan's way round.
// HO-113's pass of 2026-05-21 03:27:11-03:41:41 at the factory station (8 -> 0 at 03:31:40 -> 200
// deg) on a 450-degree North-stop rotator: the first GOTO (azimuth 8.1) is commanded to travel
// 368.1 and the pass is followed down through north with no commanded jump over a few degrees,
// where the nearest way would go to 8 and swing 351 degrees round at north.
#include "fixture.h"

#include <algorithm>
#include <cmath>

#include "orbit/observe.h"

using namespace satrak_test;
using namespace std::chrono_literals;

namespace {

store::Model factory_450() {
  store::Model m = tb::testing::shipped_model();  // the factory station, 27.391 N 128.657 E
  m.station.rotor_start = station::RotorStart::north;
  m.rotator.az_travel_deg = 450.0;
  m.rotor_control = true;
  return m;
}

}  // namespace

TEST_CASE("GOTO stream of a pass: on the planned way round through north (issue 57)") {
  const orbit::UtcTime aos = orbit::from_civil(2026, 5, 21, 3, 27, 16);
  Acu acu(aos, {}, factory_450());
  const orbit::Sgp4& sat = *acu.tracker.propagator(*acu.model.db.find("HO-113"));
  std::vector<double> travels;
  std::optional<std::pair<double, double>> sent;
  for (int s = 0; s < 7 * 60; ++s) {
    const auto ob = orbit::observe(sat, acu.model.station.observer(), acu.clock.now());
    REQUIRE(ob.ok());
    const double az = ob.look.az_deg, el = std::max(0.0, ob.look.el_deg);
    if (!sent || rotator::pointing_error_deg(az, el, sent->first, sent->second) > 4.0) {
      sent = {az, el};
      REQUIRE(acu.cmd("GOTO=," + tb::satrak::format_fixed(az, 2) + "," + tb::satrak::format_fixed(el, 2)) ==
              "GOTO=,OK");
      REQUIRE(acu.rs().target);
      travels.push_back(acu.rs().target->az_travel);
    }
    acu.cmd("STATUS?");  // a client that polls keeps its hold
    acu.run(1s);
  }
  REQUIRE(travels.size() > 10);
  CHECK(travels.front() == doctest::Approx(368.1).epsilon(0.002));
  double jump = 0.0;
  for (std::size_t i = 1; i < travels.size(); ++i) jump = std::max(jump, std::abs(travels[i] - travels[i - 1]));
  CHECK(jump < 30.0);
  CHECK(*std::min_element(travels.begin(), travels.end()) < 360.0);  // past north
  CHECK(acu.loop->client_follow_text() ==
        "following satrak's targets on the planned way round for HO-113 (pass to 03:42)");
}
