// HamlibRadio against real Hamlib peers: rigctld -m 1 (the dummy rig) on a free loopback port,
// driven through the NET rigctl backend; read back with rigctl -m 2 and rigctld's own protocol.
// Killing and restarting the daemon exercises the fault report and the reconnect.
#include <doctest/doctest.h>

#include "radio/factory.h"
#include "radio/hamlib/hamlib_radio.h"
#include "radio/hamlib/rigctld_link.h"
#include "support.h"

using namespace tb::radio;
using namespace std::chrono_literals;
using tbtest::eventually;

// Hamlib 4.5.4's rig_open() for the NET rigctl backend leaks two small blocks (512 + 240 bytes)
// on connections that rig_close()/rig_cleanup() never free; a ten-line C program
// calling only rig_init/rig_open/rig_close/rig_cleanup shows the same. It is not ours to fix, so
// LeakSanitizer is told to ignore leaks allocated inside libhamlib (and nowhere else).
extern "C" const char* __lsan_default_suppressions() { return "leak:libhamlib.so\n"; }

namespace {

std::unique_ptr<tbtest::Child> start_rigctld(int port, bool vfo_mode = false) {
  std::vector<std::string> args{*tbtest::which("rigctld"), "-m", "1", "-T", "127.0.0.1", "-t", std::to_string(port)};
  if (vfo_mode) args.push_back("--vfo");
  auto child = std::make_unique<tbtest::Child>(args, false);
  if (!child->started() || !eventually([&] { return tbtest::tcp_connectable(port); }, 5000ms))
    return nullptr;
  return child;
}

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  return s;
}

// The main (RX) VFO as Hamlib's own client reads it.
std::string rigctl_f(int port) {
  std::string f;
  for (int attempt = 0; attempt < 3 && f.empty(); ++attempt)  // rigctld's occasional reset: tcp_exchange
    f = trim(tbtest::run_capture("timeout 10 rigctl -m 2 -r 127.0.0.1:" + std::to_string(port) + " f 2>/dev/null"));
  return f;
}

// The split TX frequency and the mode, straight from rigctld's protocol ("i", "m").
std::string rigctld_query(int port, const std::string& cmd, int lines) {
  return trim(tbtest::tcp_exchange(port, cmd + "\n", lines));
}

}  // namespace

