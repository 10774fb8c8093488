// `trakbox radio import FILE [--format F] [--replace]` and `trakbox radio diff` (issue 59): modes
// from the public lists merged into the satellites' modes, and where each value came from
// (store/mode_import.h). Through the running station's socket when one runs on the state (its
// model's owner checks, stores, re-tunes and saves), else on the state file itself through the same
// door, holding the state's lock so that no station starts meanwhile (as `trakbox settings`).
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/attach_client.h"
#include "cli/options.h"
#include "cli/tracker_config.h"
#include "live/state_lock.h"
#include "live/station_app.h"
#include "live/station_socket.h"
#include "live/status.h"
#include "store/mode_import.h"
#include "store/owner.h"
#include "store/state_file.h"
#include "util/files.h"
#include "util/json_limits.h"

namespace tb::app {
namespace {

using json = nlohmann::json;

const char* kRadioUsage =
    "usage: trakbox radio import FILE [--format satnogs|trsp|sqf|subtone|oscarwatch] [--replace]\n"
    "       trakbox radio diff [SAT] [--conflicts]\n"
    "each with [--state DIR | --socket PATH]\n\n"
    "import merges the modes of a public list into the satellites' modes: the SatNOGS DB transmitter\n"
    "list (JSON), a Gpredict NNNNN.trsp, SatPC32's Doppler.SQF or SubTone.SQF, OscarWatch's\n"
    "satellite_database.json (the format is guessed from the name and content unless given). Values you\n"
    "entered, and those of the freq/mode file, are kept and a different one in the list is reported;\n"
    "--replace takes the list's. diff lists every mode's values (SAT's alone when named) with where each\n"
    "came from and what a list said otherwise (--conflicts: only those). Through the running station\n"
    "when one runs on the state directory, else in the state file.\n\n"
    "examples:\n"
    "  trakbox radio import 44909.trsp\n"
    "  trakbox radio import Doppler.SQF\n"
    "  trakbox radio diff RS-44 --conflicts\n\n"
    "options:\n";

std::vector<OptionSpec> radio_specs() {
  return {{"help", "", "this text"},
          {"format", "NAME", "the list's format: satnogs, trsp, sqf, subtone or oscarwatch (default: guessed)"},
          {"replace", "", "take the list's values over yours and the freq/mode file's"},
          {"conflicts", "", "diff: only the values a list said otherwise"},
          {"state", "DIR", "the state directory (default: the user's, as trakbox's)"},
          {"socket", "PATH", "the running station's socket (the system service's: " + std::string(kServiceSocket) + ")"},
          {"data", "DIR", "the shipped data a fresh state starts from (default: as trakbox's)"}};
}

int print_answer(const json& answer, const std::string& where) {
  if (!answer.is_object() || (!answer.contains("lines") && !answer.contains("error"))) {
    std::fprintf(stderr, "trakbox radio: %s: no answer it understands\n", where.c_str());
    return kExitFailure;
  }
  if (answer.contains("error")) {
    std::fprintf(stderr, "refused: %s\n", answer["error"].get<std::string>().c_str());
    return kExitFailure;
  }
  for (const json& line : answer["lines"]) std::printf("%s\n", line.get<std::string>().c_str());
  return kExitOk;
}

int through_socket(const std::string& socket, const json& request) {
  bool not_running = false;
  const std::string line = "radio " + request.dump(-1, ' ', false, json::error_handler_t::replace);
  if (line.size() + 1 > kMaxRequestBytes) {
    std::fprintf(stderr, "trakbox radio: the file makes a request of %zu bytes, more than the %zu the station's socket takes\n",
                 line.size() + 1, kMaxRequestBytes);
    return kExitFailure;
  }
  const auto answer = station_request(socket, "radio", line, not_running);
  if (!answer) return not_running ? kStatusNotRunning : kExitFailure;
  std::string why;
  return print_answer(json_limits::parse_bounded<json>(*answer, why), socket);
}

// Nothing runs on the state: its file, read and written through the model's owner.
int on_state_file(const std::filesystem::path& dir, const std::string& data_dir, const json& request) {
  store::StateFile file(dir);
  const store::LoadOutcome loaded = file.load(true);
  if (loaded.kind == store::LoadOutcome::Kind::corrupt) {
    std::fprintf(stderr, "trakbox radio: %s: %s; nothing read or changed (trakbox's next start keeps it aside)\n",
                 file.path().c_str(), loaded.reason.c_str());
    return kExitFailure;
  }
  store::Model model;
  json satrak;
  if (loaded.kind == store::LoadOutcome::Kind::loaded) {
    try {
      model = store::model_from_json(loaded.data);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "trakbox radio: %s: %s; nothing read or changed\n", file.path().c_str(), e.what());
      return kExitFailure;
    }
    if (loaded.data.contains("satrak")) satrak = loaded.data["satrak"];
  } else {
    std::vector<std::string> notes;
    model = defaults_with_data(data_dir, notes);  // what a first start would load
  }
  store::ModelOwner owner(std::move(model), store::Origin::state);
  json answer = store::radio_request(owner, request, store::Origin::command_line);
  if (answer.value("changed", false)) {
    json doc = store::to_json(owner.model());
    if (!satrak.is_null()) doc["satrak"] = satrak;
    std::string error;
    if (!file.save(doc, error)) {
      std::fprintf(stderr, "trakbox radio: %s: not saved: %s\n", file.path().c_str(), error.c_str());
      return kExitFailure;
    }
  }
  return print_answer(answer, file.path().string());
}

// The request the words make; nullopt (said) when they make none.
std::optional<json> build_request(const std::vector<std::string>& words, const ParsedOptions& o, int& code) {
  code = kExitUsage;
  if (!words.empty() && words[0] == "diff" && words.size() <= 2) {
    json r = {{"action", "diff"}, {"conflicts", o.has("conflicts")}};
    if (words.size() == 2) r["satellite"] = words[1];
    return r;
  }
  if (words.size() != 2 || words[0] != "import") {
    std::fprintf(stderr, "trakbox radio: expected import FILE or diff [SAT] (see trakbox radio --help)\n");
    return std::nullopt;
  }
  const auto content = files::read_whole_file(words[1]);
  if (!content) {
    std::fprintf(stderr, "trakbox radio: %s: cannot be read\n", words[1].c_str());
    code = kExitFailure;
    return std::nullopt;
  }
  const std::string name = std::filesystem::path(words[1]).filename().string();
  json r = {{"action", "import"}, {"file", name}, {"text", *content}, {"replace", o.has("replace")}};
  if (const auto f = o.value("format")) r["format"] = *f;
  return r;
}

}  // namespace

