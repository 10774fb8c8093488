// `trakbox settings [--json]`, `trakbox settings set KEY VALUE`, `trakbox settings reset KEY`
// (issue 55): every stored setting with its value, range and where it came from. Through the running
// station's socket when one runs on the state (its model's owner checks, stores, reconfigures and
// saves), else on the state file itself, through the same door (store/owner.h), holding the state's
// lock so that no station starts meanwhile. A damaged state file is never written over.
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
#include "store/owner.h"
#include "store/settings.h"
#include "store/state_file.h"
#include "util/json_limits.h"

namespace tb::app {
namespace {

const char* kUsage =
    "usage: trakbox settings [--json] [--state DIR | --socket PATH]\n"
    "       trakbox settings set KEY VALUE [--state DIR | --socket PATH]\n"
    "       trakbox settings reset KEY [--state DIR | --socket PATH]\n\n"
    "Every stored setting: its value, where it came from (default, state, command line, menus, ...),\n"
    "its range or choices, and the option or menu that sets it. set and reset change one, checked as\n"
    "the next start will check it: through the running station when one runs on the state directory\n"
    "(it takes effect at once and is saved), else in the state file.\n\n"
    "examples:\n"
    "  trakbox settings\n"
    "  trakbox settings set station.height_m 120\n"
    "  trakbox settings set sharing.exclusive rotctld\n"
    "  trakbox settings reset rotator.az_skew\n\n"
    "options:\n";

std::vector<OptionSpec> specs() {
  return {{"help", "", "this text"},
          {"json", "", "the list as JSON"},
          {"state", "DIR", "the state directory (default: the user's, as trakbox's)"},
          {"socket", "PATH", "the running station's socket (the system service's: " + std::string(kServiceSocket) + ")"},
          {"data", "DIR", "the shipped data a fresh state starts from (default: as trakbox's)"}};
}

int print_list(const nlohmann::json& doc, bool as_json) {
  if (as_json) std::fputs((doc.dump(2) + "\n").c_str(), stdout);
  else std::fputs(store::settings_text(doc).c_str(), stdout);
  return kExitOk;
}

// The words after `settings` as one request line for the station.
std::string request_line(const std::vector<std::string>& words) {
  std::string line = "settings";
  for (const std::string& w : words) line += " " + w;
  return line;
}

int through_socket(const std::string& socket, const std::vector<std::string>& words, bool as_json) {
  bool not_running = false;
  const auto answer = station_request(socket, "settings", request_line(words), not_running);
  if (!answer) return not_running ? kStatusNotRunning : kExitFailure;
  if (words.empty()) {
    std::string why;
    const nlohmann::json doc = json_limits::parse_bounded<nlohmann::json>(*answer, why);
    if (!doc.is_object() || !doc.contains("settings")) {
      std::fprintf(stderr, "trakbox settings: %s: %s\n", socket.c_str(), answer->substr(0, 200).c_str());
      return kExitFailure;
    }
    return print_list(doc, as_json);
  }
  std::fputs((*answer + "\n").c_str(), answer->rfind("ok:", 0) == 0 ? stdout : stderr);
  return answer->rfind("ok:", 0) == 0 ? kExitOk : kExitFailure;
}

// Nothing runs on the state: its file, read and written through the model's owner.
int on_state_file(const std::filesystem::path& dir, const std::string& data_dir, const std::vector<std::string>& words,
                  bool as_json) {
  store::StateFile file(dir);
  const store::LoadOutcome loaded = file.load(true);
  if (loaded.kind == store::LoadOutcome::Kind::corrupt) {
    std::fprintf(stderr, "trakbox settings: %s: %s; nothing read or changed (trakbox's next start keeps it aside)\n",
                 file.path().c_str(), loaded.reason.c_str());
    return kExitFailure;
  }
  store::Model model;
  nlohmann::json satrak;
  if (loaded.kind == store::LoadOutcome::Kind::loaded) {
    try {
      model = store::model_from_json(loaded.data);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "trakbox settings: %s: %s; nothing read or changed\n", file.path().c_str(), e.what());
      return kExitFailure;
    }
    if (loaded.data.contains("satrak")) satrak = loaded.data["satrak"];
  } else {
    std::vector<std::string> notes;
    model = defaults_with_data(data_dir, notes);  // what a first start would load
  }
  const bool fresh = loaded.kind != store::LoadOutcome::Kind::loaded;
  store::ModelOwner owner(std::move(model), fresh ? store::Origin::defaults : store::Origin::state);
  if (words.empty())
    return print_list(store::settings_document(owner.model(), [&owner](std::string_view key) {
                        return std::string(store::to_string(owner.origin_of(key)));
                      }),
                      as_json);
  store::EditResult r;
  if (words[0] == "set" && words.size() >= 3) {
    std::string value;
    for (std::size_t i = 2; i < words.size(); ++i) value += (i > 2 ? " " : "") + words[i];
    r = owner.set_typed(words[1], value, store::Origin::socket);
  } else if (words[0] == "reset" && words.size() == 2) {
    r = owner.reset(words[1], store::Origin::socket);
  } else {
    std::fprintf(stderr, "trakbox settings: expected set KEY VALUE or reset KEY (see trakbox settings --help)\n");
    return kExitUsage;
  }
  if (!r.ok()) {
    std::fprintf(stderr, "refused: %s\n", r.refusal->c_str());
    return kExitFailure;
  }
  const store::Setting* s = store::find_setting(words[1]);
  std::string now = words[1] + " = " + store::shown(*s, s->get(owner.model()));
  if (const auto warn = store::setting_warning(words[1], owner.model())) now += "; WARNING: " + *warn;
  if (r.changed) {
    nlohmann::json doc = store::to_json(owner.model());
    if (!satrak.is_null()) doc["satrak"] = satrak;
    std::string error;
    if (!file.save(doc, error)) {
      std::fprintf(stderr, "trakbox settings: %s: not saved: %s\n", file.path().c_str(), error.c_str());
      return kExitFailure;
    }
  }
  std::printf("ok: %s%s (%s)\n", now.c_str(), r.changed ? "" : " (unchanged)", file.path().c_str());
  return kExitOk;
}

}  // namespace

