// Unit tests that need an outside program (socat, rigctld, rotctld): such a test is registered
// with `* doctest::skip(skip_without({...}))` and starts with `require_tools({...})`.
//  * Tool present: the test runs.
//  * Tool missing here: doctest skips it, counted as skipped in its summary, and the reason is
//    printed ("SKIPPED: ... socat is not installed") — never a green test that asserted nothing.
//  * Tool missing in CI (environment variable CI set, not "false"/"0"): the test runs and
//    require_tools() fails it, naming the tool: CI installs every tool (scripts/install-deps.sh).
// The integration tests do the same through _tbharness.skip() (exit 77, or 1 in CI).
#pragma once
#include <doctest/doctest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace tb::testing {

// The program's path on PATH (/usr/bin:/bin when PATH is unset), if it is there.
inline std::optional<std::string> find_tool(std::string_view name) {
  const char* env = std::getenv("PATH");
  const std::string path = env ? env : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= path.size()) {
    std::size_t end = path.find(':', start);
    if (end == std::string::npos) end = path.size();
    if (end > start) {
      std::string candidate = path.substr(start, end - start) + "/" + std::string(name);
      if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    start = end + 1;
  }
  return std::nullopt;
}

// Running in CI: CI set to anything but "", "0" or "false".
inline bool in_ci() {
  const char* ci = std::getenv("CI");
  if (!ci) return false;
  const std::string v = ci;
  return !(v.empty() || v == "0" || v == "false");
}

// The first of the tools that is missing, if any.
inline std::optional<std::string> missing_tool(std::initializer_list<std::string_view> tools) {
  for (std::string_view t : tools)
    if (!find_tool(t)) return std::string(t);
  return std::nullopt;
}

// For doctest::skip(): whether to skip a test needing these tools (missing, and not in CI). Says
// why on standard error, once per test registered.
inline bool skip_without(std::initializer_list<std::string_view> tools) {
  const auto missing = missing_tool(tools);
  if (!missing || in_ci()) return false;
  std::fprintf(stderr, "SKIPPED: a test needs %s, which is not installed (scripts/install-deps.sh)\n",
               missing->c_str());
  return true;
}

// At the start of a test registered with skip_without(): every tool there, or the test fails
// (only reached without them in CI).
inline void require_tools(std::initializer_list<std::string_view> tools) {
  const auto missing = missing_tool(tools);
  const char* ci = std::getenv("CI");
  REQUIRE_MESSAGE(!missing, (missing ? *missing : std::string()) << " is not installed (CI=" << std::string(ci ? ci : "unset")
                                                                  << ": in CI every tool must be)");
}

}  // namespace tb::testing
