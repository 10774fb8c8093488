// An outside client's targets through the pass plan (issue 57), on the simulated station: a
// 450-degree North-stop rotator, HO-113's pass of 2026-05-21 03:27:11-03:41:41 at the factory
// station (8 -> 0 at 03:31:40 -> 200 deg). A rotctld client sends the satellite's position
// whenever it has moved more than 4 degrees (and is heard every second, as its `p` polls are). With the pass recognised, the first target (azimuth 8)
// goes to travel 368 and the pass is followed 368 -> 360 -> 200 with no target jumping more than a
// few degrees; the plain nearest way would go to 8 and swing 351 degrees at north. A SatNOGS job's
// own elements (tle0/1/2) are planned the same way when the database lacks the satellite.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "orbit/observe.h"
#include "support/sim_station.h"
#include "tracker/operations.h"

using namespace tb;

namespace {

const orbit::UtcTime kAos = orbit::from_civil(2026, 5, 21, 3, 27, 11);

struct Client : testing::StationFixture {
  Client() : StationFixture(orbit::add_seconds(kAos, 5.0)) {
    model.station.rotor_start = station::RotorStart::north;
    model.rotator.az_travel_deg = 450.0;
    build_station();
  }
  // The satellite's position from the station's engine (the elements the test gives).
  std::vector<double> travels;  // the rotator's target after each P
  void follow(const orbit::Sgp4& sat, double seconds) {
    std::optional<std::pair<double, double>> sent;
    const tracker::Requester who{tracker::HolderKind::rotctld, "rotctld 127.0.0.1:5000"};
    for (int s = 0; s < seconds; ++s) {
      const auto ob = orbit::observe(sat, model.station.observer(), now);
      REQUIRE(ob.ok());
      const double az = ob.look.az_deg, el = std::max(0.0, ob.look.el_deg);
      if (!sent || rotator::pointing_error_deg(az, el, sent->first, sent->second) > 4.0) {
        sent = {az, el};
        REQUIRE(tracker::StationOps(*station, who).go_to(az, el).ok());
        REQUIRE(station->rotator().status().target);
        travels.push_back(station->rotator().status().target->az_travel);
      }
      station->control().heard(who.label, now);  // its `p` of every second, as satnogs-client polls
      run(1.0);
    }
  }
  double largest_jump() const {
    double j = 0.0;
    for (std::size_t i = 1; i < travels.size(); ++i) j = std::max(j, std::abs(travels[i] - travels[i - 1]));
    return j;
  }
  const orbit::Sgp4& ho113() const { return *tracker.propagator(*model.db.find("HO-113")); }
};

}  // namespace

TEST_CASE("client plan: a rotctld client's HO-113 pass on the planned way round, through north without a swing") {
  Client c;
  c.follow(c.ho113(), 60 * 7);  // to 03:34:16, past north (03:31:40) and the culmination
  REQUIRE(c.travels.size() > 10);
  CHECK(c.travels.front() == doctest::Approx(368.1).epsilon(0.002));  // azimuth 8.1, the overlap's way
  CHECK(c.largest_jump() < 30.0);
  CHECK(*std::min_element(c.travels.begin(), c.travels.end()) < 360.0);  // went on past north
  CHECK(c.station->client_follow_text() ==
        "following rotctld's targets on the planned way round for HO-113 (pass to 03:42)");
  CHECK(c.station->status_line().find("following rotctld's targets") != std::string::npos);
}

TEST_CASE("client plan: a target matching no satellite goes the nearest way and ends it") {
  Client c;
  c.follow(c.ho113(), 90);  // the antenna is round at travel ~368 by then
  CHECK_FALSE(c.station->client_follow_text().empty());
  const tracker::Requester who{tracker::HolderKind::rotctld, "rotctld 127.0.0.1:5000"};
  REQUIRE(tracker::StationOps(*c.station, who).go_to(90.0, 45.0).ok());  // nobody's there
  CHECK(c.station->client_follow_text().empty());
  // From travel ~368 the nearest way to azimuth 90 is 450, not 90.
  CHECK(c.station->rotator().status().target->az_travel == doctest::Approx(450.0));
}

TEST_CASE("client plan: without the satellite in the database the same stream swings at north") {
  Client c;
  const orbit::Sgp4 sat(c.ho113().elements());
  c.model.db.satellites.erase(c.model.db.satellites.begin() + *c.model.db.find("HO-113"));
  c.follow(sat, 60 * 7);
  CHECK(c.travels.front() == doctest::Approx(8.1).epsilon(0.02));
  CHECK(c.largest_jump() > 300.0);
  CHECK(c.station->client_follow_text().empty());
}

