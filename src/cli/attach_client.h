// The clients of the running station's socket: `trakbox attach`, `trakbox status`, `trakbox events`
// (attach_server.h; docs/service.md). Each returns the command's exit status.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace tb::app {

int run_attach(const std::vector<std::string>& args);
int run_status(const std::vector<std::string>& args);
int run_events(const std::vector<std::string>& args);
// `trakbox standby on|off`, `trakbox reserve START END [NOTE]` (live/station_command.h).
int run_station_command(const std::string& command, const std::vector<std::string>& args);
// `trakbox settings [set KEY VALUE | reset KEY]` (settings_client.cpp; store/settings.h).
int run_settings(const std::vector<std::string>& args);
// `trakbox radio import FILE | diff` (radio_client.cpp; store/mode_import.h).
int run_radio(const std::vector<std::string>& args);
// `trakbox calibrate [sun|moon|undo]` (calibrate_client.cpp; docs/calibration.md).
int run_calibrate(const std::vector<std::string>& args);
// `trakbox log ...` (log_client.cpp): through the socket, or the state's logbook when nothing runs.
int run_log(const std::vector<std::string>& args);
// This terminal attached to the station at socket_path (also what a second `trakbox` on a state
// directory in use does); line: plain lines even on a terminal.
int attach_to(const std::string& socket_path, bool line);
// One request line to the station's socket and everything it answers; nullopt (said on stderr,
// `not_running` set when nothing runs there) when it cannot be asked.
std::optional<std::string> station_request(const std::string& socket, const std::string& command,
                                           const std::string& line, bool& not_running, bool quiet = false);

}  // namespace tb::app
