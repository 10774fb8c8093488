// The non-interactive orbit commands: the same engine the menus use, for scripts and tests.
//
//   trakbox propagate ELEMENTS [--sat NAME|NUMBER] --start MIN --stop MIN --step MIN
//   trakbox schedule  ELEMENTS [--sat NAME|NUMBER] --station LAT,LON,HEIGHT_M --start ISO8601
//                     --step SECONDS --count N [--freq HZ] [--dut1 S] [--csv|--json]
//   trakbox passes    ELEMENTS [--sat NAME|NUMBER]... --station LAT,LON,HEIGHT_M --start ISO8601
//                     --hours H [--min-el DEG] [--dut1 S] [--csv|--json]
//   trakbox next      [SAT...] [--station ...] [--start ...] [--min-el DEG] [--watch]
//
// ELEMENTS, --station, --start and --hours may be left out: the stored database (its tracking
// list without --sat) and station of --state (cli_defaults.h), now, 24 hours.
//
// args are the words after the subcommand's name. Output goes to stdout, warnings and errors to
// stderr. Exit codes: kExitOk; kExitFailure when propagation failed part-way (the output up to the
// failure is complete and the failure is reported); kExitUsage for bad arguments or unusable input.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "orbit/elements.h"

namespace tb::app {

int run_propagate(std::vector<std::string> args);
int run_schedule(std::vector<std::string> args);
int run_passes(std::vector<std::string> args);
// trakbox next [SAT...]: the next pass of each satellite, one line each (cli_next.cpp).
int run_next(std::vector<std::string> args);

// A satellite of `sets` by KEY: the name exactly, then the name ignoring case and surrounding
// blanks, then the catalog number (digits or Alpha-5). Several matching sets of one satellite: the
// newest epoch, with a warning on stderr. Nothing, and `why` (listing the choices), when none does.
std::optional<std::size_t> match_sat(const std::vector<orbit::Elements>& sets, const std::string& key,
                                     std::string& why);

// One-line summaries for `trakbox --help`.
std::string orbit_commands_summary();

}  // namespace tb::app