int run_radio(const std::vector<std::string>& args) {
  Subcommand sub;
  if (const auto done = read_subcommand(args, radio_specs(), "radio", kRadioUsage, sub)) return *done;
  const ParsedOptions& o = sub.options;
  int code = kExitOk;
  const auto request = build_request(sub.words, o, code);
  if (!request) return code;
  if (const auto socket = o.value("socket")) return through_socket(*socket, *request);
  const std::filesystem::path dir = o.value("state") ? std::filesystem::path(*o.value("state"))
                                                     : store::default_state_directory();
  const std::string data = o.value("data").value_or(default_data_directory());
  LockHolder holder;
  std::string lock_error;
  std::optional<StateLock> lock = StateLock::take(dir, holder, lock_error);
  if (!lock && !lock_error.empty()) {
    std::error_code ec;
    if (!std::filesystem::exists(dir, ec)) {
      // No state yet: an import makes the directory, as trakbox's first start does (for the user alone).
      std::filesystem::create_directories(dir, ec);
      std::filesystem::permissions(dir, std::filesystem::perms::owner_all, ec);
      lock_error.clear();
      if (auto again = StateLock::take(dir, holder, lock_error)) lock.emplace(std::move(*again));
    }
    if (!lock && !lock_error.empty()) {
      std::fprintf(stderr, "trakbox radio: %s\n", lock_error.c_str());
      return kExitFailure;
    }
  }
  if (!lock) {
    // A station runs on this state: it is asked (its socket, as its lock file names it).
    return through_socket(!holder.socket.empty() ? holder.socket : socket_for_state(dir.string()), *request);
  }
  return on_state_file(dir, data, *request);
}

}  // namespace tb::app
