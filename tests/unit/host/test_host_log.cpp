// Host mode's LOG on a whole simulated station: the QSO filled from the pass being tracked
// (tracker::LogOps) and on disk before LOGGED is answered; refusals name the field.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "host/host_mode.h"
#include "logbook/lotw_names.h"
#include "support/sim_station.h"
#include "support/temp_logbook.h"
#include "test_paths.h"
#include "tracker/log_ops.h"
#include "tracker/operations.h"

using namespace tb;

namespace {
struct LoggingStation : testing::StationFixture, testing::TempLogbook {
  std::unique_ptr<host::Interpreter> host;
  LoggingStation() {
    build_station();
    open_logbook(*station, "hostlog");
    host = std::make_unique<host::Interpreter>(*station);
    station->tick();
  }
};
}  // namespace

TEST_CASE("LOG CALL GRID RST logs the pass's QSO: satellite, TQSL's name, mode, both links, time, my grid") {
  LoggingStation s;
  REQUIRE(s.logging.book);
  REQUIRE(tracker::StationOps(*s.station).track("RS-44").ok());
  s.run(2);  // 2026-05-21 12:00:02 UTC
  const auto r = s.host->execute("LOG w1aw fn31 59");
  REQUIRE(r.ok);
  REQUIRE(r.lines.size() == 2);
  CHECK(r.lines[0] == "LOGGED 1 W1AW RS-44 2026-05-21 12:00:02");
  // RS-44 is not up over the station at 12:00 (it rises at 21:25): stored, and said (issue 60).
  CHECK(r.lines[1].rfind("NOTE RS-44 was below the horizon here (-", 0) == 0);
  CHECK(r.lines[1].find("deg) at 12:00:02 UTC") != std::string::npos);
  const auto q = s.logging.book->get(1);
  REQUIRE(q);
  CHECK(q->call == "W1AW");
  CHECK(q->grid == "FN31");
  CHECK(q->rst_sent == "59");
  CHECK(q->sat_name == "RS-44");
  CHECK(q->lotw_name == "RS-44");
  CHECK(q->norad == 44909);
  CHECK(q->mode == "SSB");  // the freq/mode record's lsb uplink
  CHECK(q->uplink_hz == 145'965'000);
  CHECK(q->downlink_hz == 435'640'000);
  CHECK(q->band == "2m");
  CHECK(q->band_rx == "70cm");
  // RS-44 is below the horizon at 12:00: nothing has been sent to the radio, nothing as tuned.
  CHECK(q->uplink_tuned_hz == 0);
  CHECK(q->downlink_tuned_hz == 0);
  CHECK(q->my_grid == "PL47hj");  // the factory station 27.391 N 128.657 E, by hand
  CHECK(q->station_call.empty());   // the factory's NOCALL is no callsign
  CHECK(q->source == logbook::Source::host);
  CHECK(q->time_on == 1779364802);  // Python calendar.timegm((2026, 5, 21, 12, 0, 2))

  // In the pass: as tuned is what the simulated radio was sent, within RS-44's Doppler (at most
  // 3.4 kHz on 2 m and 10.2 kHz on 70 cm for its 7.3 km/s orbit seen from the ground).
  for (int i = 0; i < 24 * 60 && !s.station->tuner().last_sent_uplink_hz(); ++i) s.step(std::chrono::seconds(60));
  REQUIRE(s.station->tuner().last_sent_uplink_hz());
  REQUIRE(s.host->execute("LOG K1JT").ok);
  const auto p = s.logging.book->get(2);
  REQUIRE(p);
  CHECK(p->uplink_tuned_hz == *s.station->tuner().last_sent_uplink_hz());
  CHECK(p->downlink_tuned_hz == *s.station->tuner().last_sent_downlink_hz());
  CHECK(std::abs(p->uplink_tuned_hz - p->uplink_hz) < 3'400);
  CHECK(std::abs(p->downlink_tuned_hz - p->downlink_hz) < 10'200);
  CHECK(p->uplink_tuned_hz != p->uplink_hz);
}

TEST_CASE("LOG refusals name the field and store nothing") {
  LoggingStation s;
  s.run(1);
  // Nothing chosen yet (Stop no longer ends tracking, issue 44: it stops the rotator only).
  CHECK(s.host->execute("LOG W1AW").lines == std::vector<std::string>{"ERROR LOG: sat: no satellite is tracked; name one"});
  REQUIRE(tracker::StationOps(*s.station).track("ISS").ok());
  s.run(1);
  CHECK(s.host->execute("LOG").lines == std::vector<std::string>{"ERROR LOG: expected LOG CALL [GRID] [RST]"});
  const auto grid = s.host->execute("LOG W1AW FN3");
  CHECK_FALSE(grid.ok);
  REQUIRE(grid.lines.size() == 1);
  CHECK(grid.lines[0].rfind("ERROR LOG: grid: 'FN3' is not a Maidenhead locator", 0) == 0);
  CHECK(s.host->execute("LOG W1AW 66").lines ==
        std::vector<std::string>{"ERROR LOG: rst_sent: '66' is not a report (RS like 59 or RST like 599)"});
  CHECK(s.logging.book->count() == 0);
  // ISS is ARISS for LoTW.
  REQUIRE(tracker::StationOps(*s.station).track("ISS").ok());
  s.run(1);
  REQUIRE(s.host->execute("LOG K1JT").ok);
  CHECK(s.logging.book->get(1)->lotw_name == "ARISS");
  CHECK(s.logging.book->get(1)->mode == "FM");
}
