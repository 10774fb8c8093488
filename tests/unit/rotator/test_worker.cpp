// WorkerRotator (rotator/worker.h), the worker thread the Hamlib and Satrak rotator drivers share,
// on a scripted link: connect, serve, refusals, losses and reconnects, and what is dropped.
#include <doctest/doctest.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "rotator/worker.h"

using namespace tb::rotator;
using namespace std::chrono_literals;

namespace {

// What the scripted link does and saw; shared between the test and the worker thread.
struct Script {
  std::mutex m;
  int open_failures = 0;          // the next opens that fail
  bool lose = false;              // the next poll loses the link
  bool silent = false;            // every poll goes unanswered (wrong speed, controller off)
  std::optional<std::string> refuse;  // go_to refuses with this
  AzEl position{12.5, 3.0};
  std::vector<std::string> calls;  // "open", "close", "stop", "goto 10.0/20.0" (polls not kept)
  std::atomic<int> polls_entered{0};

  void log(std::string c) {
    if (c != "poll") calls.push_back(std::move(c));
  }
  std::vector<std::string> seen() {
    std::lock_guard lk(m);
    return calls;
  }
};

class ScriptedLink final : public RotatorLink {
 public:
  explicit ScriptedLink(std::shared_ptr<Script> s) : s_(std::move(s)) {}
  bool open(std::string& error) override {
    std::lock_guard lk(s_->m);
    s_->log("open");
    if (s_->open_failures > 0) {
      --s_->open_failures;
      error = "no answer";
      return false;
    }
    return true;
  }
  void close() override {
    std::lock_guard lk(s_->m);
    s_->log("close");
  }
  Range az_range() override { return {-180.0, 180.0}; }
  bool stop(std::string&) override {
    std::lock_guard lk(s_->m);
    s_->log("stop");
    return true;
  }
  bool go_to(AzEl p, std::optional<std::string>& refusal, std::string&) override {
    std::lock_guard lk(s_->m);
    char buf[64];
    std::snprintf(buf, sizeof buf, "goto %.1f/%.1f", p.az, p.el);
    s_->log(buf);
    refusal = s_->refuse;
    return true;
  }
  bool poll(LinkReport& report, std::string& error) override {
    ++s_->polls_entered;
    std::lock_guard lk(s_->m);
    s_->log("poll");
    if (s_->lose || s_->silent) {
      s_->lose = false;
      error = s_->silent ? "timed out" : "gone";
      return false;
    }
    report.position = s_->position;
    report.motion = AxisMotion{Drive::increase, Drive::stop};
    report.limits = LimitFlags{{true, false}, {false, true}};
    return true;
  }

 private:
  std::shared_ptr<Script> s_;
};

bool wait_for(const std::function<bool()>& cond, std::chrono::milliseconds limit = 3s) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (!cond()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(5ms);
  }
  return true;
}

struct Rig {
  explicit Rig(int open_failures = 0, LinkTiming timing = {20ms, 200ms, 50ms, 400ms}) : script(std::make_shared<Script>()) {
    script->open_failures = open_failures;
    rot = std::make_unique<WorkerRotator>("scripted", std::make_unique<ScriptedLink>(script), timing);
  }
  std::shared_ptr<Script> script;
  std::unique_ptr<WorkerRotator> rot;
};

}  // namespace

TEST_CASE("WorkerRotator connects and answers from the link's last report") {
  spdlog::set_level(spdlog::level::off);
  Rig r;
  CHECK(r.rot->description() == "scripted");
  REQUIRE(wait_for([&] { return r.rot->read().has_value(); }));
  const Health h = r.rot->health();
  CHECK(h.state == LinkState::ok);
  CHECK(h.message.empty());
  CHECK(h.connects == 1);
  CHECK(r.rot->read()->az == 12.5);
  CHECK(r.rot->read()->el == 3.0);
  CHECK(r.rot->motion().az == Drive::increase);
  CHECK(r.rot->limits().az.low);
  CHECK(r.rot->limits().el.high);
  CHECK(r.rot->az_range().lo == -180.0);
  CHECK(r.rot->az_range().hi == 180.0);
}