TEST_CASE("client plan: a SatNOGS job's own elements plan its pass when the database lacks the satellite") {
  Client c;
  const orbit::Sgp4 sat(c.ho113().elements());
  c.model.db.satellites.erase(c.model.db.satellites.begin() + *c.model.db.find("HO-113"));
  tracker::Window w;
  w.kind = "satnogs";
  w.id = "4242";
  w.start = orbit::add_seconds(kAos, -60.0);
  w.end = orbit::add_seconds(kAos, 15 * 60.0);
  w.satellite = "HO-113";
  w.note = "FM 435800000 Hz";
  // data/amateur.tle's HO-113, as a job carries it.
  w.tle1 = "1 50466U 21131B   26141.25853896  .00000178  00000-0  68719-4 0  9990";
  w.tle2 = "2 50466  98.4967 233.7959 0004412 162.6945 197.4396 14.41327977231233";
  c.station->set_satnogs_windows({w});
  c.follow(sat, 60 * 7);
  CHECK(c.travels.front() == doctest::Approx(368.1).epsilon(0.002));
  CHECK(c.largest_jump() < 30.0);
  CHECK(c.station->client_follow_text() ==
        "following rotctld's targets on the planned way round for HO-113 (pass to 03:42)");
}

TEST_CASE("client plan: before a SatNOGS window the antenna goes to the start of the job's pass plan") {
  // 400 s before AOS, nothing tracked; the window opens 30 s before AOS.
  testing::StationFixture f(orbit::add_seconds(kAos, -400.0));
  f.model.station.rotor_start = station::RotorStart::north;
  f.model.rotator.az_travel_deg = 450.0;
  f.model.rotor_control = true;  // the station drives its rotator (off, nothing would move)
  f.build_station();
  tracker::Window w;
  w.kind = "satnogs";
  w.id = "4243";
  w.start = orbit::add_seconds(kAos, -30.0);
  w.end = orbit::add_seconds(kAos, 14 * 60.0);
  w.satellite = "HO-113";
  w.tle1 = "1 50466U 21131B   26141.25853896  .00000178  00000-0  68719-4 0  9990";
  w.tle2 = "2 50466  98.4967 233.7959 0004412 162.6945 197.4396 14.41327977231233";
  f.station->set_satnogs_windows({w});
  f.run(5.0);
  CHECK_FALSE(f.station->rotator().status().target);  // 6.2 min ahead: not yet
  f.run(200.0);
  REQUIRE(f.station->rotator().status().target);
  // The plan's start: HO-113 at its AOS (-2 deg: 03:26:37.1 at azimuth 8.42 by skyfield 1.49, the
  // same two lines) the overlap's way, travel 368.4.
  CHECK(f.station->rotator().status().target->az_travel == doctest::Approx(368.4).epsilon(0.002));
  CHECK(f.station->rotator().status().az.travel == doctest::Approx(368.4).epsilon(0.01));  // there before the window
  CHECK(f.now < w.start);
}

TEST_CASE("client plan: after the pass an antenna left a turn from the stop unwinds, unless a pass is due") {
  for (const bool job_due : {false, true}) {
    CAPTURE(job_due);
    Client c;
    c.follow(c.ho113(), 90);  // round at travel ~368 (azimuth ~8) when the client goes quiet
    REQUIRE(c.station->rotator().status().target);
    const double wound = c.station->rotator().status().target->az_travel;
    REQUIRE(wound > 360.5);
    if (job_due)  // a SatNOGS window 10 minutes after HO-113's LOS: its plan takes the antenna from there
      c.station->control().set_windows({{"satnogs", "4242", orbit::from_civil(2026, 5, 21, 3, 52, 0),
                                         orbit::from_civil(2026, 5, 21, 4, 0, 0), "AO-91", "", "", ""}});
    // The client is handed back by its silence; HO-113's pass goes on to LOS 03:41:41.
    c.run(orbit::minutes_between(c.now, orbit::from_civil(2026, 5, 21, 3, 41, 0)) * 60.0);
    CHECK(c.station->rotator().status().target->az_travel == doctest::Approx(wound));  // not before LOS
    c.run(120.0);
    const double after = c.station->rotator().status().target->az_travel;
    if (job_due) CHECK(after == doctest::Approx(wound));
    else CHECK(std::abs(after - (wound - 360.0)) < 0.5);  // where it stands (in the dead band), a turn back
  }
}
