#include "app/app.h"

#include <cstdio>
#include <string>
#include <vector>

#include "app/cli_orbit.h"
#include "app/options.h"

namespace tb::app {
namespace {

std::string usage() {
  return "usage: trakbox COMMAND [ARGS...]\n"
         "       trakbox --help\n"
         "\n"
         "commands:\n" +
         orbit_commands_summary() +
         "\n"
         "`trakbox COMMAND --help` describes a command's arguments. Exit status: 0 done, 1 the command\n"
         "could not finish (e.g. a satellite decayed part-way), 2 bad arguments or unusable input.\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + (argc > 0 ? 1 : 0), argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::fputs(usage().c_str(), stdout);
    return kExitOk;
  }
  const std::string command = args[0];
  args.erase(args.begin());
  if (command == "propagate") return run_propagate(std::move(args));
  if (command == "schedule") return run_schedule(std::move(args));
  if (command == "passes") return run_passes(std::move(args));
  std::fprintf(stderr, "trakbox: %s: unknown %s; expected propagate, schedule or passes (see trakbox --help)\n",
               command.c_str(), command.rfind('-', 0) == 0 ? "option" : "command");
  return kExitUsage;
}

}  // namespace tb::app
