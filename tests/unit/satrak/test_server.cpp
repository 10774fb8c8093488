// The Satrak TCP server on loopback, with the station ticking on the same io_context in a thread of
// its own; the clients (good and bad) run in the test's threads. Every wait is bounded.
#include <atomic>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <future>
#include <sstream>

#include "fixture.h"
#include "net.h"
#include "rotator/satrak/client.h"
#include "satrak/server.h"

using namespace satrak_test;
using namespace std::chrono_literals;

namespace {

// The station and the Satrak server on one io_context run by a thread; the RTC advances `rate` times
// as fast as the wall clock (a tick every 50 ms of wall time) on that thread only.
struct Live {
  explicit Live(orbit::UtcTime t0, satrak::ServerOptions o = {}, std::function<void(Acu&)> setup = {}, int rate = 1)
      : acu(t0), rate(rate) {
    if (setup) setup(acu);
    o.address = "127.0.0.1";
    o.port = 0;
    server = std::make_unique<satrak::Server>(acu.io, *acu.unit, o);
    port = server->port();
    acu.unit->start();
    arm();
    thread = std::thread([this] { acu.io.run(); });
  }
  ~Live() {
    acu.io.stop();
    thread.join();
  }
  void arm() {
    ticker.expires_after(50ms);
    ticker.async_wait([this](const boost::system::error_code& ec) {
      if (ec) return;
      acu.base += 50ms * rate;
      acu.loop->tick();
      ++ticks;
      arm();
    });
  }
  // Runs f on the loop's thread and returns its result.
  template <typename F>
  auto on_loop(F f) {
    using R = decltype(f());
    auto p = std::make_shared<std::promise<R>>();
    auto fut = p->get_future();
    boost::asio::post(acu.io, [p, f]() mutable { p->set_value(f()); });
    REQUIRE(fut.wait_for(10s) == std::future_status::ready);
    return fut.get();
  }
  // Polls a condition on the loop until it holds or the time is up.
  template <typename F>
  bool wait_for(F cond, std::chrono::milliseconds within) {
    const auto deadline = std::chrono::steady_clock::now() + within;
    while (std::chrono::steady_clock::now() < deadline) {
      if (on_loop(cond)) return true;
      std::this_thread::sleep_for(20ms);
    }
    return false;
  }

  Acu acu;
  int rate = 1;
  std::unique_ptr<satrak::Server> server;
  unsigned short port = 0;
  boost::asio::steady_timer ticker{acu.io};
  std::atomic<long> ticks{0};
  std::thread thread;
};

bool starts_with(const std::string& s, const std::string& p) { return s.rfind(p, 0) == 0; }

}  // namespace

TEST_CASE("Server: a client's session, frame by frame") {
  Live live(kT0);
  satrak::Client c;
  REQUIRE(c.connect("127.0.0.1", live.port, 5s));
  CHECK(c.request("VERSION?", 5s) == "VERSION?,TRAKBOX SATRAK CU V9.9.9,DU simulated");
  CHECK(c.request("GOTO=,20,10", 5s) == "GOTO=,OK");
  CHECK(live.wait_for([&] { return std::abs(live.acu.rs().az.deg - 20.0) < 1.2 && live.acu.rs().az.motion == rotator::Drive::stop && live.acu.rs().el.motion == rotator::Drive::stop &&
                                  std::abs(live.acu.rs().el.deg - 10.0) < 0.4; },
                        20s));
  const auto st = c.request("STATUS?", 5s);
  REQUIRE(st);
  const auto f = satrak::parse_payload(*st)->fields;
  REQUIRE(f.size() == 16);
  CHECK(std::abs(std::stod(f[1]) - 20.0) < 1.2);

  // Raw bytes: two frames and noise in one write, a bad checksum, a frame split over writes.
  RawSocket raw(live.port);
  REQUIRE(raw.ok());
  raw.send("noise\r\n" + satrak::encode("TPOS?") + "$STATUS?*00\r\n" + satrak::encode("FOO?"), 2s);
  std::string got = raw.read_until("FOO?", 5s);
  got += raw.read_until("\n", 1s);
  std::vector<tb::satrak::Decoded> frames = satrak::Decoder().feed(got);
  REQUIRE(frames.size() == 3);
  for (const auto& d : frames) CHECK(d.kind == satrak::Decoded::Kind::frame);  // replies are always exact
  CHECK(starts_with(frames[0].payload, "TPOS?,"));
  CHECK(frames[1].payload == "STATUS?,ERR,1");
  CHECK(frames[2].payload == "FOO?,ERR,4");
  const std::string wire = satrak::encode("REDUCTION?");
  raw.send(wire.substr(0, 5), 1s);
  std::this_thread::sleep_for(100ms);
  raw.send(wire.substr(5), 1s);
  CHECK(raw.read_until("\r\n", 5s) == satrak::encode("REDUCTION?,1,1"));
}

