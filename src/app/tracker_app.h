// The interactive program: `trakbox [options]` — loads the state, builds the station (simulated
// unless hardware is named), and runs the TrakBox menus on a terminal, a serial line or stdio, or
// standalone tracking, or the unattended service, on one event loop.
#pragma once
#include <string>
#include <vector>

#include "cli/tracker_config.h"

namespace tb::app {

int run_tracker(const std::vector<std::string>& args, FrontEnd front_end = FrontEnd::menus);

}  // namespace tb::app
