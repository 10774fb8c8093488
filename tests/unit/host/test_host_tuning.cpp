// Host mode's tuning and station commands (issue 47): PB, OR/OT, CT, ?T and QTH act through the
// same StationOps operations as the page, and refuse with the value named.
#include <doctest/doctest.h>

#include "host/host_mode.h"
#include "support/sim_station.h"
#include "tracker/operations.h"

using namespace tb;

TEST_CASE("host PB / OR / OT / CT / ?T on RS-44 a minute before its culmination") {
  testing::StationFixture st(orbit::from_civil(2026, 5, 21, 10, 57, 0));
  st.build_station();
  host::Interpreter host(*st.station);
  CHECK(host.execute("?T").lines[0] == "ERROR ?T: no satellite is tuned: track one first");
  REQUIRE(tracker::StationOps(*st.station).track("RS-44").ok());
  st.run(2.0);
  CHECK(host.execute("?T").lines[0] == "TUNE SPOT 435640000 145965000 RX +0 TX +0 TONE 0.0");
  CHECK(host.execute("PB435645000").ok);
  CHECK(host.execute("OT-250").ok);
  CHECK(host.execute("?T").lines[0] == "TUNE SPOT 435645000 145960000 RX +0 TX -250 TONE 0.0");
  CHECK(st.model.radio.tx_corrections.at("RS-44 SSB") == -250);
  CHECK(host.execute("PB435700000").lines[0] ==
        "ERROR PB: spot 435700000 Hz is outside RS-44's downlink passband 435610000-435670000 Hz");
  CHECK(host.execute("PB435.645").lines[0] == "ERROR PB: '435.645' is not a whole number of Hz, e.g. PB435640000");
  CHECK(host.execute("OR+999999").lines[0] == "ERROR OR: RX offset 999999 Hz out of range: expected -100000 to 100000");
  CHECK(host.execute("CT67.0").ok);
  CHECK(host.execute("?T").lines[0] == "TUNE SPOT 435645000 145960000 RX +0 TX -250 TONE 67.0");
  CHECK(host.execute("CTabc").lines[0] == "ERROR CT: 'abc' is not a tone: expected Hz such as CT67.0, or CT0 for none");
  CHECK(host.execute("OT0").ok);
  CHECK_FALSE(st.model.radio.tx_corrections.contains("RS-44 SSB"));
}

TEST_CASE("host QTH: a locator's centre or LAT,LON[,HEIGHT_M], stored as menu 4 would") {
  testing::StationFixture st;
  st.build_station();
  host::Interpreter host(*st.station);
  const host::Reply r = host.execute("QTH JN58td");
  REQUIRE(r.ok);
  CHECK(r.lines[0] == "QTH 48.1458, 11.6250, 0 m");
  CHECK(st.model.station.lat_deg == doctest::Approx(48.0 + 1.0 / 8 + 1.0 / 48).epsilon(1e-12));
  CHECK(host.execute("QTH 27.391,128.657,50").lines[0] == "QTH 27.3910, 128.6570, 50 m");
  // Read as --station reads it, refused with the settings table's sentence (store/settings.h).
  CHECK(host.execute("QTH 95,10").lines[0].rfind("ERROR QTH: station.lat_deg: 95 is outside -90 .. 90 deg in '95,10'", 0) == 0);
  CHECK(host.execute("QTH 1,2,12000").lines[0].rfind("ERROR QTH: station.height_m: 12000 is outside -500 .. 9000 m", 0) == 0);
  CHECK(host.execute("QTH somewhere").lines[0].rfind("ERROR QTH: expected LAT,LON[,HEIGHT_M] in degrees", 0) == 0);
  CHECK(st.model.station.lat_deg == 27.391);
  // Hemisphere letters as the command line takes them; no height given keeps the stored one.
  CHECK(host.execute("QTH 48.85N,2.35E").lines[0] == "QTH 48.8500, 2.3500, 50 m");
}
