// The servers on loopback, with the io_context on a thread that also ticks the simulated station:
// Hamlib's own NET clients (rotctl -m 2, rigctl -m 2) drive trakbox, and clients that flood, never
// read or stay silent do not stall the loop or the other clients. Every wait is bounded; every
// child process is reaped.
#include <doctest/doctest.h>
#include "support/tools.h"
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>

#include "fixture.h"
#include "raw_client.h"
#include "netctl/host_server.h"
#include "netctl/server.h"

using namespace tb;
using namespace nettest;

namespace {

std::string port_arg(std::uint16_t port) { return "127.0.0.1:" + std::to_string(port); }

// Polls cond on the loop every 20 ms until it holds or the limit passes.
template <class F>
bool eventually(LoopThread& lt, F cond, std::chrono::milliseconds limit = 30s) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < end) {
    if (lt.on_loop(cond)) return true;
    std::this_thread::sleep_for(20ms);
  }
  return lt.on_loop(cond);
}

}  // namespace

TEST_CASE_FIXTURE(ServerCase, "server: Hamlib's rotctl -m 2 moves and reads the simulated antenna" * doctest::skip(tb::testing::skip_without({"rotctl"}))) {
  tb::testing::require_tools({"rotctl"});
  const auto rotctl = tb::testing::find_tool("rotctl");
  netctl::RotctldServer server(io, 0, *st.station);
  REQUIRE(server.port() != 0);
  LoopThread lt(io, st);

  const RunResult set = run({*rotctl, "-m", "2", "-r", port_arg(server.port()), "P", "120", "30"});
  CAPTURE(set.err);
  REQUIRE(!set.timed_out);
  CHECK(set.status == 0);
  CHECK(lt.on_loop([&] { return st.station->rotator().status().target.has_value(); }));
  // The station ticks on the loop until the antenna has arrived.
  REQUIRE(eventually(lt, [&] { return st.station->rotator().status().on_target; }));
  const rotator::AzEl truth = lt.on_loop([&] { return st.truth(); });
  CHECK(az_diff(truth.az, 120.0) < 1.1);
  CHECK(std::abs(truth.el - 30.0) < 0.36);

  const RunResult get = run({*rotctl, "-m", "2", "-r", port_arg(server.port()), "p"});
  CAPTURE(get.err);
  REQUIRE(!get.timed_out);
  CHECK(get.status == 0);
  const auto l = lines(get.out);
  REQUIRE(l.size() >= 2);
  CHECK(az_diff(std::stod(l[0]), truth.az) < 0.5);
  CHECK(std::abs(std::stod(l[1]) - truth.el) < 0.3);

  // A position the client's own limits (from \dump_state) refuse never reaches trakbox.
  const RunResult bad = run({*rotctl, "-m", "2", "-r", port_arg(server.port()), "P", "120", "95"});
  REQUIRE(!bad.timed_out);
  CHECK(lt.on_loop([&] { return st.station->rotator().status().target->el; }) == doctest::Approx(30.0));

  // S and K through the client.
  CHECK(run({*rotctl, "-m", "2", "-r", port_arg(server.port()), "S"}).status == 0);
  CHECK(lt.on_loop([&] { return st.station->rotator().status().mode; }) == rotator::ControlMode::idle);
  lt.stop();
  CHECK(lt.ticks() > 10);  // the station ticked all along
}

