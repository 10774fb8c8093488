// `trakbox log add|list|export|import`: through the running station's socket ("log {json}"); with
// no station running, list, export and import open the state directory's logbook themselves.
#include <cstdio>
#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/attach_client.h"
#include "live/log_requests.h"
#include "cli/options.h"
#include "live/station_socket.h"
#include "logbook/logbook.h"
#include "store/state_file.h"
#include "tracker/elements_refresh.h"
#include "util/json_limits.h"

namespace tb::app {

using nlohmann::json;

namespace {

std::vector<OptionSpec> log_specs() {
  return {{"help", "", "this list"},
          {"socket", "PATH", "the station's socket (default: that of --state or of the default state directory)"},
          {"state", "DIR", "the state directory (its socket, or its logbook.sqlite when no station runs)"},
          {"since", "DATE", "list/export: the QSOs from this UTC date or time on (2026-12-01, 2026-12-01T21:00Z)"},
          {"adif", "FILE", "export: write the ADIF to FILE (default: standard output)"},
          {"rst-rcvd", "RST", "add: the report received"},
          {"note", "TEXT", "add: a note (the ADIF COMMENT)"},
          {"sat", "NAME", "add: the satellite (default: the one tracked)"},
          {"mode", "MODE", "add: the emission FM, SSB, CW (default: the tracked radio's)"},
          {"time", "UTC", "add: the time on (default: now)"},
          {"power", "W", "add: the transmitter power"}};
}

std::string log_usage() {
  return "usage: trakbox log add CALL [GRID] [RST] [--rst-rcvd RST] [--note TEXT] [--sat NAME] [--mode MODE]\n"
         "                      [--time UTC] [--power W]\n"
         "       trakbox log list [--since DATE]\n"
         "       trakbox log export [--since DATE] [--adif FILE]\n"
         "       trakbox log import FILE\n"
         "each with [--socket PATH | --state DIR]\n\n"
         "The operator's logbook (docs/logbook.md). add logs a QSO with the pass the running station tracks\n"
         "(satellite, mode, both frequencies, time, your grid); it is acknowledged once on disk. export writes\n"
         "ADIF 3.1.4 for LoTW and loggers; import reads an ADIF file whole or not at all.\n\noptions:\n" +
         describe_options(log_specs());
}

int log_fail(const std::string& why) {
  std::fprintf(stderr, "trakbox log: %s\n", why.c_str());
  return kExitFailure;
}

// A request's reply: from the running station, or from the logbook itself; nullopt when the
// station stopped answering (said on standard error).
using Ask = std::function<std::optional<json>(const json&)>;

// The reply's effect on the terminal; the exit status. list and export come a page at a time
// (live/log_requests.h): each page is printed or written as it comes and the next asked with its
// "next" cursor, so neither the station nor this command holds the whole log.
int show(const std::string& action, json r, const ParsedOptions& o, const Ask& ask, json request) {
  std::ofstream file;
  const auto path = o.value("adif");
  if (action == "export" && path) {
    file.open(*path, std::ios::binary | std::ios::trunc);
    if (!file) return log_fail(*path + ": cannot be written");
  }
  for (;;) {
    if (!r.is_object()) return log_fail("no answer from the station");
    if (r.contains("error")) return log_fail(r["error"].get<std::string>());
    if (action == "add") {
      const json& q = r["qso"];
      std::printf("logged %lld %s %s %s %s\n", static_cast<long long>(q.value("id", 0LL)), q.value("call", "").c_str(),
                  q.value("sat_name", "").c_str(), q.value("mode", "").c_str(), q.value("time_on", "").c_str());
      if (r.contains("warning") && r["warning"].is_string())
        std::fprintf(stderr, "trakbox log add: note: %s\n", r["warning"].get<std::string>().c_str());
    } else if (action == "list") {
      for (const auto& q : r["qsos"])
        std::printf("%4lld  %s  %-10s %-8s %-6s %-4s %s\n", static_cast<long long>(q.value("id", 0LL)),
                    q.value("time_on", "").c_str(), q.value("call", "").c_str(), q.value("sat_name", "").c_str(),
                    q.value("grid", "").c_str(), q.value("mode", "").c_str(), q.value("source", "").c_str());
    } else if (action == "export") {
      for (const auto& w : r["warnings"]) std::fprintf(stderr, "trakbox log export: WARNING: %s\n", w.get<std::string>().c_str());
      const std::string& adif = r["adif"].get_ref<const std::string&>();
      if (path) {
        if (!(file << adif)) return log_fail(*path + ": cannot be written");
      } else {
        std::fputs(adif.c_str(), stdout);
      }
    } else if (action == "import") {
      std::printf("imported %lld QSOs, %lld already in the log", static_cast<long long>(r.value("added", 0LL)),
                  static_cast<long long>(r.value("duplicates", 0LL)));
      const long long skipped = r.value("skipped", 0LL);
      if (skipped > 0) std::printf(", %lld records skipped (not satellite QSOs)", skipped);
      std::printf("\n");
      if (r.contains("skipped_records") && r["skipped_records"].is_array())
        for (const auto& k : r["skipped_records"])
          std::printf("  skipped record %lld %s: %s\n", static_cast<long long>(k.value("record", 0LL)),
                      k.value("call", "").c_str(), k.value("why", "").c_str());
      if (skipped > static_cast<long long>(r.value("skipped_records", json::array()).size()))
        std::printf("  (and %lld more)\n", skipped - static_cast<long long>(r["skipped_records"].size()));
    }
    if ((action != "list" && action != "export") || !r.contains("next") || !r["next"].is_string()) break;
    request["after"] = r["next"];
    auto more = ask(request);
    if (!more) return kExitFailure;
    r = std::move(*more);
  }
  if (path && action == "export" && !file.flush()) return log_fail(*path + ": cannot be written");
  return kExitOk;
}

// The request of the command line; an error names the argument.
std::optional<json> build_request(const std::string& action, const ParsedOptions& o, std::string& error) {
  const auto& pos = o.positional();
  json j{{"action", action}};
  if (const auto s = o.value("since")) j["since"] = *s;
  if (action == "add") {
    if (pos.size() < 2 || pos.size() > 4) return error = "add: expected CALL [GRID] [RST]", std::nullopt;
    j["call"] = pos[1];
    for (std::size_t i = 2; i < pos.size(); ++i)
      j[!pos[i].empty() && pos[i][0] >= '0' && pos[i][0] <= '9' ? "rst_sent" : "grid"] = pos[i];
    for (const auto& [opt, key] : {std::pair<const char*, const char*>{"rst-rcvd", "rst_rcvd"}, {"note", "note"},
                                   {"sat", "sat"}, {"mode", "mode"}, {"time", "time_on"}})
      if (const auto v = o.value(opt)) j[key] = *v;
    if (const auto p = o.value("power")) {
      const auto w = to_double(*p);
      if (!w) return error = "--power: expected watts, found '" + *p + "'", std::nullopt;
      j["power_w"] = *w;
    }
  } else if (action == "import") {
    if (pos.size() != 2) return error = "import: expected FILE", std::nullopt;
    std::ifstream in(pos[1], std::ios::binary);
    if (!in) return error = pos[1] + ": cannot be read", std::nullopt;
    std::ostringstream s;
    s << in.rdbuf();
    j["adif"] = s.str();
  } else if (pos.size() != 1) {
    return error = action + ": unexpected argument '" + pos[1] + "'", std::nullopt;
  }
  return j;
}

// No station runs: list, export and import on the state directory's logbook itself.
json direct(logbook::Logbook& book, const json& j) {
  const std::string action = j["action"];
  if (action == "list") return log_list(book, j);
  if (action == "export") return log_export(book, j, tracker::ElementsRefresh::wall_now());
  return log_import(book, j["adif"].get<std::string>());
}

}  // namespace

int run_log(const std::vector<std::string>& args) {
  ParseOutcome parsed = parse_options(args, log_specs());
  if (parsed.error) return std::fprintf(stderr, "trakbox log: %s\n%s", parsed.error->text().c_str(), log_usage().c_str()), kExitUsage;
  const ParsedOptions& o = parsed.options;
  if (o.has("help")) return std::fputs(log_usage().c_str(), stdout), kExitOk;
  const auto& pos = o.positional();
  const std::string action = pos.empty() ? "" : pos[0];
  if (action != "add" && action != "list" && action != "export" && action != "import")
    return std::fprintf(stderr, "trakbox log: expected add, list, export or import\n%s", log_usage().c_str()), kExitUsage;
  if (o.has("socket") && o.has("state")) return log_fail("--socket: not with --state");
  if (const auto s = o.value("since"); s && !logbook::parse_utc(*s))
    return std::fprintf(stderr, "trakbox log: --since: expected a UTC date like 2026-12-01, found '%s'\n", s->c_str()), kExitUsage;
  std::string error;
  const auto request = build_request(action, o, error);
  if (!request) return std::fprintf(stderr, "trakbox log: %s\n", error.c_str()), kExitUsage;
  const std::string state_dir = o.value("state").value_or(store::default_state_directory().string());
  const std::string socket = o.value("socket").value_or(o.has("state") ? socket_for_state(state_dir) : default_client_socket());
  bool not_running = false;
  const std::string line = "log " + request->dump(-1, ' ', false, json::error_handler_t::replace);
  if (line.size() + 1 > kMaxRequestBytes)
    return log_fail(pos[0] + ": " + (pos.size() > 1 ? pos[1] : std::string("the request")) + " makes a request of " +
                std::to_string(line.size() + 1) + " bytes, more than the " + std::to_string(kMaxRequestBytes) +
                " (" + std::to_string(kMaxRequestBytes >> 20) + " MiB) the station's socket takes: split the file");
  const auto text = station_request(socket, "log", line, not_running);
  if (text) {
    const Ask ask = [&socket](const json& j) -> std::optional<json> {
      bool gone = false;
      const auto t = station_request(socket, "log", "log " + j.dump(-1, ' ', false, json::error_handler_t::replace), gone);
      if (!t) return std::nullopt;
      std::string why;
      return json_limits::parse_bounded<json>(*t, why);
    };
    std::string why;
    return show(action, json_limits::parse_bounded<json>(*text, why), o, ask, *request);
  }
  if (!not_running) return kExitFailure;
  if (action == "add") return log_fail("add: no station is running to take the pass from (start trakbox first)");
  if (!std::filesystem::exists(state_dir + "/logbook.sqlite")) return log_fail(state_dir + ": no logbook.sqlite there");
  std::fprintf(stderr, "trakbox log: no station runs; using %s/logbook.sqlite\n", state_dir.c_str());
  std::string err;
  auto book = logbook::Logbook::open(state_dir + "/logbook.sqlite", err);
  if (!book) return log_fail(err);
  const Ask ask = [&book](const json& j) -> std::optional<json> { return direct(*book, j); };
  return show(action, direct(*book, *request), o, ask, *request);
}

}  // namespace tb::app