int run_settings(const std::vector<std::string>& args) {
  Subcommand sub;
  if (const auto done = read_subcommand(args, specs(), "settings", kUsage, sub)) return *done;
  const std::vector<std::string>& words = sub.words;
  const ParsedOptions& o = sub.options;
  if (!words.empty() && words[0] != "set" && words[0] != "reset") {
    std::fprintf(stderr, "trakbox settings: '%s': expected set or reset (see trakbox settings --help)\n",
                 words[0].c_str());
    return kExitUsage;
  }
  if ((words.size() == 1) || (words.size() >= 1 && words[0] == "set" && words.size() < 3) ||
      (words.size() >= 1 && words[0] == "reset" && words.size() != 2)) {
    std::fprintf(stderr, "trakbox settings: expected set KEY VALUE or reset KEY (see trakbox settings --help)\n");
    return kExitUsage;
  }
  if (words.size() >= 2 && !store::find_setting(words[1])) {
    std::fprintf(stderr, "refused: %s: no such setting (trakbox settings lists them)\n", words[1].c_str());
    return kExitFailure;
  }
  const bool as_json = o.has("json");
  if (const auto socket = o.value("socket")) return through_socket(*socket, words, as_json);
  const std::filesystem::path dir = o.value("state") ? std::filesystem::path(*o.value("state"))
                                                     : store::default_state_directory();
  LockHolder holder;
  std::string lock_error;
  std::optional<StateLock> lock = StateLock::take(dir, holder, lock_error);
  if (!lock && !lock_error.empty()) {
    std::error_code ec;
    if (!std::filesystem::exists(dir, ec)) {
      // No state yet: the list is what a first start would have; a set makes the directory, as
      // trakbox's first start does (for the user alone).
      if (words.empty()) return on_state_file(dir, o.value("data").value_or(default_data_directory()), words, as_json);
      std::filesystem::create_directories(dir, ec);
      std::filesystem::permissions(dir, std::filesystem::perms::owner_all, ec);
      lock_error.clear();
      if (auto again = StateLock::take(dir, holder, lock_error)) lock.emplace(std::move(*again));
    }
    if (!lock && !lock_error.empty()) {
      std::fprintf(stderr, "trakbox settings: %s\n", lock_error.c_str());
      return kExitFailure;
    }
  }
  if (!lock) {
    // A station runs on this state: it is asked (its socket, as its lock file names it).
    const std::string socket = !holder.socket.empty() ? holder.socket : socket_for_state(dir.string());
    return through_socket(socket, words, as_json);
  }
  return on_state_file(dir, o.value("data").value_or(default_data_directory()), words, as_json);
}

}  // namespace tb::app
