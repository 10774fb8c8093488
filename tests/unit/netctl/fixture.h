// A whole simulated station (support/sim_station.h's StationFixture: SimulatedRotator,
// SimulatedRadio, StationLoop, a clock the test moves) for the netctl tests, and helpers for
// talking to the servers: an io_context on a thread that also ticks the station (so every station
// call happens on one thread, as in the program), loopback clients, bounded child processes.
#pragma once
#include <doctest/doctest.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <spdlog/spdlog.h>
#include <sys/wait.h>
#include <unistd.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/sim_station.h"

extern char** environ;

namespace nettest {

using namespace std::chrono_literals;
using namespace tb;

inline const bool kQuietLogs = [] {
  spdlog::set_level(spdlog::level::off);
  return true;
}();

// The shared StationFixture on the test's model (default: the factory settings alone), its station
// built, rotor control as asked, and a first reading taken.
struct SimStation : tb::testing::StationFixture {
  explicit SimStation(store::Model m = {}, bool rotor_control = true)
      : StationFixture(orbit::from_civil(2026, 5, 21, 12, 0, 0), std::move(m)) {
    build_station();
    station->set_rotor_control(rotor_control);
    station->tick();  // a first reading
  }
  void step(std::chrono::milliseconds dt = 100ms) { StationFixture::step(dt); }
  // Ticks (simulated time only) until the rotator is on its target and has stopped coasting, at
  // most `limit`.
  bool settle(std::chrono::seconds limit = 300s) {
    for (auto t = 0ms; t < limit; t += 100ms) {
      step();
      if (station->rotator().status().on_target && std::abs(rotator_sim->true_velocity(rotator::Axis::az)) < 0.01 &&
          std::abs(rotator_sim->true_velocity(rotator::Axis::el)) < 0.01)
        return true;
    }
    return false;
  }
};

// A protocol (netctl::RigctlProtocol, netctl::RotctlProtocol) on a fresh station: what most
// protocol cases start from, as TEST_CASE_FIXTURE(ProtocolOn<...>, ...) with `st` and `p`.
template <class Protocol>
struct ProtocolOn {
  SimStation st;
  Protocol p{*st.station};
};

// The protocol's whole reply to one request line.
template <class Protocol>
std::string ask(Protocol& p, std::string_view line) {
  return p.handle(line).text;
}

// Smallest angle between two azimuths.
inline double az_diff(double a, double b) {
  double d = std::fmod(std::abs(a - b), 360.0);
  return d > 180.0 ? 360.0 - d : d;
}

// The event loop on a thread of its own for the duration of a test: the servers and a timer that
// advances the simulated clock and ticks the station run there. The test thread touches the
// station only through on_loop().
class LoopThread {
 public:
  // Every `period` of real time the station's clock moves `sim_step` and the station ticks.
  LoopThread(boost::asio::io_context& io, SimStation& st, std::chrono::milliseconds period = 10ms,
             std::chrono::milliseconds sim_step = 100ms)
      : io_(io), st_(st), timer_(io), period_(period), sim_step_(sim_step) {
    arm();
    thread_ = std::thread([this] { io_.run(); });
  }
  ~LoopThread() { stop(); }
  void stop() {
    if (!thread_.joinable()) return;
    boost::asio::post(io_, [this] {
      stopping_ = true;
      timer_.cancel();
      io_.stop();
    });
    thread_.join();
  }
  // Runs f on the loop and returns its result (bounded wait; throws when the loop does not answer).
  template <class F>
  auto on_loop(F f) -> decltype(f()) {
    using R = decltype(f());
    auto task = std::make_shared<std::packaged_task<R()>>(std::move(f));
    auto fut = task->get_future();
    boost::asio::post(io_, [task] { (*task)(); });
    if (fut.wait_for(10s) != std::future_status::ready) throw std::runtime_error("event loop did not answer");
    return fut.get();
  }
  std::uint64_t ticks() const { return ticks_.load(); }

 private:
  void arm() {
    timer_.expires_after(period_);
    timer_.async_wait([this](const boost::system::error_code& ec) {
      if (ec || stopping_) return;
      st_.step(sim_step_);
      ++ticks_;
      arm();
    });
  }
  boost::asio::io_context& io_;
  SimStation& st_;
  boost::asio::steady_timer timer_;
  std::chrono::milliseconds period_, sim_step_;
  bool stopping_ = false;
  std::atomic<std::uint64_t> ticks_{0};
  std::thread thread_;
};

// A fresh station and the io_context its servers run on: where the server cases start, as
// TEST_CASE_FIXTURE(ServerCase, ...) with `st` and `io`; the case makes its servers, then its
// LoopThread (which stops first, before the servers go).
struct ServerCase {
  SimStation st;
  boost::asio::io_context io;
};

// Runs a program to completion with a time limit, capturing stdout and stderr. Killed (by its
// pid) and reaped when the limit passes.
struct RunResult {
  int status = -1;        // exit status, -1 when killed or not started
  bool timed_out = false;
  std::string out, err;
};
inline RunResult run(const std::vector<std::string>& argv, std::chrono::milliseconds limit = 20s) {
  RunResult r;
  int outp[2], errp[2];
  if (::pipe(outp) != 0) return r;
  if (::pipe(errp) != 0) {
    ::close(outp[0]);
    ::close(outp[1]);
    return r;
  }
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&fa, outp[1], 1);
  posix_spawn_file_actions_adddup2(&fa, errp[1], 2);
  posix_spawn_file_actions_addclose(&fa, outp[0]);
  posix_spawn_file_actions_addclose(&fa, errp[0]);
  posix_spawn_file_actions_addclose(&fa, outp[1]);
  posix_spawn_file_actions_addclose(&fa, errp[1]);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, argv[0].c_str(), &fa, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  ::close(outp[1]);
  ::close(errp[1]);
  if (rc != 0) {
    ::close(outp[0]);
    ::close(errp[0]);
    return r;
  }
  const auto end = std::chrono::steady_clock::now() + limit;
  pollfd fds[2] = {{outp[0], POLLIN, 0}, {errp[0], POLLIN, 0}};
  int open_fds = 2;
  while (open_fds > 0) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      r.timed_out = true;
      break;
    }
    if (::poll(fds, 2, static_cast<int>(std::min<long long>(left.count(), 200))) < 0) break;
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      char buf[4096];
      const ssize_t n = ::read(fds[i].fd, buf, sizeof buf);
      if (n <= 0) {
        ::close(fds[i].fd);
        fds[i].fd = -1;
        --open_fds;
      } else {
        (i == 0 ? r.out : r.err).append(buf, static_cast<std::size_t>(n));
      }
    }
  }
  for (auto& f : fds)
    if (f.fd >= 0) ::close(f.fd);
  int st = 0;
  if (r.timed_out) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &st, 0);
    return r;
  }
  // Output closed: the child is exiting; still bounded.
  for (;;) {
    const pid_t w = ::waitpid(pid, &st, WNOHANG);
    if (w == pid) break;
    if (std::chrono::steady_clock::now() > end) {
      r.timed_out = true;
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &st, 0);
      return r;
    }
    std::this_thread::sleep_for(5ms);
  }
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

inline std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string l;
  while (std::getline(ss, l)) out.push_back(l);
  return out;
}

}  // namespace nettest

#include "support/shipped_model.h"

namespace nettest {

// The shipped element sets and freq/mode table (data/), as trakbox loads them, in Tucson.
inline store::Model shipped_model() { return tb::testing::shipped_model_in_tucson(); }

}  // namespace nettest
