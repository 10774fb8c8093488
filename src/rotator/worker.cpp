#include "rotator/worker.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <condition_variable>
#include <mutex>

namespace tb::rotator {

using SteadyClock = std::chrono::steady_clock;

struct WorkerRotator::Shared {
  std::string label;
  std::unique_ptr<RotatorLink> link;  // used by the worker only
  LinkTiming timing;
  std::mutex m;
  std::condition_variable cv;
  bool quit = false;
  bool done = false;
  // Commands for the worker.
  std::optional<AzEl> pending_pos;
  bool pending_stop = false;
  // The worker's report.
  bool connected = false;
  Health health{LinkState::connecting, "connecting", 0};
  std::optional<AzEl> pos;
  AxisMotion motion;
  LimitFlags limits;
  Range az_range{0.0, 360.0};
  std::string alarm;                   // the controller's last alarm line, while it is shown
  SteadyClock::time_point alarm_at{};

  void run();
  void note_alarm(const LinkReport& report);  // under m
  std::string serve();
  void set_fault(const std::string& message);
  bool wait(std::chrono::milliseconds d);  // false when told to quit
};

void WorkerRotator::Shared::note_alarm(const LinkReport& report) {
  const auto now = SteadyClock::now();
  if (report.alarm) {
    if (*report.alarm != alarm) spdlog::warn("rotator: {} reports an alarm: {}", label, *report.alarm);
    alarm = *report.alarm;
    alarm_at = now;
    health.state = LinkState::fault;
    health.message = label + " reports an alarm: " + alarm;
  } else if (!alarm.empty() && now - alarm_at > std::chrono::seconds(10)) {
    spdlog::info("rotator: {}: no alarm for 10 s", label);
    alarm.clear();
    health.state = LinkState::ok;
    health.message.clear();
  }
}

bool WorkerRotator::Shared::wait(std::chrono::milliseconds d) {
  std::unique_lock lk(m);
  cv.wait_for(lk, d, [&] { return quit; });
  return !quit;
}

void WorkerRotator::Shared::set_fault(const std::string& message) {
  std::lock_guard lk(m);
  connected = false;
  health.state = LinkState::fault;
  health.message = message;
  pos.reset();
  motion = {};
  limits = {};
  pending_pos.reset();  // motion commands stop: nothing queued is replayed after a reconnect
  pending_stop = false;
  alarm.clear();        // the link's fault is what the health says now
}

void WorkerRotator::Shared::run() {
  auto backoff = timing.backoff_min;
  bool reported = false;  // a failed attempt has been logged since the last success
  for (;;) {
    {
      std::lock_guard lk(m);
      if (quit) break;
    }
    std::string error;
    if (!link->open(error)) {
      const std::string msg = "cannot connect to " + label + ": " + error + "; retrying in " +
                              std::to_string(backoff.count()) + " ms";
      set_fault(msg);
      if (!reported) spdlog::warn("rotator: {}", msg);
      reported = true;
      if (!wait(backoff)) break;
      backoff = std::min(backoff * 2, timing.backoff_max);
      continue;
    }
    // Open is not connected: the first valid reply is.
    LinkReport first;
    if (!link->poll(first, error)) {
      const std::string who = link->peer().empty() ? label : link->peer();
      link->close();
      const std::string msg = "no answer from " + who + ": " + link->silent_hint() + " (" + error + ")";
      set_fault(msg);
      if (!reported) spdlog::warn("rotator: {}; trying again, less often each time", msg);
      reported = true;
      if (!wait(backoff)) break;
      backoff = std::min(backoff * 2, timing.backoff_max);
      continue;
    }
    {
      std::lock_guard lk(m);
      // The whole first report, as every later one (its motion was dropped: a test saw "stopped"
      // while the rotator said it was turning, until the next poll).
      if (first.position) pos = first.position;
      if (first.motion) motion = *first.motion;
      if (first.limits) limits = *first.limits;
      connected = true;
      health.state = LinkState::ok;
      health.message.clear();
      ++health.connects;
      pending_pos.reset();
      pending_stop = false;
      az_range = link->az_range();
      if (az_range.empty()) az_range = {0.0, 360.0};
    }
    spdlog::info("rotator: connected to {}", label);
    reported = false;
    backoff = timing.backoff_min;

    const std::string lost = serve();
    link->close();
    {
      std::lock_guard lk(m);
      if (quit) break;
    }
    const std::string msg = "lost " + label + ": " + lost + "; motion stopped, reconnecting";
    set_fault(msg);
    spdlog::warn("rotator: {}", msg);
    reported = false;
    if (!wait(backoff)) break;
  }
  std::lock_guard lk(m);
  connected = false;
  done = true;
  cv.notify_all();
}

// Serves the open link until it is lost (returns why) or the worker is told to quit.
std::string WorkerRotator::Shared::serve() {
  auto next_poll = SteadyClock::now();
  for (;;) {
    std::optional<AzEl> cmd;
    bool stop_now = false;
    {
      std::unique_lock lk(m);
      cv.wait_until(lk, next_poll, [&] { return quit || pending_stop || pending_pos.has_value(); });
      if (quit) return {};
      stop_now = pending_stop;
      pending_stop = false;
      cmd = pending_pos;
      pending_pos.reset();
    }
    std::string error;
    if (stop_now && !link->stop(error)) return error;
    if (cmd) {
      std::optional<std::string> refusal;
      if (!link->go_to(*cmd, refusal, error)) return error;
      std::lock_guard lk(m);
      if (refusal) {
        health.state = LinkState::fault;
        health.message = label + " " + *refusal;
      } else if (health.state == LinkState::fault && alarm.empty()) {
        health.state = LinkState::ok;
        health.message.clear();
      }
    }
    if (SteadyClock::now() >= next_poll) {
      LinkReport report;
      if (!link->poll(report, error)) return error;
      {
        std::lock_guard lk(m);
        if (report.position) pos = report.position;
        if (report.motion) motion = *report.motion;
        if (report.limits) limits = *report.limits;
        note_alarm(report);
      }
      next_poll = SteadyClock::now() + timing.poll;
    }
  }
}

WorkerRotator::WorkerRotator(std::string label, std::unique_ptr<RotatorLink> link, LinkTiming timing)
    : s_(std::make_shared<Shared>()) {
  s_->label = std::move(label);
  s_->link = std::move(link);
  s_->timing = timing;
  s_->health = {LinkState::connecting, "connecting to " + s_->label, 0};
  worker_ = std::thread([s = s_] { s->run(); });
}

WorkerRotator::~WorkerRotator() {
  std::unique_lock lk(s_->m);
  s_->quit = true;
  s_->cv.notify_all();
  const auto patience = 2 * s_->timing.io_timeout + std::chrono::seconds(1);
  const bool finished = s_->cv.wait_for(lk, patience, [&] { return s_->done; });
  lk.unlock();
  if (finished)
    worker_.join();
  else
    worker_.detach();  // stuck in a blocking call; it holds its own reference to the shared state
}

std::string WorkerRotator::description() const { return s_->label; }

Health WorkerRotator::health() {
  std::lock_guard lk(s_->m);
  return s_->health;
}

AxisMotion WorkerRotator::motion() {
  std::lock_guard lk(s_->m);
  return s_->motion;
}

LimitFlags WorkerRotator::limits() {
  std::lock_guard lk(s_->m);
  return s_->limits;
}

void WorkerRotator::stop() {
  std::lock_guard lk(s_->m);
  s_->pending_pos.reset();
  if (s_->connected) s_->pending_stop = true;
  s_->cv.notify_all();
}

std::optional<AzEl> WorkerRotator::read() {
  std::lock_guard lk(s_->m);
  return s_->pos;
}

void WorkerRotator::set_position(AzEl p) {
  std::lock_guard lk(s_->m);
  if (!s_->connected) return;  // dropped while the link is down
  s_->pending_pos = p;
  s_->cv.notify_all();
}

Range WorkerRotator::az_range() {
  std::lock_guard lk(s_->m);
  return s_->az_range;
}

}  // namespace tb::rotator