TEST_CASE("Hamlib: tune a rigctld dummy, read back, survive a daemon restart" * doctest::skip(tb::testing::skip_without({"rigctld", "rigctl"}))) {
  tb::testing::require_tools({"rigctld", "rigctl"});
  const int port = tbtest::free_tcp_port();
  REQUIRE(port > 0);
  auto daemon = start_rigctld(port);
  REQUIRE(daemon);

  RadioConfig cfg;
  DriverTiming timing;
  timing.worker = {50ms, 200ms};
  auto made = make_radio("rigctld:127.0.0.1:" + std::to_string(port), cfg, timing);
  REQUIRE(made.driver);
  auto& radio = *made.driver;

  radio.set_downlink_mode(Mode::usb);
  radio.set_downlink_frequency(435'123'450);
  radio.set_uplink_mode(Mode::lsb);
  radio.set_uplink_frequency(145'950'000);
  REQUIRE(radio.wait_idle(10'000ms));
  auto st = radio.status();
  CHECK_FALSE(st.fault);
  CHECK(st.message == "");
  CHECK(st.connected);
  CHECK(st.downlink_hz == 435'123'450);
  CHECK(st.uplink_hz == 145'950'000);

  CHECK(rigctl_f(port) == "435123450");
  CHECK(rigctld_query(port, "i", 1) == "145950000");   // split TX on VFO B
  CHECK(rigctld_query(port, "s", 2) == "1\nVFOB");
  const std::string mode = rigctld_query(port, "m", 2);
  CAPTURE(mode);
  CHECK(mode.rfind("USB\n", 0) == 0);

  // A sequence, as the tracker sends it.
  for (Hz hz : {435'123'440, 435'123'430, 435'123'420}) {
    radio.set_downlink_frequency(hz);
    REQUIRE(radio.wait_idle(10'000ms));
    CHECK(rigctl_f(port) == std::to_string(hz));
  }

  // The daemon dies while nothing is being sent: the idle check sees the connection closed.
  daemon->stop();
  REQUIRE(eventually([&] { return radio.status().fault && !radio.status().connected; }, 10'000ms));
  st = radio.status();
  CHECK(st.message.find("rigctld at 127.0.0.1:" + std::to_string(port)) != std::string::npos);
  CHECK(st.pending == 0);
  // A command given now is kept for when it is back.
  radio.set_downlink_frequency(435'200'000);
  CHECK(eventually([&] { return radio.status().pending >= 1; }, 10'000ms));
  st = radio.status();
  CHECK(st.downlink_hz == 435'123'420);   // the last one the radio took

  // It comes back (a fresh dummy, on its defaults): reconnect, then the pending downlink and the
  // remembered uplink and modes are sent again.
  daemon = start_rigctld(port);
  REQUIRE(daemon);
  REQUIRE(eventually([&] { return !radio.status().fault && radio.status().pending == 0; }, 15'000ms));
  st = radio.status();
  CHECK(st.connects >= 2);
  CHECK(st.downlink_hz == 435'200'000);
  CHECK(rigctl_f(port) == "435200000");
  CHECK(rigctld_query(port, "i", 1) == "145950000");
  made.driver.reset();
}

TEST_CASE("Hamlib: the dummy backend directly, Main/Sub chosen automatically") {
  HamlibLink link({1, "", 0, HamlibVfoScheme::automatic});
  link.open();
  CHECK(link.scheme() == HamlibVfoScheme::main_sub);
  link.set_frequency(Link::downlink, 435'000'000);
  link.set_frequency(Link::uplink, 145'900'000);
  link.set_mode(Link::downlink, Mode::fm);
  link.close();
  HamlibLink split({1, "", 0, HamlibVfoScheme::split});
  split.open();
  CHECK(split.scheme() == HamlibVfoScheme::split);
  split.set_frequency(Link::uplink, 145'900'000);
  split.set_mode(Link::uplink, Mode::usb);
  split.close();
  CHECK(hamlib_model_name(1).find("Dummy") != std::string::npos);
}

TEST_CASE("Hamlib: nothing listening is a fault with Hamlib's reason, retried with backoff") {
  const int port = tbtest::free_tcp_port();
  DriverTiming timing;
  timing.worker = {50ms, 100ms};
  auto made = make_radio("rigctld:127.0.0.1:" + std::to_string(port), {}, timing);
  REQUIRE(made.driver);
  made.driver->set_downlink_frequency(435'000'000);
  REQUIRE(eventually([&] { return made.driver->status().failures >= 2; }, 10'000ms));
  const auto st = made.driver->status();
  CHECK(st.fault);
  CHECK(st.message.find("cannot open") != std::string::npos);
  CHECK_FALSE(st.connected);
}

TEST_CASE("Hamlib: dial follow reads the radio back (dummy backend, Main/Sub)") {
  // Main/Sub. (Split is not checked on the dummy: Hamlib 4.5.4's dummy, read with the cache off,
  // holds the split TX frequency in VFO A, so the current VFO reads the uplink; docs/radio.md.)
  HamlibLink link({1, "", 0, HamlibVfoScheme::main_sub});
  link.open();
  CHECK(link.can_read(Link::downlink));
  link.set_frequency(Link::downlink, 435'640'850);
  link.set_frequency(Link::uplink, 145'964'720);
  CHECK(link.read_frequency(Link::downlink) == 435'640'850);
  CHECK(link.read_frequency(Link::uplink) == 145'964'720);
  link.close();
}

TEST_CASE("Hamlib: the CTCSS tone reaches rigctld" * doctest::skip(tb::testing::skip_without({"rigctld", "rigctl"}))) {
  tb::testing::require_tools({"rigctld", "rigctl"});
  const int port = tbtest::free_tcp_port();
  REQUIRE(port > 0);
  auto daemon = start_rigctld(port);
  REQUIRE(daemon);
  auto made = make_radio("rigctld:127.0.0.1:" + std::to_string(port), RadioConfig{});
  REQUIRE(made.driver);
  made.driver->set_ctcss_tone(670);   // SO-50's 67.0 Hz
  REQUIRE(made.driver->wait_idle(10s));
  CHECK_FALSE(made.driver->status().fault);
  CHECK(rigctld_query(port, "c", 1) == "670");
}

TEST_CASE("Hamlib: a backend with RIG_FUNC_SATMODE gets satellite mode at open and the links on Main/Sub") {
  // Hamlib's dummy lists SATMODE among its functions and Main and Sub among its VFOs, as the IC-9700
  // (3081), IC-9100 (3068) and TS-2000 (2014) backends do.
  HamlibLink link({1, "", 0, HamlibVfoScheme::automatic});
  link.open();
  CHECK(link.scheme() == HamlibVfoScheme::main_sub);
  CHECK(link.satellite_mode());
  link.set_frequency(Link::downlink, 435'647'270);
  link.set_frequency(Link::uplink, 145'962'570);
  CHECK(link.read_frequency(Link::downlink) == 435'647'270);
  CHECK(link.read_frequency(Link::uplink) == 145'962'570);
  link.close();
  HamlibLink split({1, "", 0, HamlibVfoScheme::split});
  split.open();
  CHECK_FALSE(split.satellite_mode());
  split.close();
}

TEST_CASE("rigctld --vfo: satellite mode on, downlink on Sub and uplink on Main, both read back, tone on Main" * doctest::skip(tb::testing::skip_without({"rigctld", "rigctl"}))) {
  tb::testing::require_tools({"rigctld", "rigctl"});
  const int port = tbtest::free_tcp_port();
  REQUIRE(port > 0);
  auto daemon = start_rigctld(port, true);
  REQUIRE(daemon);
  RigctldLink link("127.0.0.1:" + std::to_string(port), HamlibVfoScheme::automatic);
  link.open();
  CHECK(link.carry() == RigctldLink::Carry::main_sub);
  CHECK(link.satellite_mode());
  CHECK(rigctld_query(port, "u Main SATMODE", 1) == "1");
  link.set_mode(Link::downlink, Mode::usb);
  link.set_mode(Link::uplink, Mode::lsb);
  link.set_frequency(Link::downlink, 435'647'270);
  link.set_frequency(Link::uplink, 145'962'570);
  CHECK(rigctld_query(port, "f Sub", 1) == "435647270");
  CHECK(rigctld_query(port, "f Main", 1) == "145962570");
  CHECK(rigctld_query(port, "m Sub", 2) == "USB\n2400");   // passband 0: the mode's normal one
  CHECK(rigctld_query(port, "m Main", 2) == "LSB\n2400");
  // The operator's dial on each band, read back per VFO.
  CHECK(rigctld_query(port, "F Sub 435657270", 1) == "RPRT 0");
  CHECK(link.read_frequency(Link::downlink) == 435'657'270);
  CHECK(link.read_frequency(Link::uplink) == 145'962'570);
  link.set_ctcss_tone(670);
  CHECK(rigctld_query(port, "c Main", 1) == "670");
  link.close();
}

TEST_CASE("rigctld without --vfo: split as Gpredict does it, both links read back with f and i" * doctest::skip(tb::testing::skip_without({"rigctld", "rigctl"}))) {
  tb::testing::require_tools({"rigctld", "rigctl"});
  const int port = tbtest::free_tcp_port();
  REQUIRE(port > 0);
  auto daemon = start_rigctld(port);
  REQUIRE(daemon);
  RigctldLink link("127.0.0.1:" + std::to_string(port), HamlibVfoScheme::automatic);
  link.open();
  CHECK(link.carry() == RigctldLink::Carry::split);
  CHECK_FALSE(link.satellite_mode());
  link.set_frequency(Link::downlink, 435'647'270);
  link.set_frequency(Link::uplink, 145'962'570);   // S 1 VFOB, I, then the check that split holds
  CHECK(link.can_read(Link::uplink));
  CHECK(rigctld_query(port, "s", 2) == "1\nVFOB");
  CHECK(link.read_frequency(Link::downlink) == 435'647'270);
  CHECK(link.read_frequency(Link::uplink) == 145'962'570);
  CHECK(rigctld_query(port, "F 435657270", 1) == "RPRT 0");   // the operator's dial
  CHECK(link.read_frequency(Link::downlink) == 435'657'270);
  link.close();
}
