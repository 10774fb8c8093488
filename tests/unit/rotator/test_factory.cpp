// The --rotator specs of the rotator module: simulated, hamlib:MODEL:DEVICE[:BAUD], rotctld:HOST[:PORT]
// (each kind's parser and factory; rotator/registry.h picks them, tests/unit/rotator/test_registry.cpp).
#include <doctest/doctest.h>
#include <spdlog/spdlog.h>

#include "rotator/factory.h"

using namespace tb::rotator;
using tb::orbit::from_civil;
using tb::station::ManualClock;

TEST_CASE("Rotator specs that parse") {
  spdlog::set_level(spdlog::level::off);
  auto sim = parse_simulated_spec("simulated");
  REQUIRE(sim.spec);
  CHECK(sim.spec->kind == RotatorSpec::Kind::simulated);
  CHECK(to_string(*sim.spec) == "simulated");

  auto gs = parse_hamlib_spec("hamlib:603:/dev/ttyUSB0:9600");
  REQUIRE(gs.spec);
  CHECK(gs.spec->kind == RotatorSpec::Kind::hamlib);
  CHECK(gs.spec->model == 603);
  CHECK(gs.spec->device == "/dev/ttyUSB0");
  CHECK(gs.spec->baud == 9600);
  CHECK(to_string(*gs.spec) == "hamlib:603:/dev/ttyUSB0:9600");

  auto nobaud = parse_hamlib_spec("hamlib:1:/dev/null");
  REQUIRE(nobaud.spec);
  CHECK(nobaud.spec->baud == 0);
  CHECK(nobaud.spec->device == "/dev/null");

  auto net = parse_rotctld_spec("rotctld:127.0.0.1:4599");
  REQUIRE(net.spec);
  CHECK(net.spec->kind == RotatorSpec::Kind::rotctld);
  CHECK(net.spec->model == 2);
  CHECK(net.spec->host == "127.0.0.1");
  CHECK(net.spec->port == 4599);
  CHECK(net.spec->device == "127.0.0.1:4599");
  CHECK(to_string(*net.spec) == "rotctld:127.0.0.1:4599");

  auto dflt = parse_rotctld_spec("rotctld:localhost");
  REQUIRE(dflt.spec);
  CHECK(dflt.spec->port == 4533);
  auto v6 = parse_rotctld_spec("rotctld:[::1]:4533");
  REQUIRE(v6.spec);
  CHECK(v6.spec->host == "[::1]");
  CHECK(v6.spec->device == "[::1]:4533");
}

TEST_CASE("Bad rotator specs say what is wrong and what is expected") {
  auto err = [](const char* s) {
    const std::string_view text(s);
    SpecResult r = text.starts_with("hamlib") ? parse_hamlib_spec(s)
                   : text.starts_with("rotctld") ? parse_rotctld_spec(s)
                                                 : parse_simulated_spec(s);
    CHECK_FALSE(r.spec);
    return r.error;
  };
  CHECK(err("simulated:fast") == "bad --rotator 'simulated:fast': expected simulated or simulated:mount=AZ,EL (a mounting error in degrees: "
        "the rotator reads that much more than where the antenna points), e.g. simulated:mount=2.0,-1.0");
  CHECK(err("hamlib") == "bad --rotator 'hamlib': missing MODEL; expected hamlib:MODEL:DEVICE[:BAUD], e.g. hamlib:603:/dev/ttyUSB0:9600");
  CHECK(err("hamlib:nosuch:/dev/ttyUSB0").find("MODEL 'nosuch' is neither a Hamlib rotator model number nor the name "
                                               "of one (see `rotctl -l`)") != std::string::npos);
  // Something after the speed is no part of the device (issue 47).
  CHECK(err("hamlib:603:/dev/ttyUSB0:9600:x") == "bad --rotator 'hamlib:603:/dev/ttyUSB0:9600:x': 'x' after BAUD 9600; "
                                                 "expected hamlib:MODEL:DEVICE[:BAUD], e.g. hamlib:603:/dev/ttyUSB0:9600");
  CHECK(err("hamlib:603").find("missing DEVICE") != std::string::npos);
  CHECK(err("hamlib:603:").find("missing DEVICE") != std::string::npos);
  CHECK(err("hamlib:603:/dev/ttyUSB0:9601").find("BAUD 9601 is not a serial speed") != std::string::npos);
  CHECK(err("hamlib:2:localhost:4533").find("for a rotctld use rotctld:HOST:PORT") != std::string::npos);
  CHECK(err("hamlib:99999:/dev/ttyUSB0") == "bad --rotator 'hamlib:99999:/dev/ttyUSB0': Hamlib has no rotator model 99999 (see `rotctl -l`)");
  CHECK(err("rotctld").find("missing HOST") != std::string::npos);
  CHECK(err("rotctld:").find("missing HOST") != std::string::npos);
  CHECK(err("rotctld:host:") .find("empty PORT") != std::string::npos);
  CHECK(err("rotctld:host:http") == "bad --rotator 'rotctld:host:http': PORT 'http' is not a TCP port (1..65535); "
                                    "expected rotctld:HOST[:PORT], e.g. rotctld:localhost:4533");
  CHECK(err("rotctld:host:70000").find("not a TCP port") != std::string::npos);
  CHECK(err("rotctld:::1:4533").find("IPv6 address goes in brackets") != std::string::npos);
  CHECK(err("rotctld:[::1").find("unclosed '['") != std::string::npos);
}

