#include "app/app.h"

#include <cstdio>
#include <string>
#include <vector>

#include "cli/attach_client.h"
#include "cli/cli_elements.h"
#include "cli/cli_orbit.h"
#include "cli/options.h"
#include "rotator/registry.h"
#include "app/tracker_app.h"
#include "radio/registry.h"
#include "rotator/satrak/client.h"

#include <iostream>

namespace tb::app {
namespace {

std::string usage() {
  return "usage: trakbox [options]              the TrakBox menus on the simulated station\n"
         "       trakbox COMMAND [ARGS...]      a non-interactive command\n"
         "\n"
         "options:\n" +
         describe_options(tracker_option_specs()) +
         "\n"
         "commands:\n" +
         orbit_commands_summary() +
         "  satrak HOST[:PORT] COMMAND...   send Satrak ACU commands (STATUS?, GOTO=,10,20, ...) and print\n"
         "                      the replies\n"
         "  attach [--socket PATH|--state DIR]   the menus of the running station (the service) on this\n"
         "                      terminal; Ctrl-] detaches, Ctrl-T takes the keyboard\n"
         "  status [--json] [--socket PATH|--state DIR]   what the running station does; exit 0 healthy,\n"
         "                      1 running with problems, 3 not running\n"
         "  events [--socket PATH|--state DIR]   the running station's events as JSON lines\n"
         "  log add|list|export|import ...   the logbook: a QSO of the pass tracked, ADIF out and in\n"
         "  calibrate [sun|moon|undo]   the sky calibration: the antenna peaked on the Sun or the Moon\n"
         "                      sets the rotator's offsets (docs/calibration.md)\n"
         "  radio import FILE|diff   modes from SatNOGS, Gpredict .trsp, SatPC32 .SQF or OscarWatch\n"
         "                      merged into the satellites' (yours kept); diff: each value's source\n"
         "  host [options]      host mode (menu 7's commands: AZ EL, MU, MD, FU, FD, S, ?A, ?, Q) on\n"
         "                      stdin/stdout for scripts; takes the options above\n" +
         "\n"
         "`trakbox COMMAND --help` describes a command's arguments. Exit status: 0 done, 1 the command\n"
         "could not finish (e.g. a satellite decayed part-way), 2 bad arguments or unusable input.\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + (argc > 0 ? 1 : 0), argv + argc);
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h" || args[0] == "help")) {
    std::fputs(usage().c_str(), stdout);
    return kExitOk;
  }
  // The device registries: every radio (radio/registry.h) with its spec form and what it can do.
  if (args.size() == 2 && args[0] == "--radio" && args[1] == "list") {
    std::fputs(radio::radio_list_text().c_str(), stdout);
    return kExitOk;
  }
  if (args.size() == 2 && args[0] == "--rotator" && args[1] == "list") {
    std::fputs(rotator::rotator_list_text().c_str(), stdout);
    return kExitOk;
  }
  if (!args.empty() && args[0].rfind('-', 0) != 0) {
    const std::string command = args[0];
    std::vector<std::string> rest(args.begin() + 1, args.end());
    if (command == "propagate") return run_propagate(std::move(rest));
    if (command == "schedule") return run_schedule(std::move(rest));
    if (command == "passes") return run_passes(std::move(rest));
    if (command == "next") return run_next(std::move(rest));
    if (command == "elements") return run_elements(std::move(rest));
    if (command == "host") return run_tracker(rest, FrontEnd::host);
    if (command == "satrak") return satrak::run_cli(rest, std::cout, std::cerr);
    if (command == "attach") return run_attach(rest);
    if (command == "status") return run_status(rest);
    if (command == "events") return run_events(rest);
    if (command == "log") return run_log(rest);
    if (command == "standby" || command == "reserve" || command == "track") return run_station_command(command, rest);
    if (command == "settings") return run_settings(rest);
    if (command == "calibrate") return run_calibrate(rest);
    if (command == "radio") return run_radio(rest);
    std::fprintf(stderr, "trakbox: %s: unknown command; expected propagate, schedule, passes, next, elements, host, satrak, attach, status, events, log, settings, calibrate, radio, standby, reserve or track (see trakbox --help)\n",
                 command.c_str());
    return kExitUsage;
  }
  return run_tracker(args);
}

}  // namespace tb::app
