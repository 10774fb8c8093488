// --satnogs-station ID: the station's SatNOGS calendar read every 10 minutes (issue 44). Each poll
// is one anonymous GET {--satnogs-url}/api/jobs/?ground_station=ID (no Authorization header: with
// the owner's token it is the station's heartbeat) with the element refresh's bounds (connect and
// total time, size), on the downloader's worker; the answer comes back on the event loop and its
// upcoming jobs become the station's SatNOGS windows (tracker/satnogs_jobs.h). A failed or
// malformed answer keeps the last good list and is a problem in status (StationLoop::satnogs_state).
#pragma once
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "util/loop_fwd.h"

namespace tb::tracker {
class StationLoop;
}

namespace tb::app {

class SatnogsPoll {
 public:
  SatnogsPoll(boost::asio::io_context& io, tracker::StationLoop& station, std::string base_url, int station_id,
              std::chrono::milliseconds timeout);
  ~SatnogsPoll();
  SatnogsPoll(const SatnogsPoll&) = delete;
  SatnogsPoll& operator=(const SatnogsPoll&) = delete;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

class StationApp;
// The poll of the stored --satnogs-station (none without one), and the warning when the SatNOGS
// flowgraph's rigctl port (4532) is trakbox's rigctld's too.
std::unique_ptr<SatnogsPoll> start_satnogs(StationApp& app, std::optional<int> rigctld_port,
                                           std::chrono::seconds timeout, spdlog::logger& log);

}  // namespace tb::app