TEST_CASE_FIXTURE(ServerCase, "server: Hamlib's rigctl -m 2 tunes the downlink (F / f) and the uplink (I / i)" * doctest::skip(tb::testing::skip_without({"rigctl"}))) {
  tb::testing::require_tools({"rigctl"});
  const auto rigctl = tb::testing::find_tool("rigctl");
  netctl::RigctldServer server(io, 0, *st.station);
  LoopThread lt(io, st);
  const std::string where = port_arg(server.port());

  // Nothing tuned yet: the client reads the frequency when it opens and inside set_vfo/set_freq,
  // and gives a command up when that read fails.
  RunResult r = run({*rigctl, "-m", "2", "-r", where, "V", "VFOB", "F", "435120000", "v"});
  CAPTURE(r.out);
  CAPTURE(r.err);
  REQUIRE(!r.timed_out);
  CHECK(r.status == 0);
  CHECK(lt.on_loop([&] { return st.radio_sim->frequency(radio::Link::uplink); }) == 435120000);
  CHECK(!lt.on_loop([&] { return st.radio_sim->frequency(radio::Link::downlink); }));
  CHECK(r.out == "VFOB\n");

  r = run({*rigctl, "-m", "2", "-r", where, "V", "VFOA", "F", "145950000"});
  CAPTURE(r.out);
  CAPTURE(r.err);
  REQUIRE(!r.timed_out);
  CHECK(r.status == 0);
  CHECK(lt.on_loop([&] { return st.radio_sim->frequency(radio::Link::downlink); }) == 145950000);

  r = run({*rigctl, "-m", "2", "-r", where, "f"});
  REQUIRE(!r.timed_out);
  CHECK(r.status == 0);
  REQUIRE(!lines(r.out).empty());
  CHECK(lines(r.out)[0] == "145950000");

  r = run({*rigctl, "-m", "2", "-r", where, "I", "435100000"});
  REQUIRE(!r.timed_out);
  CHECK(r.status == 0);
  CHECK(lt.on_loop([&] { return st.radio_sim->frequency(radio::Link::uplink); }) == 435100000);
  CHECK(lt.on_loop([&] { return st.radio_sim->frequency(radio::Link::downlink); }) == 145950000);

  r = run({*rigctl, "-m", "2", "-r", where, "i"});
  REQUIRE(!r.timed_out);
  CHECK(r.status == 0);
  REQUIRE(!lines(r.out).empty());
  CHECK(lines(r.out)[0] == "435100000");

  // Several commands in one session: VFO B is the uplink; mode on each link.
  r = run({*rigctl, "-m", "2", "-r", where, "V", "VFOB", "F", "435110000", "M", "LSB", "0", "V", "VFOA", "M", "USB",
           "0", "m", "s"});
  CAPTURE(r.out);
  REQUIRE(!r.timed_out);
  CHECK(r.status == 0);
  CHECK(lt.on_loop([&] { return st.radio_sim->frequency(radio::Link::uplink); }) == 435110000);
  CHECK(lt.on_loop([&] { return st.radio_sim->mode(radio::Link::uplink); }) == radio::Mode::lsb);
  CHECK(lt.on_loop([&] { return st.radio_sim->mode(radio::Link::downlink); }) == radio::Mode::usb);
  CHECK(r.out.find("USB\n") != std::string::npos);

  // Split as a logging program sets it up: the client reads the TX frequency with i (or by
  // swapping VFOs), never with a plain f, because \dump_state says no VFO is targetable.
  r = run({*rigctl, "-m", "2", "-r", where, "S", "1", "VFOB", "I", "435130000", "X", "USB", "0", "i", "x", "s", "f"});
  CAPTURE(r.out);
  REQUIRE(!r.timed_out);
  CHECK(r.status == 0);
  CHECK(r.out == "435130000\nUSB\n0\n1\nVFOB\n145950000\n");
  CHECK(lt.on_loop([&] { return st.radio_sim->mode(radio::Link::uplink); }) == radio::Mode::usb);
  lt.stop();
}

