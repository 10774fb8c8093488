// The non-interactive orbit commands: the same engine the menus use, for scripts and tests.
//
//   trakbox propagate ELEMENTS [--sat NAME|NUMBER] --start MIN --stop MIN --step MIN
//   trakbox schedule  ELEMENTS [--sat NAME|NUMBER] --station LAT,LON,HEIGHT_M --start ISO8601
//                     --step SECONDS --count N [--freq HZ] [--dut1 S] [--csv|--json]
//   trakbox passes    ELEMENTS [--sat NAME|NUMBER]... --station LAT,LON,HEIGHT_M --start ISO8601
//                     --hours H [--min-el DEG] [--dut1 S] [--csv|--json]
//
// args are the words after the subcommand's name. Output goes to stdout, warnings and errors to
// stderr. Exit codes: kExitOk; kExitFailure when propagation failed part-way (the output up to the
// failure is complete and the failure is reported); kExitUsage for bad arguments or unusable input.
#pragma once
#include <string>
#include <vector>

namespace tb::app {

int run_propagate(std::vector<std::string> args);
int run_schedule(std::vector<std::string> args);
int run_passes(std::vector<std::string> args);

// One-line summaries for `trakbox --help`.
std::string orbit_commands_summary();

}  // namespace tb::app
