// --on-event: commands run on the station's events (docs/service.md). Each runs under /bin/sh with
// the event in its environment (tracker/events.h: TRAKBOX_EVENT, TRAKBOX_SATELLITE, TRAKBOX_AOS,
// ...), in its own process group, never waited for by the station: its output and exit status go
// to the log when it ends; past the time limit its process group is killed (and the log says so),
// also after `sh` has ended when it left something running in the background ('(sleep 300) &'), and
// at the latest when trakbox stops (a command that leaves its process group with setsid escapes this);
// while a hook still runs for an event (a kind, and for AOS/LOS a satellite), it is not started
// again for the same one (the event is logged as skipped). A failed hook is logged, never retried.
#pragma once
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "util/loop_fwd.h"

namespace tb::tracker {
struct Event;
}

namespace tb::app {

struct EventHook {
  std::vector<std::string> kinds;  // empty: every kind
  std::string command;
};
// "CMD" (every event) or "KIND[,KIND...]=CMD"; nullopt with the reason when a kind is unknown.
std::optional<EventHook> parse_event_hook(const std::string& text, std::string& error);

class EventHooks {
 public:
  EventHooks(boost::asio::io_context& io, std::vector<EventHook> hooks, std::chrono::seconds limit,
             spdlog::logger& log);
  ~EventHooks();  // hooks still running are killed
  EventHooks(const EventHooks&) = delete;
  EventHooks& operator=(const EventHooks&) = delete;
  void fire(const tracker::Event& e);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tb::app