TEST_CASE_FIXTURE(ServerCase, "server: a flooding, a non-reading and a silent client never stall the loop or the others") {
  netctl::RotctldServer rot(io, 0, *st.station);
  netctl::RigctldServer rig(io, 0, *st.station);
  LoopThread lt(io, st);

  RawClient silent(rot.port());  // connects and never says anything
  RawClient flood(rot.port());   // bytes without a newline, as fast as it can
  RawClient deaf(rig.port());    // asks and asks, never reads
  RawClient good(rot.port());
  RawClient good_rig(rig.port());
  REQUIRE(silent.ok());
  REQUIRE(flood.ok());
  REQUIRE(deaf.ok());
  REQUIRE(good.ok());
  REQUIRE(good_rig.ok());
  deaf.set_receive_buffer(4096);
  REQUIRE(eventually(lt, [&] { return rot.client_count() == 3 && rig.client_count() == 2; }, 5s));

  std::atomic<bool> stop{false};
  std::atomic<long> flooded{0}, deaf_sent{0};
  std::atomic<bool> deaf_dropped{false};
  std::thread flooder([&] {
    const std::string junk(16 * 1024, 'x');
    while (!stop) {
      const long n = flood.send_some(junk);
      if (n < 0) break;
      flooded += n;
      if (n == 0) std::this_thread::sleep_for(1ms);
    }
  });
  std::thread asker([&] {
    std::string many;
    for (int i = 0; i < 1000; ++i) many += "\\dump_state\n";
    while (!stop) {
      const long n = deaf.send_some(many);
      if (n < 0) {
        deaf_dropped = true;
        break;
      }
      deaf_sent += n;
      if (n == 0) std::this_thread::sleep_for(1ms);
    }
  });

  // Meanwhile the well-behaved clients get their answers and the station keeps ticking.
  const std::uint64_t ticks0 = lt.ticks();
  CHECK(good.ask("P 200 40") == "RPRT 0\n");
  for (int i = 0; i < 20; ++i) {
    const std::string r = good.ask("p", 2);
    CAPTURE(r);
    CHECK(lines(r).size() == 2);
    const std::string hz = std::to_string(145200000 + 10 * i);
    CHECK(good_rig.ask("F " + hz) == "RPRT 0\n");
    CHECK(good_rig.ask("f") == hz + "\n");
    std::this_thread::sleep_for(20ms);
  }
  REQUIRE(eventually(lt, [&] { return st.station->rotator().status().on_target; }));
  const rotator::AzEl truth = lt.on_loop([&] { return st.truth(); });
  CHECK(az_diff(truth.az, 200.0) < 1.1);
  CHECK(lt.ticks() > ticks0 + 20);

  // The client that never reads is disconnected once its replies pile up; the flooder was told
  // once that its line is too long and is still connected (it may yet send a newline).
  const auto drop_deadline = std::chrono::steady_clock::now() + 20s;
  while (!deaf_dropped && rig.client_count() == 2 && std::chrono::steady_clock::now() < drop_deadline)
    std::this_thread::sleep_for(20ms);
  CHECK(lt.on_loop([&] { return rig.client_count(); }) == 1);
  stop = true;
  flooder.join();
  asker.join();
  CHECK(flooded.load() > static_cast<long>(netctl::kMaxLineLength));
  CHECK(deaf_sent.load() > 64 * 1024 / 30);
  CHECK(flood.read_until([](const std::string& s) { return s.find('\n') != std::string::npos; }));
  CHECK(flood.received() == "RPRT -8\n");
  // The flooder ends its line: the next one is heard again.
  CHECK(flood.send_all("\np\n"));
  CHECK(flood.read_until([](const std::string& s) { return std::count(s.begin(), s.end(), '\n') >= 3; }));
  CHECK(lines(flood.received()).size() == 3);
  CHECK(lines(flood.received())[0] == "RPRT -8");
  // The silent client is still there and answered when it speaks.
  CHECK(silent.ask("_") == "trakbox rotator (simulated)\n");
  lt.stop();
}

TEST_CASE_FIXTURE(ServerCase, "server: q closes after the reply; a half-closed client still gets its answers") {
  netctl::RotctldServer rot(io, 0, *st.station);
  LoopThread lt(io, st);
  {
    RawClient c(rot.port());
    REQUIRE(c.ok());
    CHECK(c.send_all("_\nq\np\n"));
    CHECK(c.closed_by_peer());
    CHECK(c.received() == "trakbox rotator (simulated)\nRPRT 0\n");  // nothing after q
  }
  {
    RawClient c(rot.port());
    REQUIRE(c.ok());
    CHECK(c.send_all("P 10 10\nS\n_"));  // the last line has no newline
    c.shutdown_write();
    CHECK(c.closed_by_peer());
    CHECK(c.received() == "RPRT 0\nRPRT 0\ntrakbox rotator (simulated)\n");
  }
  REQUIRE(eventually(lt, [&] { return rot.client_count() == 0; }, 5s));
  lt.stop();
}

