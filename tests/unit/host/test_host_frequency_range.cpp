// Issue 18, item 6: host-mode FU/FD values that no radio can tune are answered with an error, and
// the radio is left as it was.
#include <doctest/doctest.h>

#include <memory>

#include "host/host_mode.h"
#include "support/sim_station.h"

using namespace tb;

TEST_CASE("FU / FD outside 1 MHz .. 6 GHz are refused with the frequency they would mean") {
  testing::StationFixture st;
  st.build_station();
  host::Interpreter host(*st.station);
  REQUIRE(host.execute("FD43590000").ok);
  const auto before = st.radio_sim->history().size();
  for (const char* bad : {"FD999999999", "FU14595", "FU99999"}) {
    INFO(bad);
    const host::Reply r = host.execute(bad);
    CHECK(!r.ok);
    REQUIRE(r.lines.size() == 1);
    CHECK(r.lines[0].find("which no radio here tunes: expected 1 MHz to 6 GHz") != std::string::npos);
  }
  CHECK(host.execute("FU14595").lines[0].find("0.14595 MHz") != std::string::npos);
  CHECK(st.radio_sim->history().size() == before);
  CHECK(st.radio_sim->frequency(radio::Link::downlink) == 435900000);
  CHECK(host.execute("FU100000").ok);      // 1 MHz, the lowest
  CHECK(host.execute("FD600000000").ok);   // 6 GHz, the highest
}