TEST_CASE("Server: a client that sends a burst and then reads gets every reply, in order") {
  // 4,000 queries in one write: a read of 4 KiB brings in some 240 of them at once. The replies
  // (more than max_output in all) must leave as fast as the socket takes them, not one frame per
  // write while the next read adds 240 (a host on a busy machine was dropped for that).
  Live live(kT0);
  RawSocket raw(live.port);
  REQUIRE(raw.ok());
  const int n = 4000;
  std::string burst;
  for (int i = 0; i < n; ++i) burst += satrak::encode("REDUCTION?");
  const std::string reply = satrak::encode("REDUCTION?,1,1");
  REQUIRE(reply.size() * n > satrak::ServerOptions{}.max_output);
  REQUIRE(raw.send(burst, 5s) == static_cast<long>(burst.size()));
  std::string got;
  while (got.size() < reply.size() * n) {
    const std::string more = raw.read_until("\n", 5s);
    if (more.empty()) break;
    got += more;
  }
  std::string expected;
  for (int i = 0; i < n; ++i) expected += reply;
  CHECK(got == expected);
  CHECK(live.on_loop([&] { return live.server->stats().dropped_slow; }) == 0u);
}

TEST_CASE("Server: clients in parallel while a pass is tracked; flooding, mute, vanishing clients change nothing") {
  const orbit::Pass pass = iss_pass(tucson_model(), kT0, 30.0, 70.0);
  satrak::ServerOptions o;
  o.max_output = 16 * 1024;
  o.send_buffer = 8 * 1024;
  Live live(orbit::add_minutes(pass.aos, 2.0), o, [](Acu& a) {
    REQUIRE(a.cmd("SATELLITE=,amateur.txt,ISS,1,1") == "SATELLITE=,OK");
    REQUIRE(a.cmd("TRACK=,1") == "TRACK=,OK");
  }, 5);
  // Satrak brings the antenna onto the satellite first.
  auto pointing_error = [&] {
    return live.on_loop([&] {
      const auto& s = live.acu.rs();
      const orbit::Sgp4 sgp4(iss_elements());
      const auto o = orbit::observe(sgp4, live.acu.model.station.observer(), live.acu.clock.now());
      return rotator::pointing_error_deg(s.az.deg, s.el.deg, o.look.az_deg, o.look.el_deg);
    });
  };
  const auto deadline = std::chrono::steady_clock::now() + 90s;
  while (pointing_error() > 2.0 && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(100ms);
  REQUIRE(pointing_error() <= 2.0);
  const long ticks0 = live.ticks;

  // A client that never reads its replies while asking for many.
  RawSocket mute(live.port, 4096);
  REQUIRE(mute.ok());
  // A client that sends 1 MB without a newline.
  RawSocket flood(live.port);
  REQUIRE(flood.ok());
  // A silent client, and one that goes away in the middle of a frame.
  RawSocket silent(live.port);
  {
    RawSocket gone(live.port);
    gone.send("$STATUS?*2", 1s);
  }

  std::atomic<bool> mute_cut{false};
  std::thread mute_thread([&] {
    std::string burst;
    for (int i = 0; i < 2000; ++i) burst += satrak::encode("STATUS?");
    for (int round = 0; round < 200 && !mute_cut; ++round)
      if (mute.send(burst, 200ms) < 0) mute_cut = true;
  });
  std::atomic<long> flood_sent{0};
  std::thread flood_thread([&] {
    const std::string chunk(64 * 1024, 'x');
    for (int i = 0; i < 16; ++i) {
      const long n = flood.send(chunk, 5s);
      if (n < 0) break;
      flood_sent += n;
    }
  });

  std::atomic<int> good{0}, bad{0};
  std::vector<std::thread> clients;
  for (int k = 0; k < 4; ++k) {
    clients.emplace_back([&] {
      satrak::Client c;
      if (!c.connect("127.0.0.1", live.port, 5s)) {
        ++bad;
        return;
      }
      const char* queries[] = {"STATUS?", "TPOS?", "SATELLITE?", "VERSION?", "TIME?", "ERRSTATUS?"};
      for (int i = 0; i < 60; ++i) {
        const std::string q = queries[i % 6];
        const auto r = c.request(q, 5s);
        if (r && starts_with(*r, q + ",") && r->find(",ERR,") == std::string::npos) ++good;
        else if (bad++ < 3) MESSAGE("bad reply to " << q << ": " << (r ? *r : "none: " + c.error()));
        std::this_thread::sleep_for(25ms);  // the session lasts a few seconds of station ticks
      }
    });
  }
  for (auto& t : clients) t.join();
  flood_thread.join();
  mute_thread.join();
  CHECK(good == 240);
  CHECK(bad == 0);
  CHECK(flood_sent == 16 * 64 * 1024);
  CHECK(mute_cut);  // the server dropped it
  CHECK(live.on_loop([&] { return live.server->stats().dropped_slow; }) >= 1u);

  // The flooding client got one ERR,3 and is still served.
  flood.send("\r\n" + satrak::encode("VERSION?"), 1s);
  std::string fl = flood.read_until("VERSION?", 5s);
  fl += flood.read_until("\n", 1s);  // two statements: the reads must happen in this order
  const auto fr = satrak::Decoder().feed(fl);
  REQUIRE(fr.size() == 2);
  CHECK(fr[0].payload == "ERR,3");
  CHECK(starts_with(fr[1].payload, "VERSION?,"));
  // The silent client is still connected and answered when it speaks.
  silent.send(satrak::encode("TPOS?"), 1s);
  CHECK(starts_with(silent.read_until("\n", 5s), "$TPOS?,"));

  // The station ticked all along, and Satrak still tracks the pass.
  CHECK(live.ticks - ticks0 > 20);
  CHECK(live.on_loop([&] { return live.acu.unit->tracking(); }));
  CHECK(live.on_loop([&] { return live.acu.unit->tracking_target().has_value(); }));
  CHECK(pointing_error() < 3.0);
}

TEST_CASE("Server: clients beyond the limit are closed at once") {
  satrak::ServerOptions o;
  o.max_clients = 2;
  Live live(kT0, o);
  RawSocket a(live.port), b(live.port);
  REQUIRE(live.wait_for([&] { return live.server->clients() == 2; }, 5s));
  RawSocket c(live.port);
  // Both others connected within evict_idle_after: refused with an ERR,8 frame, then closed.
  CHECK(c.read_until("\n", 5s) == satrak::encode(satrak::reply_error("", satrak::Error::not_allowed)));
  CHECK_FALSE(c.read_for(2s).has_value());  // closed by the server
  a.send(satrak::encode("VERSION?"), 1s);
  CHECK(starts_with(a.read_until("\n", 5s), "$VERSION?,"));
  CHECK(live.on_loop([&] { return live.server->stats().refused; }) == 1u);
  a.close();
  REQUIRE(live.wait_for([&] { return live.server->clients() == 1; }, 5s));
  RawSocket d(live.port);
  d.send(satrak::encode("VERSION?"), 1s);
  CHECK(starts_with(d.read_until("\n", 5s), "$VERSION?,"));
}

TEST_CASE("Server: when every connection is taken, the one silent longest makes room (issue 14, defect 2)") {
  satrak::ServerOptions o;
  o.max_clients = 3;
  o.evict_idle_after = 0ms;  // any silence is long enough: the order of last traffic decides
  Live live(kT0, o);
  RawSocket idle(live.port), poller(live.port), other(live.port);
  REQUIRE(live.wait_for([&] { return live.server->clients() == 3; }, 5s));
  for (RawSocket* s : {&poller, &other}) {  // these two poll, as a monitor-and-control program does
    s->send(satrak::encode("STATUS?"), 1s);
    CHECK(starts_with(s->read_until("\n", 5s), "$STATUS?,"));
  }
  RawSocket newcomer(live.port);
  newcomer.send(satrak::encode("VERSION?"), 1s);
  CHECK(starts_with(newcomer.read_until("\n", 5s), "$VERSION?,"));
  CHECK_FALSE(idle.read_for(2s).has_value());  // the silent one was closed
  CHECK(live.on_loop([&] { return live.server->stats().evicted; }) == 1u);
  poller.send(satrak::encode("TPOS?"), 1s);
  CHECK(starts_with(poller.read_until("\n", 5s), "$TPOS?,"));
}

TEST_CASE("trakbox satrak HOST[:PORT] COMMAND...: the command-line client") {
  Live live(kT0);
  const std::string target = "127.0.0.1:" + std::to_string(live.port);
  {
    std::ostringstream out, err;
    CHECK(satrak::run_cli({target, "VERSION?", "$TPOS?*27", "GOTO=,10,10"}, out, err) == 0);
    std::istringstream lines(out.str());
    std::string l1, l2, l3;
    std::getline(lines, l1);
    std::getline(lines, l2);
    std::getline(lines, l3);
    CHECK(l1 == "VERSION?,TRAKBOX SATRAK CU V9.9.9,DU simulated");
    CHECK(starts_with(l2, "TPOS?,"));
    CHECK(l3 == "GOTO=,OK");
    CHECK(err.str().empty());
  }
  {
    std::ostringstream out, err;
    CHECK(satrak::run_cli({"--timeout", "3", target, "FOO?", "STATUS?"}, out, err) == 1);  // one refused
    CHECK(starts_with(out.str(), "FOO?,ERR,4\nSTATUS?,"));
  }
  {
    std::ostringstream out, err;
    CHECK(satrak::run_cli({target}, out, err) == 2);
    CHECK(err.str().find("missing COMMAND") != std::string::npos);
    CHECK(satrak::run_cli({"127.0.0.1:99999", "STATUS?"}, out, err) == 2);
    CHECK(satrak::run_cli({target, "$STATUS?*00"}, out, err) == 2);
    CHECK(satrak::run_cli({"--timeout", "x", target, "STATUS?"}, out, err) == 2);
    CHECK(satrak::run_cli({"--help"}, out, err) == 0);
  }
  {
    std::ostringstream out, err;
    CHECK(satrak::run_cli({"127.0.0.1:" + std::to_string(unused_port()), "STATUS?"}, out, err) == 1);
    CHECK(err.str().find("cannot connect") != std::string::npos);
  }
  std::string e;
  CHECK(satrak::parse_rotator_spec("satrak:[::1]:4002", e)->host == "::1");
  CHECK(satrak::parse_rotator_spec("satrak:host", e)->port == 4001);
  CHECK_FALSE(satrak::parse_rotator_spec("satrak:a:b:c", e));
  CHECK(e == "bad --rotator 'satrak:a:b:c': too many ':' (an IPv6 address goes in brackets); expected "
             "satrak:HOST[:PORT], e.g. satrak:192.0.2.7:4001");
  CHECK_FALSE(satrak::parse_rotator_spec("satrak::4001", e));
}

TEST_CASE("SatrakRotator: another Satrak ACU as trakbox's rotator, with lost connections retried") {
  Live peer(kT0, {}, {}, 4);
  std::string e;
  CHECK_FALSE(satrak::parse_rotator_spec("satrak:", e));
  CHECK_FALSE(satrak::parse_rotator_spec("rotctld:x", e));
  CHECK(satrak::parse_rotator_spec("satrak:192.0.2.7", e)->port == 4001);
  auto opt = satrak::parse_rotator_spec("satrak:127.0.0.1:" + std::to_string(peer.port), e);
  REQUIRE(opt);
  opt->poll = 100ms;
  opt->backoff_min = 50ms;
  opt->backoff_max = 200ms;

  auto wait = [](auto cond, std::chrono::milliseconds within) {
    const auto deadline = std::chrono::steady_clock::now() + within;
    while (std::chrono::steady_clock::now() < deadline) {
      if (cond()) return true;
      std::this_thread::sleep_for(20ms);
    }
    return false;
  };

  SUBCASE("the driver on its own") {
    satrak::SatrakRotator rot(*opt);
    CHECK(rot.description() == "satrak 127.0.0.1:" + std::to_string(peer.port));
    REQUIRE(wait([&] { return rot.health().ok() && rot.read().has_value(); }, 5s));
    CHECK(rot.health().connects == 1);
    rot.set_position({20.0, 10.0});
    bool saw_motion = false;
    REQUIRE(wait([&] {
      saw_motion = saw_motion || rot.motion().az == rotator::Drive::increase;
      const auto p = rot.read();
      return p && std::abs(p->az - 20.0) < 1.2 && std::abs(p->el - 10.0) < 0.4 && rot.motion().az == rotator::Drive::stop;
    }, 20s));
    CHECK(saw_motion);
    CHECK(peer.on_loop([&] { return peer.acu.rs().target->az_travel; }) == doctest::Approx(20.0));

    // The peer goes away: a fault, reported; it comes back on the same port: reconnected.
    peer.on_loop([&] {
      peer.server->close();
      return 0;
    });
    REQUIRE(wait([&] { return rot.health().state == rotator::LinkState::fault; }, 5s));
    CHECK_FALSE(rot.read().has_value());
    CHECK(rot.health().message.find("127.0.0.1") != std::string::npos);
    peer.on_loop([&] {
      satrak::ServerOptions o;
      o.port = peer.port;
      peer.server = std::make_unique<satrak::Server>(peer.acu.io, *peer.acu.unit, o);
      return 0;
    });
    REQUIRE(wait([&] { return rot.health().ok() && rot.read().has_value(); }, 10s));
    CHECK(rot.health().connects == 2);

    // A GOTO the peer refuses (an elevation beyond 180) is reported.
    rot.set_position({30.0, 200.0});
    REQUIRE(wait([&] { return rot.health().state == rotator::LinkState::fault; }, 5s));
    CHECK(rot.health().message.find("GOTO=,ERR,") != std::string::npos);
  }
  SUBCASE("behind the rotator controller, as --rotator satrak:HOST:PORT") {
    station::ManualClock clock(kT0);
    rotator::Controller ctl(rotator::RotatorConfig{}, station::RotorStart::north, std::make_unique<satrak::SatrakRotator>(*opt));
    ctl.set_control_enabled(true);
    ctl.set_target(rotator::AzEl{30.0, 15.0});
    REQUIRE(wait([&] {
      clock.advance(100ms);
      ctl.tick(clock.now());
      const auto& s = ctl.status();
      return s.has_position && s.on_target && std::abs(s.az.deg - 30.0) < 1.2 && std::abs(s.el.deg - 15.0) < 0.4;
    }, 25s));
    CHECK(peer.on_loop([&] { return std::abs(peer.acu.rs().az.deg - 30.0) < 1.5; }));
  }
}