TEST_CASE_FIXTURE(ServerCase, "server: connections beyond max_clients are closed; close() drops everyone; port 0 and bind errors") {
  netctl::ServerOptions opt = netctl::RotctldServer::named("rotctld");
  opt.max_clients = 2;
  netctl::RotctldServer rot(io, 0, *st.station, opt);
  netctl::RigctldServer other(io, 0, *st.station);
  CHECK(rot.port() != other.port());
  // The same port twice: the second cannot listen, and says where.
  try {
    netctl::RigctldServer clash(io, rot.port(), *st.station);
    FAIL("listening twice on one port");
  } catch (const std::system_error& e) {
    CHECK(std::string(e.what()).find("127.0.0.1:" + std::to_string(rot.port())) != std::string::npos);
  }
  CHECK_THROWS_AS(netctl::RotctldServer(io, 0, *st.station, [] {
                    netctl::ServerOptions o;
                    o.address = "not-an-address";
                    return o;
                  }()),
                  std::system_error);

  LoopThread lt(io, st);
  RawClient a(rot.port()), b(rot.port());
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  CHECK(a.ask("_") == "trakbox rotator (simulated)\n");
  CHECK(b.ask("_") == "trakbox rotator (simulated)\n");
  RawClient c(rot.port());
  CHECK(c.closed_by_peer());
  CHECK(c.received() == "RPRT -9\n");  // both others spoke within evict_idle_after: refused, and told so
  CHECK(a.ask("_") == "trakbox rotator (simulated)\n");
  lt.on_loop([&] {
    rot.close();
    return 0;
  });
  CHECK(a.closed_by_peer());
  CHECK(b.closed_by_peer());
  CHECK(lt.on_loop([&] { return rot.client_count(); }) == 0u);
  lt.stop();
}

TEST_CASE_FIXTURE(ServerCase, "server: when every connection is taken, the one silent longest makes room (issue 14, defect 2)") {
  netctl::ServerOptions opt = netctl::RotctldServer::named("rotctld");
  opt.max_clients = 4;
  opt.evict_idle_after = 0ms;  // any silence is long enough: the order of last traffic decides
  netctl::RotctldServer rot(io, 0, *st.station, opt);
  LoopThread lt(io, st);
  RawClient idle1(rot.port()), idle2(rot.port()), poller(rot.port()), first(rot.port());
  REQUIRE(idle1.ok());
  REQUIRE(idle2.ok());
  REQUIRE(poller.ok());
  REQUIRE(eventually(lt, [&] { return rot.client_count() == 4; }, 5s));
  // idle1 and idle2 never send; the others (Gpredict's way) ask before each newcomer arrives.
  std::vector<std::unique_ptr<RawClient>> newcomers;
  for (int round = 0; round < 2; ++round) {
    CHECK(first.ask("_") == "trakbox rotator (simulated)\n");
    for (auto& n : newcomers) CHECK(n->ask("_") == "trakbox rotator (simulated)\n");
    CHECK(poller.ask("p").find('\n') != std::string::npos);
    newcomers.push_back(std::make_unique<RawClient>(rot.port()));
    CHECK(newcomers.back()->ask("_") == "trakbox rotator (simulated)\n");
    CHECK(rot.client_count() == 4);
  }
  // The two idle holders made room, oldest first; the poller kept its connection throughout.
  CHECK(idle1.closed_by_peer());
  CHECK(idle2.closed_by_peer());
  CHECK(poller.ask("_") == "trakbox rotator (simulated)\n");
}

