// `trakbox status`: the running station's facts as one JSON document (built on the station's
// event loop, sent over the attach socket), the text `trakbox status` prints from it, and the
// exit status a script reads (docs/service.md).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "store/model.h"

namespace tb::app {

class StationApp;

// What the station's process adds to its facts.
struct StatusContext {
  std::string version;
  std::string state_dir;
  std::vector<std::string> attached;  // who is attached
  std::string keyboard;               // who has the keyboard
  bool service = false;
  // The TCP servers that run: port, clients, what they refused and why (netctl::ServerStats,
  // satrak::Server::Stats); none when not given.
  std::function<nlohmann::json()> servers;
};

nlohmann::json station_status(StationApp& app, const StatusContext& context);
// What is wrong, one line each ("rotator link: fault: no reply"); none when healthy.
std::vector<std::string> status_problems(const nlohmann::json& status);
// What a first start leaves to set ("setup" in the status, SETUP lines in its text, the page's
// Station card open): the factory's callsign, the factory's position. Not problems: the station
// works meanwhile.
std::vector<std::string> setup_needed(const store::Model& model);
// The document as a few lines for a person.
std::string format_status(const nlohmann::json& status);

// The document's "schema": raised when a field changes meaning or goes away (added fields keep it).
// 1: the first one numbered (issue 39): station, schema, los null for a satellite always up.
inline constexpr int kStatusSchema = 1;

// Exit statuses of `trakbox status` (as systemctl status: 3 for a station that is not running).
inline constexpr int kStatusHealthy = 0;
inline constexpr int kStatusUnhealthy = 1;
inline constexpr int kStatusNotRunning = 3;

}  // namespace tb::app
