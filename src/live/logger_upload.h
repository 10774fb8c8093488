// --logger cloudlog:URL|wavelog:URL (docs/logbook.md): the logger's two jobs on the event loop, the
// requests on the downloader's worker, one at a time.
//  - The radio state (api/radio): what the station tracks and the radio's frequencies and modes as
//    tuned, looked at every second and posted when logbook::radio_post_due says so (a change, every
//    5 minutes while tracking, once when tracking ends).
//  - The QSOs (api/qso): each QSO logged is queued in the logbook in its own transaction
//    (Logging::upload); the uploader sends the due entries of the queue one at a time, marks one
//    done only on a reply that says the logger stored it, and otherwise puts it back with the
//    backoff (logbook::upload_backoff_s) and a problem in status until one succeeds. The queue is
//    on disk: what a restart interrupts is sent again (a logger that already has it answers
//    "Duplicate", which counts as done).
// The key is read from --logger-key-file at the start and kept here only: never in a log line, a
// reply, status or the state file (which keeps the file's path).
#pragma once
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "logbook/logger.h"

namespace spdlog {
class logger;
}
namespace tb::tracker {
struct Logging;
}
namespace tb::store {
struct LoggerConfig;
}

namespace tb::app {

struct LoggerSettings {
  logbook::LoggerSpec spec;
  std::string key;
  int station_id = 0;                      // Cloudlog's station_profile_id
  std::chrono::milliseconds timeout{30000};
};

class StationApp;

class LoggerUpload {
 public:
  // On the app's event loop and station; `logging` (the app's) outlives it.
  LoggerUpload(StationApp& app, tracker::Logging& logging, LoggerSettings settings);
  ~LoggerUpload();
  LoggerUpload(const LoggerUpload&) = delete;
  LoggerUpload& operator=(const LoggerUpload&) = delete;
  // A QSO was queued: send it now rather than at the next second.
  void wake();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The key of a key file: its first line, trimmed; the refusal names the file ("--logger-key-file
// /x/key: ..."); `warning` is set when others may read it.
std::optional<std::string> read_logger_key(const std::string& path, std::string& key, std::string& warning);

// The uploader of the stored --logger (none without one). A logger without a readable key or a
// station id is the returned refusal; the caller decides what it costs (logger_not_started).
std::optional<std::string> start_logger(StationApp& app, tracker::Logging& logging, std::chrono::seconds timeout,
                                        std::unique_ptr<LoggerUpload>& out);

// A stored logger that could not start (its key file gone since it was set): the QSOs are still
// queued (nothing is lost for the logger), status' log.logger carries the reason as its problem,
// and the log and standard error say it once.
void logger_not_started(const store::LoggerConfig& c, tracker::Logging& logging, const std::string& why,
                        spdlog::logger& log);

}  // namespace tb::app
