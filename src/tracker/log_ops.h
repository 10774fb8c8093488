// Logging a QSO in one step, from any front end (the page, menu 1's key, host LOG, `trakbox log
// add`, POST /api/v1/log): the operator gives the call (and maybe the grid, the reports, a note);
// everything else comes from the pass being tracked as the station knows it now: the satellite
// (its database name, NORAD number and TQSL's name), the mode, both links nominal (the Tuner's spot
// in the satellite's frame, where the transponder is) and as tuned (the last frequencies sent),
// the time, the station's callsign and grid. The QSO is on disk (committed) when log() returns ok.
//
// LogOps, like StationOps, holds references only: make one where it is needed. The logbook itself
// and the names table are the program's (tracker_app), reached through StationLoop::logging().
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "logbook/logbook.h"
#include "logbook/lotw_names.h"

namespace tb::tracker {

class StationLoop;

// The logger's uploader (live/logger_upload.h) as status shows it: never its key.
struct LoggerStatus {
  std::string kind;                        // "cloudlog", "wavelog"
  std::string url;                         // the base URL, a password in it redacted
  std::string last_upload, last_radio_post;  // ISO 8601 UTC (the station's clock), "" before the first
  std::optional<std::string> problem;      // the QSO uploads fail (cleared by one that succeeds)
  std::optional<std::string> radio_problem;  // the last radio-state post failed
};

// What the program keeps for logging: the logbook (none when it could not be opened: logging is
// then refused with the reason), the NORAD to LoTW table, and the logger's hook (a QSO to upload
// is queued in the same transaction when one is configured; the hook then wakes the uploader).
struct Logging {
  std::unique_ptr<logbook::Logbook> book;
  std::string open_error;              // why there is no book
  logbook::LotwNames names;
  bool upload = false;                 // a logger is configured: queue each QSO
  std::function<void()> on_logged;     // after a commit (the uploader's wake-up); may be empty
  std::optional<LoggerStatus> logger;  // set while a logger is configured
};

struct LogRequest {
  std::string call, grid, rst_sent, rst_rcvd, note;
  logbook::Source source = logbook::Source::cli;
  std::string sat;                      // a database satellite by name; "" the one tracked
  std::string mode;                     // the emission; "" the tracked radio mode's
  std::optional<std::int64_t> time_on;  // UTC seconds; none: now
  double power_w = 0;
};

struct LogResult {
  std::optional<std::string> refusal;   // nothing stored when set
  logbook::Qso qso;                     // as stored (with its id)
  // Stored, but worth a word: the satellite was below the station's horizon at the QSO's time
  // ("SO-50 was below the horizon here (-12.3 deg) at 21:44:20 UTC").
  std::optional<std::string> warning;
  bool ok() const { return !refusal; }
};

class LogOps {
 public:
  explicit LogOps(StationLoop& station);

  // The QSO filled from the station and stored; the refusal names the field ("call: ...").
  LogResult log(const LogRequest& r);
  // A record for a request without storing it (what log() would store).
  LogResult fill(const LogRequest& r) const;

  Logging* logging() const { return logging_; }
  // The logbook, or the refusal why there is none.
  logbook::Logbook* book(std::string& why) const;

 private:
  StationLoop& station_;
  Logging* logging_;
};

}  // namespace tb::tracker
