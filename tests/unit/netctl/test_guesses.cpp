// How fast one address may guess a secret (issue 33, defect 3): GuessGuard with the time passed in,
// exact to the millisecond; then the server with a secret, a small policy and a real loopback client:
// answers slowed per address across connections, the lockout refusing the address at accept, a
// password sent again after logging in neither logged nor echoed.
#include <doctest/doctest.h>
#include <spdlog/sinks/ostream_sink.h>

#include <sstream>

#include "fixture.h"
#include "netctl/guesses.h"
#include "netctl/host_server.h"
#include "netctl/server.h"
#include "raw_client.h"

using namespace tb;
using namespace nettest;
using netctl::GuessGuard;
using netctl::GuessPolicy;
using ms = std::chrono::milliseconds;

TEST_CASE("GuessGuard: delays double per wrong secret up to the cap, across connections of one address") {
  GuessGuard g;  // the defaults: 0.5 s doubling to 30 s, lockout after 10 for 10 minutes
  const auto t0 = GuessGuard::Clock::time_point{} + std::chrono::hours(1);
  const std::string a = "192.0.2.7";
  CHECK(g.free_at(a, t0) == t0);  // an address never wrong is answered at once
  CHECK_FALSE(g.wrong(a, t0));
  // The next attempt, whenever it comes and on whichever connection, is answered 0.5 s after the first.
  CHECK(g.free_at(a, t0) == t0 + ms(500));
  CHECK(g.free_at(a, t0 + ms(499)) == t0 + ms(500));
  CHECK_FALSE(g.wrong(a, t0 + ms(500)));
  CHECK(g.free_at(a, t0 + ms(500)) == t0 + ms(1500));  // then 1 s
  CHECK_FALSE(g.wrong(a, t0 + ms(1500)));
  CHECK(g.free_at(a, t0 + ms(1500)) == t0 + ms(3500));  // then 2 s
  // A late attempt is answered when it comes.
  CHECK(g.free_at(a, t0 + ms(9000)) == t0 + ms(9000));
  // Another address is not slowed by this one.
  CHECK(g.free_at("192.0.2.8", t0) == t0);
}

TEST_CASE("GuessGuard: ten wrong secrets lock the address out; the right one or a quiet quarter hour forgets it") {
  GuessGuard g;
  const auto t0 = GuessGuard::Clock::time_point{} + std::chrono::hours(1);
  const std::string a = "198.51.100.1";
  auto t = t0;
  int locked_at = 0;
  for (int i = 1; i <= 10; ++i) {
    t = g.free_at(a, t);  // an attacker answering as fast as it is allowed
    if (g.wrong(a, t)) locked_at = i;
  }
  CHECK(locked_at == 10);
  // 0.5+1+2+4+8+16+30+30+30 s passed before the tenth answer.
  CHECK(t - t0 == ms(121500));
  CHECK(g.locked_until(a, t) == t + ms(600000));
  CHECK(g.free_at(a, t) == t + ms(600000));
  // One more wrong secret after the lockout locks it again at once.
  const auto after = t + ms(600000);
  CHECK(g.free_at(a, after) == after);
  CHECK(g.wrong(a, after));
  CHECK(g.locked_until(a, after) == after + ms(600000));
  // The right secret forgets the address.
  g.right(a);
  CHECK(g.failures(a) == 0);
  CHECK(g.free_at(a, after) == after);
  // 15 minutes without a wrong secret (and not locked out): a clean slate.
  GuessGuard q;
  q.wrong(a, t0);
  q.wrong(a, t0 + ms(500));
  CHECK(q.free_at(a, t0 + ms(900499)) == t0 + ms(900499));  // the delays were paid long ago
  CHECK(q.failures(a) == 2);
  (void)q.free_at(a, t0 + ms(900500));
  CHECK(q.failures(a) == 0);
}

TEST_CASE("GuessGuard: the table of addresses is bounded") {
  GuessPolicy p;
  p.max_addresses = 3;
  GuessGuard g(p);
  const auto t0 = GuessGuard::Clock::time_point{} + std::chrono::hours(1);
  for (int i = 0; i < 100; ++i) g.wrong("10.0.0." + std::to_string(i), t0 + ms(i));
  int remembered = 0;
  for (int i = 0; i < 100; ++i) remembered += g.failures("10.0.0." + std::to_string(i)) > 0;
  CHECK(remembered == 3);
  CHECK(g.failures("10.0.0.99") == 1);  // the newest are kept
}

