// The station's commands that come through its socket (issue 44): `trakbox standby on|off` and
// `trakbox reserve START END [NOTE]`, `trakbox track SAT [--mode NAME]`, one request line each, answered in one line, "ok: NOTE" or
// "refused: WHY", through tracker::StationOps as the operator at the menus; the state is saved
// before the answer.
#pragma once
#include <string>
#include <vector>

namespace tb::app {

class StationApp;

// Whether this request line is one of them ("standby ...", "reserve ...", "track ...").
bool is_station_command(const std::string& line);
// Does it; the answer line without its newline.
std::string run_station_command(StationApp& app, const std::string& line);

}  // namespace tb::app
