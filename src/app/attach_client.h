// The clients of the running station's socket: `trakbox attach`, `trakbox status`, `trakbox events`
// (attach_server.h; docs/service.md). Each returns the command's exit status.
#pragma once
#include <string>
#include <vector>

namespace tb::app {

int run_attach(const std::vector<std::string>& args);
int run_status(const std::vector<std::string>& args);
int run_events(const std::vector<std::string>& args);
// `trakbox standby on|off`, `trakbox reserve START END [NOTE]` (app/station_command.h).
int run_station_command(const std::string& command, const std::vector<std::string>& args);
// This terminal attached to the station at socket_path (also what a second `trakbox` on a state
// directory in use does); line: plain lines even on a terminal.
int attach_to(const std::string& socket_path, bool line);

}  // namespace tb::app