namespace {

// The default logger replaced by one that writes into a string, at debug level.
struct CapturedLog {
  std::ostringstream out;
  std::shared_ptr<spdlog::logger> before = spdlog::default_logger();
  CapturedLog() {
    auto log = std::make_shared<spdlog::logger>("test", std::make_shared<spdlog::sinks::ostream_sink_mt>(out));
    log->set_level(spdlog::level::debug);
    spdlog::set_default_logger(log);
  }
  ~CapturedLog() { spdlog::set_default_logger(before); }
  std::string text() {
    spdlog::default_logger()->flush();
    return out.str();
  }
};

netctl::ServerOptions with_secret(netctl::ServerOptions o) {
  o.secret = "RealSecret42";
  o.guesses.first_delay = ms(200);
  o.guesses.max_delay = ms(400);
  o.guesses.lockout_after = 4;
  o.guesses.lockout_for = ms(60000);
  return o;
}

}  // namespace

TEST_CASE("server: wrong secrets from one address are answered later and later, then it is locked out") {
  CapturedLog log;
  SimStation st;
  boost::asio::io_context io;
  netctl::RotctldServer rot(io, 0, *st.station, with_secret(netctl::RotctldServer::named("rotctld")));
  LoopThread lt(io, st);
  // Two connections of one address, guessing in turn: the delays are the address's, not the connection's.
  RawClient a(rot.port()), b(rot.port());
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  const auto t = std::chrono::steady_clock::now();
  CHECK(a.ask("\\password guess1") == "RPRT -1\n");
  CHECK(b.ask("\\password guess2") == "RPRT -1\n");
  CHECK(a.ask("\\password guess3") == "RPRT -1\n");
  // The fourth wrong secret locks the address out: this connection closes, a new one is refused.
  CHECK(b.ask("\\password guess4") == "RPRT -1\n");
  // The server answered each at least the address's delay after the one before: 200 + 400 + 400 ms
  // (a lower bound, whatever the machine's load).
  CHECK(std::chrono::steady_clock::now() - t >= ms(1000));
  CHECK(b.closed_by_peer());
  RawClient c(rot.port());
  CHECK(c.closed_by_peer());
  CHECK(c.received() == "RPRT -9\n");
  CHECK(lt.on_loop([&] { return rot.server().stats().refused_locked_out; }) == 1u);
  CHECK(lt.on_loop([&] { return rot.server().stats().wrong_secrets; }) == 4u);
  CHECK(lt.on_loop([&] { return rot.server().stats().lockouts; }) == 1u);
  lt.stop();
  const std::string text = log.text();
  CHECK(text.find("127.0.0.1 locked out until") != std::string::npos);
  CHECK(text.find("guess") == std::string::npos);  // no secret given reaches the log
}

TEST_CASE("server: a password sent again after logging in is checked, never logged and never echoed") {
  CapturedLog log;
  SimStation st;
  boost::asio::io_context io;
  netctl::RotctldServer rot(io, 0, *st.station, with_secret(netctl::RotctldServer::named("rotctld")));
  netctl::HostServer host(io, 0, *st.station, with_secret(netctl::HostServer::defaults()));
  LoopThread lt(io, st);
  RawClient r(rot.port());
  REQUIRE(r.ok());
  CHECK(r.ask("\\password RealSecret42") == "RPRT 0\n");
  CHECK(r.ask("\\password RealSecret42") == "RPRT 0\n");
  CHECK(r.ask("\\PASSWORD RealSecret42") == "RPRT 0\n");
  CHECK(r.ask("\\password OtherSecret99") == "RPRT -1\n");
  CHECK(r.ask("_") == "trakbox rotator (simulated)\n");  // still logged in

  RawClient h(host.port());
  REQUIRE(h.ok());
  h.exchange("", "TrakBox>>");
  CHECK(h.exchange("PASS RealSecret42\r\n", "TrakBox>>").find("OK authenticated") != std::string::npos);
  const std::string again = h.exchange("pass RealSecret42\r\n", "TrakBox>>");
  CHECK(again.find("OK authenticated") != std::string::npos);
  CHECK(again.find("RealSecret42") == std::string::npos);  // not echoed
  lt.stop();
  const std::string text = log.text();
  CHECK(text.find("RealSecret42") == std::string::npos);
  CHECK(text.find("OtherSecret99") == std::string::npos);
  CHECK(text.find("authenticated") != std::string::npos);
}

