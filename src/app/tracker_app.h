// The interactive program: `trakbox [options]` — loads the state, builds the station (simulated
// unless hardware is named), and runs the TrakBox menus on a terminal, a serial line or stdio, or
// standalone tracking, on one event loop.
#pragma once
#include <string>
#include <vector>

#include "app/options.h"

namespace tb::app {

std::vector<OptionSpec> tracker_option_specs();
// How the program talks to its operator.
enum class FrontEnd {
  menus,  // the TrakBox menus (or standalone with --standalone)
  host,   // `trakbox host`: host mode (menu 7's command set) on stdin/stdout, no echo; Q ends
};
int run_tracker(const std::vector<std::string>& args, FrontEnd front_end = FrontEnd::menus);

// Where the shipped data lives: --data, else $TRAKBOX_DATA, else PREFIX/share/trakbox of an installed
// binary, else (a binary in its own build tree) the source tree's data/.
std::string default_data_directory();

}  // namespace tb::app
