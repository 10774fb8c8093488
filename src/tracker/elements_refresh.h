// The scheduled refresh of the menu-3 database (issue 12, "Keeping the database current"): every
// RefreshSettings::interval_hours of wall time (never more often than every 2 hours) and on
// "refresh now" (menu 3-5, host mode RF), each configured source is downloaded on a worker thread
// (download::Downloader: redirects followed, conditional requests with the last answer's validators)
// and the sets it holds replace older sets of the same catalog number (store::apply_refresh).
//
// Nothing here blocks the event loop: downloads run on the worker, their results are posted back
// and applied there. A source whose download fails, times out, answers an HTTP error or a body
// that is not element data (CelesTrak's plain-text "No GP data found") changes nothing: the
// database keeps its last good sets. What happened goes to the log and to last_result() (the
// status line, host mode ?R, menu 3-5).
#pragma once
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "orbit/time.h"
#include "store/owner.h"

namespace tb::download {
class Downloader;
struct DownloadResult;
}  // namespace tb::download
namespace tb::station {
class Clock;
}

namespace tb::tracker {

// What the status line says of the elements (pure, for the tests): nothing while they are current
// and nothing went wrong; otherwise how old they are and what to do about it.
struct RefreshState {
  bool has_sources = false;
  bool running = false;
  bool attempted = false;  // a refresh finished since the start
  bool failed = false;     // ... and a source of it failed
  int updated = 0;
  std::optional<double> stale_days;  // the database's youngest set, when every set is too old
  // Not attempted since the start because the last one (before a restart) was within the
  // interval: the hours until the next one (a restarting station does not ask the servers sooner).
  std::optional<double> next_in_hours;
};
std::string refresh_status_text(const RefreshState& s);

class ElementsRefresh {
 public:
  // post: runs a function on the event-loop thread (download results arrive on the worker).
  // changed: a refresh ended (the database and the refresh settings are changed through the
  // model's owner, which saves and announces them; the tracker sees new elements).
  using Post = std::function<void(std::function<void()>)>;
  ElementsRefresh(store::ModelOwner& owner, Post post, std::function<void()> changed);
  ~ElementsRefresh();
  ElementsRefresh(const ElementsRefresh&) = delete;
  ElementsRefresh& operator=(const ElementsRefresh&) = delete;

  // The wall clock (unix seconds), which the schedule counts in: servers count real hours, whatever
  // the station's clock (--clock, --clock-rate) says.
  static std::int64_t wall_now();

  // Every tick, with the wall clock (unix seconds): starts the scheduled refresh when it is due.
  void poll(std::int64_t now_unix);
  // Starts a refresh now (the interval does not apply to a refresh the operator asks for).
  // The reason when it cannot: no source configured, or one is running.
  std::optional<std::string> refresh_now(std::int64_t now_unix);
  bool running() const { return pending_ > 0; }

  // Manual refreshes (StationOps::refresh_elements, issue 46) come at most once per
  // kManualEvery per source, counted in the station's time: when the next may come (a time after
  // `now`), or nullopt when it may come now; note_manual says one came at `now` for every source.
  static constexpr std::chrono::minutes kManualEvery{10};
  // The station's clock (--clock, --clock-rate) the limit counts in; without one, the system's.
  void set_station_clock(const station::Clock* clock) { station_clock_ = clock; }
  orbit::UtcTime station_now() const;
  std::optional<orbit::UtcTime> manual_next(orbit::UtcTime now) const;
  void note_manual(orbit::UtcTime now);

  // The outcome of the last refresh, one line ("" before the first); whether it failed (any source).
  const std::string& last_result() const { return last_result_; }
  bool last_failed() const { return last_failed_; }
  // A short form for the status line at the station's time `now` (refresh_status_text).
  std::string status_word(orbit::UtcTime now) const;

  // Bounds of one download (default 60 s; `--elements-timeout`).
  void set_timeout(std::chrono::milliseconds t) { timeout_ = t; }

 private:
  struct Outcome;
  void start(std::int64_t now_unix);
  void finished(const std::string& url, download::DownloadResult r);
  void complete();

  store::ModelOwner& owner_;
  const store::Model& model_;
  Post post_;
  std::function<void()> changed_;
  std::unique_ptr<download::Downloader> downloader_;
  std::shared_ptr<int> alive_ = std::make_shared<int>(0);
  std::chrono::milliseconds timeout_{60000};
  int pending_ = 0;
  std::vector<Outcome> outcomes_;
  std::string last_result_;
  bool last_failed_ = false;
  int last_updated_ = 0;
  std::vector<std::pair<std::string, orbit::UtcTime>> manual_;  // source URL -> its last manual refresh
  const station::Clock* station_clock_ = nullptr;
};

}  // namespace tb::tracker