TEST_CASE_FIXTURE(ServerCase, "server: one address holds at most max_per_address connections; host mode names the reason it refuses") {
  netctl::ServerOptions o = netctl::HostServer::defaults();
  o.max_per_address = 2;
  o.loopback_exempt = false;  // loopback is exempt by default: the test's clients are all loopback
  netctl::HostServer host(io, 0, *st.station, o);
  netctl::ServerOptions only_other = netctl::HostServer::defaults();
  only_other.allow.push_back(*inet::parse_cidr("192.0.2.0/24"));
  netctl::HostServer fenced(io, 0, *st.station, only_other);
  LoopThread lt(io, st);
  RawClient a(host.port()), b(host.port());
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  a.exchange("", "TrakBox>>");
  b.exchange("", "TrakBox>>");
  RawClient c(host.port());
  CHECK(c.closed_by_peer());
  CHECK(c.received().find("ERROR busy") == 0);
  CHECK(lt.on_loop([&] { return host.server().stats().refused_per_address; }) == 1u);
  // Refused by --allow: told so, not "busy".
  RawClient d(fenced.port());
  CHECK(d.closed_by_peer());
  CHECK(d.received() == "ERROR not allowed: this address is not in the station's --allow list\r\n");
  CHECK(lt.on_loop([&] { return fenced.server().stats().refused_not_allowed; }) == 1u);
  lt.stop();
}

// Issue 33, defect 7: clients trickling a byte every few seconds kept every connection "heard from"
// and locked a real client out for as long as they lasted. Silence now counts from the last whole
// line, so the trickler that has completed no line for longest makes room.
TEST_CASE_FIXTURE(ServerCase, "server: clients that trickle bytes without ever ending a line make room for a real client") {
  netctl::ServerOptions o = netctl::RotctldServer::named("rotctld");
  o.max_clients = 2;
  o.evict_idle_after = ms(300);
  netctl::RotctldServer rot(io, 0, *st.station, o);
  LoopThread lt(io, st);
  RawClient a(rot.port()), b(rot.port());
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  for (int i = 0; i < 10; ++i) {  // a byte each every 50 ms for half a second: never a newline
    a.send_some("p");
    b.send_some("p");
    std::this_thread::sleep_for(ms(50));
  }
  RawClient c(rot.port());
  REQUIRE(c.ok());
  CHECK(c.ask("_") == "trakbox rotator (simulated)\n");
  CHECK((a.closed_by_peer(ms(500)) || b.closed_by_peer(ms(500))));
  lt.stop();
}

// Issue 38, item 8: the budget was per /128 and per port.
TEST_CASE("guesses: an IPv6 address counts as its /64, IPv4 as itself") {
  CHECK(netctl::key_of("2001:db8:1::1") == "2001:db8:1::/64");
  CHECK(netctl::key_of("2001:db8:1::2") == "2001:db8:1::/64");
  CHECK(netctl::key_of("2001:db8:1:0:ffff:ffff:ffff:ffff") == "2001:db8:1::/64");
  CHECK(netctl::key_of("2001:db8:1:1::1") == "2001:db8:1:1::/64");
  CHECK(netctl::key_of("::1") == "::/64");
  CHECK(netctl::key_of("192.0.2.7") == "192.0.2.7");
  CHECK(netctl::key_of("::ffff:192.0.2.7") == "192.0.2.7");
  CHECK(netctl::key_of("not an address") == "not an address");
}

TEST_CASE("GuessGuard: after 4 wrong secrets from 2001:db8:1::1, 2001:db8:1::2 waits too (the repro)") {
  GuessPolicy p;
  p.lockout_after = 4;
  GuessGuard g(p);
  const auto t0 = GuessGuard::Clock::time_point{} + std::chrono::hours(1);
  auto t = t0;
  for (int i = 0; i < 3; ++i) {
    REQUIRE(g.free_at("2001:db8:1::1", t) <= t);
    CHECK_FALSE(g.wrong("2001:db8:1::1", t, "rotctld"));
    t = g.free_at("2001:db8:1::1", t);
  }
  // Its neighbour in the /64 is not answered at once: it pays the /64's 2 s (0.5, 1, then 2).
  CHECK(g.free_at("2001:db8:1::2", t0 + ms(1500)) == t0 + ms(3500));
  CHECK(g.wrong("2001:db8:1::2", t0 + ms(3500), "host"));
  CHECK(g.locked_until("2001:db8:1::ffff", t0 + ms(3600)) == t0 + ms(3500) + p.lockout_for);
  CHECK(g.lockout_cause("2001:db8:1::9") == "2001:db8:1::/64 (wrong secrets, the last from 2001:db8:1::2 on host)");
  // Another /64 is its own.
  CHECK(g.free_at("2001:db8:2::1", t0 + ms(3600)) == t0 + ms(3600));
}