TEST_CASE("make_simulated_rotator builds the simulated rotator on the given clock") {
  ManualClock clock(from_civil(2026, 1, 1));
  auto d = make_simulated_rotator(clock);
  REQUIRE(d);
  REQUIRE(d->as_adc());
  CHECK_FALSE(d->as_degrees());
  CHECK(d->description() == "simulated");
  CHECK(d->as_adc()->read() == Counts{0, 0});
}

TEST_CASE("A Hamlib rotator that cannot connect reports the fault and keeps retrying, without blocking") {
  spdlog::set_level(spdlog::level::off);
  ManualClock clock(from_civil(2026, 1, 1));
  HamlibOptions t;
  t.backoff_min = std::chrono::milliseconds(20);
  t.backoff_max = std::chrono::milliseconds(50);
  // A serial rotator on a device that does not exist.
  auto d = make_hamlib_rotator(*parse_hamlib_spec("hamlib:601:/nonexistent/ttyTB0:9600").spec, t);
  REQUIRE(d->as_degrees());
  CHECK(d->description() == "hamlib 601 /nonexistent/ttyTB0 9600");
  Health h;
  for (int i = 0; i < 250 && h.state != LinkState::fault; ++i) {  // at most 5 s
    h = d->health();
    if (h.state != LinkState::fault) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  CHECK(h.state == LinkState::fault);
  CHECK(h.message.find("cannot connect to hamlib 601 /nonexistent/ttyTB0 9600") != std::string::npos);
  CHECK(h.message.find("retrying") != std::string::npos);
  CHECK(h.connects == 0);
  CHECK_FALSE(d->as_degrees()->read());
  d->as_degrees()->set_position({10, 10});  // dropped, returns at once
  d->stop();
  d.reset();  // joins the worker promptly
}

TEST_CASE("A Hamlib rotator by its name, as radios are: hamlib:GS-232B is model 603 (Hamlib's ROT_MODEL_GS232B)") {
  for (const char* spec : {"hamlib:GS-232B:/dev/ttyUSB0:9600", "hamlib:gs232b:/dev/ttyUSB0:9600",
                           "hamlib:Yaesu GS-232B:/dev/ttyUSB0:9600"}) {
    INFO(spec);
    const SpecResult r = parse_hamlib_spec(spec);
    REQUIRE(r.spec);
    CHECK(r.spec->model == 603);
    CHECK(r.spec->device == "/dev/ttyUSB0");
    CHECK(r.spec->baud == 9600);
  }
}

TEST_CASE("The simulated rotator's mounting error: simulated:mount=AZ,EL, written back as given") {
  const SpecResult r = parse_simulated_spec("simulated:mount=2.0,-1.0");
  REQUIRE(r.spec);
  CHECK(r.spec->kind == RotatorSpec::Kind::simulated);
  CHECK(r.spec->mount_az_deg == 2.0);
  CHECK(r.spec->mount_el_deg == -1.0);
  CHECK(to_string(*r.spec) == "simulated:mount=2,-1");
  CHECK(to_string(*parse_simulated_spec("simulated").spec) == "simulated");
  for (const char* bad : {"simulated:mount=2", "simulated:mount=2,x", "simulated:mount=50,0", "simulated:mount="})
    CHECK(parse_simulated_spec(bad).error.find("each within 45 deg") != std::string::npos);
}