TEST_CASE("WorkerRotator: stop goes first, the latest position wins, a refusal is a fault until one is accepted") {
  spdlog::set_level(spdlog::level::off);
  Rig r;
  REQUIRE(wait_for([&] { return r.rot->read().has_value(); }));
  {
    // Hold the worker inside a poll while the commands come in.
    std::lock_guard lk(r.script->m);
    const int polls = r.script->polls_entered;
    REQUIRE(wait_for([&] { return r.script->polls_entered > polls; }));
    r.rot->set_position({1.0, 2.0});
    r.rot->set_position({10.0, 20.0});
    r.rot->stop();  // drops the position given before it
    r.rot->set_position({30.0, 40.0});
    r.script->refuse = "refused GOTO=,30.00,40.00: GOTO=,ERR,3";
  }
  REQUIRE(wait_for([&] { return r.rot->health().state == LinkState::fault; }));
  CHECK(r.rot->health().message == "scripted refused GOTO=,30.00,40.00: GOTO=,ERR,3");
  CHECK(r.script->seen() == std::vector<std::string>{"open", "stop", "goto 30.0/40.0"});
  {
    std::lock_guard lk(r.script->m);
    r.script->refuse.reset();
  }
  r.rot->set_position({50.0, 60.0});
  REQUIRE(wait_for([&] { return r.rot->health().state == LinkState::ok; }));
  CHECK(r.rot->health().message.empty());
  CHECK(r.rot->health().connects == 1);  // the link stayed up
}

TEST_CASE("WorkerRotator: failed connects are faults retried with backoff") {
  spdlog::set_level(spdlog::level::off);
  Rig r(2, {20ms, 200ms, 200ms, 400ms});
  REQUIRE(wait_for([&] { return r.rot->health().state == LinkState::fault; }));
  CHECK(r.rot->health().message == "cannot connect to scripted: no answer; retrying in 200 ms");
  r.rot->set_position({1.0, 1.0});  // dropped: the link is down
  r.rot->stop();
  REQUIRE(wait_for([&] { return r.rot->health().state == LinkState::ok; }));
  CHECK(r.rot->health().connects == 1);
  std::this_thread::sleep_for(50ms);
  CHECK(r.script->seen() == std::vector<std::string>{"open", "open", "open"});
}

TEST_CASE("WorkerRotator: a lost link is closed, reported, its position forgotten, and reconnected") {
  spdlog::set_level(spdlog::level::off);
  Rig r(0, {20ms, 200ms, 500ms, 1000ms});
  REQUIRE(wait_for([&] { return r.rot->read().has_value(); }));
  {
    std::lock_guard lk(r.script->m);
    r.script->lose = true;
  }
  REQUIRE(wait_for([&] { return r.rot->health().state == LinkState::fault; }));
  CHECK(r.rot->health().message == "lost scripted: gone; motion stopped, reconnecting");
  CHECK_FALSE(r.rot->read().has_value());
  CHECK(r.rot->motion().az == Drive::stop);
  CHECK_FALSE(r.rot->limits().az.low);
  r.rot->set_position({5.0, 5.0});  // dropped, never replayed after the reconnect
  REQUIRE(wait_for([&] { return r.rot->health().connects == 2 && r.rot->read().has_value(); }));
  CHECK(r.rot->health().state == LinkState::ok);
  CHECK(r.script->seen() == std::vector<std::string>{"open", "close", "open"});
  r.rot.reset();  // the worker closes the link on its way out
  CHECK(r.script->seen() == std::vector<std::string>{"open", "close", "open", "close"});
}

TEST_CASE("WorkerRotator: open is not connected; a peer that never answers is one fault, with backoff") {
  spdlog::set_level(spdlog::level::off);
  auto script = std::make_shared<Script>();
  script->silent = true;
  // Backoff 50 ms doubling to 400 ms: in 1.5 s at most 1 + 50/50... about 6 opens, not one per poll.
  WorkerRotator rot("scripted", std::make_unique<ScriptedLink>(script), {20ms, 200ms, 50ms, 400ms});
  REQUIRE(wait_for([&] { return rot.health().state == LinkState::fault; }));
  std::vector<LinkState> states;
  const auto end = std::chrono::steady_clock::now() + 1500ms;
  while (std::chrono::steady_clock::now() < end) {
    states.push_back(rot.health().state);
    std::this_thread::sleep_for(5ms);
  }
  // Never ok in between (so no link-back / link-lost pairs), never counted as a connection.
  CHECK(std::count(states.begin(), states.end(), LinkState::ok) == 0);
  CHECK(rot.health().connects == 0);
  CHECK(rot.health().message.rfind("no answer from scripted: check the speed, the cable, the power", 0) == 0);
  CHECK_FALSE(rot.read().has_value());
  const auto calls = script->seen();
  const auto opens = std::count(calls.begin(), calls.end(), std::string("open"));
  CHECK(opens >= 3);
  CHECK(opens <= 8);   // 50 + 100 + 200 + 400 + 400 ... ms apart
  // It answers: connected, ok, once.
  {
    std::lock_guard lk(script->m);
    script->silent = false;
  }
  REQUIRE(wait_for([&] { return rot.health().state == LinkState::ok; }));
  CHECK(rot.health().connects == 1);
  CHECK(rot.read().has_value());
}