TEST_CASE("GuessGuard: an exempted station is slowed, never locked out") {
  GuessPolicy p;
  p.lockout_after = 2;
  p.exempt.push_back(*inet::parse_cidr("192.0.2.0/24"));
  GuessGuard g(p);
  const auto t0 = GuessGuard::Clock::time_point{} + std::chrono::hours(1);
  CHECK_FALSE(g.wrong("192.0.2.5", t0));
  CHECK_FALSE(g.wrong("192.0.2.5", t0 + ms(500)));
  CHECK_FALSE(g.wrong("192.0.2.5", t0 + ms(1500)));
  CHECK(g.locked_until("192.0.2.5", t0 + ms(1500)) <= t0 + ms(1500));
  CHECK(g.free_at("192.0.2.5", t0 + ms(1500)) == t0 + ms(3500));
  CHECK_FALSE(g.wrong("198.51.100.1", t0));
  CHECK(g.wrong("198.51.100.1", t0 + ms(500)));
}

TEST_CASE("GuessGuard: a table full of locked-out addresses is neither scanned nor grown") {
  GuessPolicy p;
  p.lockout_after = 1;
  p.max_addresses = 4096;
  GuessGuard g(p);
  const auto t0 = GuessGuard::Clock::time_point{} + std::chrono::hours(1);
  for (int i = 0; i < 4096; ++i) CHECK(g.wrong("10.0." + std::to_string(i / 256) + "." + std::to_string(i % 256), t0));
  CHECK(g.size() == 4096);
  // 100,000 new addresses: they share one entry, slowed, never locked out (that would refuse every
  // newcomer), and the time is that of hash lookups, not of 100,000 scans of 4,096 entries.
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 100000; ++i) {
    const std::string a = "172.16." + std::to_string(i / 256 % 256) + "." + std::to_string(i % 256) + "/" + std::to_string(i);
    (void)g.locked_until(a, t0 + ms(1));
    CHECK_FALSE(g.wrong(a, t0 + ms(1)));
  }
  CHECK(g.size() == 4097);
  CHECK(g.failures("192.168.9.9") == 100000);
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));
  // When a lockout ends, its entry makes room at once.
  CHECK(g.free_at("192.168.1.1", t0 + p.lockout_for + ms(2)) == t0 + p.lockout_for + ms(2));
  CHECK(g.wrong("192.168.1.1", t0 + p.lockout_for + ms(2)));
  CHECK(g.failures("192.168.1.1") == 1);
  CHECK(g.size() == 4097);
}

TEST_CASE("server: one budget for every endpoint: a lockout on rotctld refuses the address on rigctld") {
  CapturedLog log;
  SimStation st;
  boost::asio::io_context io;
  auto shared = std::make_shared<GuessGuard>(with_secret({}).guesses);
  auto opts = [&](const char* name) {
    auto o = with_secret(netctl::RotctldServer::named(name));
    o.guard = shared;
    return o;
  };
  netctl::RotctldServer rot(io, 0, *st.station, opts("rotctld"));
  netctl::RigctldServer rig(io, 0, *st.station, opts("rigctld"));
  LoopThread lt(io, st);
  RawClient a(rot.port()), b(rig.port());
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  CHECK(a.ask("\\password guess1") == "RPRT -1\n");
  CHECK(b.ask("\\password guess2") == "RPRT -1\n");  // waited for rotctld's delay: one budget
  CHECK(a.ask("\\password guess3") == "RPRT -1\n");
  CHECK(b.ask("\\password guess4") == "RPRT -1\n");  // the fourth locks 127.0.0.1 out, everywhere
  RawClient c(rot.port());
  CHECK(c.closed_by_peer());
  CHECK(c.received() == "RPRT -9\n");
  lt.stop();
  const std::string text = log.text();
  CHECK(text.find("rotctld: connection from 127.0.0.1 refused: locked out until") != std::string::npos);
  CHECK(text.find("127.0.0.1 (wrong secrets, the last from 127.0.0.1 on rigctld)") != std::string::npos);
}
