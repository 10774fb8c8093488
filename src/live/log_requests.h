// The logbook in the running program (docs/logbook.md): opened at STATE/logbook.sqlite with the
// NORAD to LoTW table of the data directory, handed to the station (tracker::LogOps reaches it);
// the station socket's "log {json}" requests (`trakbox log add|list|export|import`); and the
// `trakbox log` command, which asks the running station, or with none running opens the state
// directory's logbook itself for list, export and import.
//
// Work that grows with the logbook never runs whole on the station's loop (issue 56, items 4 and
// 8): list and export answer one page per request (at most kSocketPage records, the client asks
// for the next with the "next" cursor), and an import (up to 16 MiB of ADIF) is parsed, checked
// and stored on a worker thread with its own connection to the logbook (SQLite WAL), its answer
// posted back to the loop once its transaction committed (or nothing was stored).
#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace tb::tracker {
struct Logging;
}
namespace tb::logbook {
class Logbook;
}

namespace tb::app {

class StationApp;

inline constexpr std::size_t kSocketPage = 100;  // records one socket reply holds at most (its 256 kB)

// Opens the logbook and sets it on the station; a logbook that cannot be opened is logged and
// reported in status, and logging is refused with the reason (the station runs on).
// The logbook is STATE/logbook.sqlite; the LoTW names come from the data directory.
std::unique_ptr<tracker::Logging> open_logging(StationApp& app, const std::filesystem::path& state_dir,
                                               const std::string& data_dir);

// The socket's "log {json}" requests: {"action": "add"|"list"|"export"|"import", ...} -> its JSON
// reply ({"ok": true, ...} or {"error": "..."}), given to `reply` on the loop: at once, or for an
// import when the worker is done. Never throws. At most one import at a time (a second is refused
// while one runs); the destructor waits for one under way.
class LogRequests {
 public:
  explicit LogRequests(StationApp& app);
  ~LogRequests();
  LogRequests(const LogRequests&) = delete;
  LogRequests& operator=(const LogRequests&) = delete;

  void handle(const std::string& request, std::function<void(std::string)> reply);

  struct Worker;

 private:
  void import(std::string request, std::function<void(std::string)> reply);
  StationApp& app_;
  std::shared_ptr<Worker> worker_;
};

// list, export (a page each) and import on a logbook: what the socket answers and what `trakbox
// log` does itself when no station runs. `now` is the export's CREATED_TIMESTAMP.
nlohmann::json log_list(const logbook::Logbook& b, const nlohmann::json& request);
nlohmann::json log_export(const logbook::Logbook& b, const nlohmann::json& request, std::int64_t now);
nlohmann::json log_import(logbook::Logbook& b, const std::string& adif);

}  // namespace tb::app