TEST_CASE_FIXTURE(ServerCase, "host server: the banner and prompt, menu 7's commands over TCP, CR / LF / CR LF lines, Q closes") {
  netctl::HostServer host(io, 0, *st.station);
  LoopThread lt(io, st);
  const std::string prompt = "TrakBox>>";
  auto ends_with_prompts = [&](std::size_t n) {
    return [&prompt, n](const std::string& s) {
      std::size_t count = 0;
      for (std::size_t at = s.find(prompt); at != std::string::npos; at = s.find(prompt, at + 1)) ++count;
      return count >= n;
    };
  };

  RawClient c(host.port());
  REQUIRE(c.ok());
  REQUIRE(c.read_until(ends_with_prompts(1)));
  CHECK(c.received() ==
        "TrakBox host mode.\r\nCommand:MUxxx,MDxxx,FUxxx,FDxxx,AZxxx_ELxx,Sxxx,Q,?A,?\r\nAlso:RF,?R,LOG,?C,STANDBY,PB,OR,OT,CT,MODE,?T,QTH (? explains each)\r\nTrakBox>>");

  // A terminal program sends CR, a script LF, telnet CR LF: one command each, one prompt each.
  CHECK(c.send_all("AZ120 EL30\rFD43580000\nMDUSB\r\n"));
  REQUIRE(c.read_until(ends_with_prompts(4)));
  CHECK(c.received().substr(c.received().size() - 3 * prompt.size()) == prompt + prompt + prompt);
  CHECK(lt.on_loop([&] { return st.station->rotor_control(); }));
  REQUIRE(eventually(lt, [&] { return st.station->rotator().status().on_target; }));
  const rotator::AzEl truth = lt.on_loop([&] { return st.truth(); });
  CHECK(az_diff(truth.az, 120.0) < 1.1);
  CHECK(std::abs(truth.el - 30.0) < 1.1);
  const radio::RadioStatus rs = lt.on_loop([&] { return st.station->radio().status(); });
  CHECK(rs.downlink_hz == radio::Hz{435800000});
  CHECK(rs.downlink_mode == radio::Mode::usb);

  // ?A reports where the antenna is; a bad command gets one ERROR line and the prompt, nothing moves.
  const std::string a = c.exchange("?A\r", prompt);
  CAPTURE(a);
  double az = 0, el = 0;
  REQUIRE(std::sscanf(a.c_str(), "AZ%lf EL%lf\r\nTrakBox>>", &az, &el) == 2);
  CHECK(az_diff(az, 120.0) < 1.1);
  CHECK(std::abs(el - 30.0) < 1.1);
  CHECK(a.size() == std::string("AZ120.0 EL30.0\r\nTrakBox>>").size());
  const std::string bad = c.exchange("FD0\r", prompt);
  CHECK(bad.rfind("ERROR FD: '0' is not a frequency", 0) == 0);
  CHECK(bad.find("\r\nTrakBox>>") == bad.size() - prompt.size() - 2);
  CHECK(lt.on_loop([&] { return st.station->radio().status().downlink_hz; }) == radio::Hz{435800000});

  // Control bytes never reach the reply raw; an overlong line is refused once, then heard again.
  const std::string garbage = c.exchange(std::string("zz\x01\x7f\n"), prompt);
  CHECK(garbage.rfind("ERROR unknown command", 0) == 0);
  CHECK(garbage.find('\x01') == std::string::npos);
  RawClient d(host.port());
  REQUIRE(d.read_until(ends_with_prompts(1)));
  CHECK(d.send_all(std::string(netctl::kMaxHostLine + 10, 'A') + "\r?A\r"));
  REQUIRE(d.read_until(ends_with_prompts(3)));
  CHECK(d.received().find("ERROR line too long: at most 256 characters\r\nTrakBox>>") != std::string::npos);
  CHECK(d.received().find("characters\r\nTrakBox>>AZ1") != std::string::npos);

  // Q closes that client only.
  CHECK(c.send_all("q\r"));
  CHECK(c.closed_by_peer());
  CHECK(eventually(lt, [&] { return host.client_count() == 1; }, 5s));
  lt.stop();
}
