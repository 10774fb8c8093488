#pragma once

namespace tb::app {
// The whole program: parses the command line, then runs a subcommand or the tracker.
int main(int argc, char** argv);
}  // namespace tb::app
