// The logbook in the running program (docs/logbook.md): opened at STATE/logbook.sqlite with the
// NORAD to LoTW table of the data directory, handed to the station (tracker::LogOps reaches it);
// the station socket's "log {json}" requests (`trakbox log add|list|export|import`); and the
// `trakbox log` command, which asks the running station, or with none running opens the state
// directory's logbook itself for list, export and import.
#pragma once
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace tb::tracker {
struct Logging;
}

namespace tb::app {

class StationApp;

// Opens the logbook and sets it on the station; a logbook that cannot be opened is logged and
// reported in status, and logging is refused with the reason (the station runs on).
// The logbook is STATE/logbook.sqlite; the LoTW names come from the data directory.
std::unique_ptr<tracker::Logging> open_logging(StationApp& app, const std::filesystem::path& state_dir,
                                               const std::string& data_dir);
// One request of the socket: {"action": "add"|"list"|"export"|"import", ...} -> its JSON reply
// ({"ok": true, ...} or {"error": "..."}). Never throws.
std::string log_socket_request(StationApp& app, const std::string& request);

}  // namespace tb::app
