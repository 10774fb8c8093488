// `trakbox calibrate [sun|moon|undo]` (issue 58, docs/calibration.md): "this is the Sun" / "this is
// the Moon" and its undo. Through the running station's socket when one runs on the state (its
// rotator's reading, its clock; the owner stores the offsets, the controller takes them at once,
// the state is saved), else on the state file with the reading the operator gives (--reading), as
// `trakbox settings` does (settings_client.cpp).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/attach_client.h"
#include "cli/calibrate_scan.h"
#include "cli/options.h"
#include "cli/tracker_config.h"
#include "live/state_lock.h"
#include "live/station_app.h"
#include "live/station_socket.h"
#include "live/status.h"
#include "orbit/sky.h"
#include "station/clock.h"
#include "store/owner.h"
#include "store/state_file.h"
#include "tracker/operations.h"
#include "util/text.h"

namespace tb::app {
namespace {

const char* kUsage =
    "usage: trakbox calibrate [--state DIR | --socket PATH]\n"
    "       trakbox calibrate sun|moon [--reading AZ,EL [--at TIME]] [--state DIR | --socket PATH]\n"
    "       trakbox calibrate undo [--state DIR | --socket PATH]\n"
    "       trakbox calibrate sun --scan --beam DEG [--shape cross|grid] [--readings N] [--settle S]\n"
    "                 [--receiver gqrx:HOST:PORT | rigctld:HOST:PORT] [--store] [--state DIR | --socket PATH]\n\n"
    "The sky calibration: peak the antenna by hand on the Sun (its noise) or the Moon (its echo), then\n"
    "say which: trakbox sets the azimuth and elevation offsets so that the rotator's reading equals the\n"
    "body's computed position, and stores them with the time (rotator.az_offset_deg, el_offset_deg).\n"
    "undo puts back the offsets before the last calibration; without a word, the stored ones are shown.\n"
    "With a station running on the state directory its rotator is read and its clock used; else give\n"
    "the reading (--reading, as the controller shows it) and, if it was not now, when (--at).\n\n"
    "examples:\n"
    "  trakbox calibrate sun\n"
    "  trakbox calibrate moon --reading 117.5,31.4 --at 2026-03-20T09:00:00Z\n"
    "  trakbox calibrate undo\n"
    "  trakbox calibrate sun --scan --beam 8 --receiver gqrx:127.0.0.1:7356 --store\n\n"
    "options:\n";

std::vector<OptionSpec> specs() {
  return {{"help", "", "this text"},
          {"reading", "AZ,EL", "the rotator's reading when no station runs (degrees, as it displays them)"},
          {"at", "TIME", "when that reading was taken (ISO 8601 UTC; default now, with menu 5's offset)"},
          {"scan", "", "sun only: a sun-noise scan finds the peak itself (the running station, a receiver)"},
          {"beam", "DEG", "--scan: the antenna's -3 dB beamwidth (the scan spans 2 beams in steps of a quarter)"},
          {"shape", "cross|grid", "--scan: a cross (4 span/step + 1 points, the default) or a grid"},
          {"readings", "N", "--scan: levels averaged at each point (default 5)"},
          {"settle", "SECONDS", "--scan: wait after the rotator arrives (default 1)"},
          {"receiver", "KIND:HOST:PORT", "--scan: gqrx:HOST:PORT (default gqrx:127.0.0.1:7356) or rigctld:HOST:PORT (coarse)"},
          {"store", "", "--scan: store the offsets found"},
          {"state", "DIR", "the state directory (default: the user's, as trakbox's)"},
          {"socket", "PATH", "the running station's socket (the system service's: " + std::string(kServiceSocket) + ")"},
          {"data", "DIR", "the shipped data a fresh state starts from (default: as trakbox's)"}};
}

std::optional<rotator::AzEl> parse_reading(std::string_view s) {
  const auto f = text::split(s, ',');
  if (f.size() != 2) return std::nullopt;
  const auto az = text::parse_double(text::trim(f[0], text::kWhitespace));
  const auto el = text::parse_double(text::trim(f[1], text::kWhitespace));
  if (!az || !el || *az < 0.0 || *az > 360.0 || *el < -90.0 || *el > 180.0) return std::nullopt;
  return rotator::AzEl{*az, *el};
}

int answer(const tracker::OpResult& r, const std::string& where) {
  if (!r.ok()) {
    std::fprintf(stderr, "refused: %s\n", r.refusal->c_str());
    return kExitFailure;
  }
  std::printf("ok: %s (%s)\n", r.note.c_str(), where.c_str());
  return kExitOk;
}

int through_socket(const std::string& socket, const std::string& word, const ParsedOptions& o) {
  if (o.has("reading") || o.has("at")) {
    std::fprintf(stderr, "trakbox calibrate: a station runs on this state: its rotator is read now "
                         "(--reading and --at are for a state no station runs on)\n");
    return kExitUsage;
  }
  bool not_running = false;
  const auto got = station_request(socket, "calibrate", word.empty() ? "calibrate" : "calibrate " + word, not_running);
  if (!got) return not_running ? kStatusNotRunning : kExitFailure;
  const bool ok = got->rfind("ok:", 0) == 0;
  std::fputs((*got + "\n").c_str(), ok ? stdout : stderr);
  return ok ? kExitOk : kExitFailure;
}

// Nothing runs on the state: its file, through the model's owner.
int on_state_file(const std::filesystem::path& dir, const std::string& data_dir, const std::string& word,
                  const ParsedOptions& o) {
  store::StateFile file(dir);
  const store::LoadOutcome loaded = file.load(true);
  if (loaded.kind == store::LoadOutcome::Kind::corrupt) {
    std::fprintf(stderr, "trakbox calibrate: %s: %s; nothing read or changed\n", file.path().c_str(),
                 loaded.reason.c_str());
    return kExitFailure;
  }
  store::Model model;
  nlohmann::json satrak;
  try {
    if (loaded.kind == store::LoadOutcome::Kind::loaded) {
      model = store::model_from_json(loaded.data);
      if (loaded.data.contains("satrak")) satrak = loaded.data["satrak"];
    } else {
      std::vector<std::string> notes;
      model = defaults_with_data(data_dir, notes);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "trakbox calibrate: %s: %s; nothing read or changed\n", file.path().c_str(), e.what());
    return kExitFailure;
  }
  store::ModelOwner owner(std::move(model), store::Origin::state);
  if (word.empty()) {
    std::printf("%s\n", tracker::calibration_text(owner.model().rotator).c_str());
    return kExitOk;
  }
  tracker::OpResult r;
  if (word == "undo") {
    r = tracker::undo_calibration(owner, store::Origin::socket);
  } else {
    const auto reading = o.value("reading") ? parse_reading(*o.value("reading")) : std::nullopt;
    if (!reading) {
      std::fprintf(stderr, o.value("reading") ? "trakbox calibrate: --reading '%s': expected AZ,EL in degrees, e.g. 138.6,31.9\n"
                                              : "trakbox calibrate: no station runs on %s: give the rotator's reading "
                                                "with --reading AZ,EL (or calibrate while trakbox runs)\n",
                   o.value("reading") ? o.value("reading")->c_str() : dir.c_str());
      return kExitUsage;
    }
    const auto at = o.value("at") ? orbit::parse_iso8601(*o.value("at"))
                                  : std::optional(station::system_now() + owner.model().clock_offset);
    if (!at) {
      std::fprintf(stderr, "trakbox calibrate: --at '%s': expected an ISO 8601 UTC time, e.g. 2026-03-20T09:00:00Z\n",
                   o.value("at")->c_str());
      return kExitUsage;
    }
    r = tracker::calibrate_offsets(owner, *orbit::parse_body(word), *at, *reading, store::Origin::socket);
  }
  if (r.ok() && r.model_changed) {
    nlohmann::json doc = store::to_json(owner.model());
    if (!satrak.is_null()) doc["satrak"] = satrak;
    std::string error;
    if (!file.save(doc, error)) {
      std::fprintf(stderr, "trakbox calibrate: %s: not saved: %s\n", file.path().c_str(), error.c_str());
      return kExitFailure;
    }
  }
  return answer(r, file.path().string());
}

// --scan's options into a request, or why not.
std::optional<SunScanRequest> scan_request(const std::string& word, const ParsedOptions& o, std::string& why) {
  SunScanRequest r;
  const auto number = [&o](const char* key) { return o.value(key) ? text::parse_double(*o.value(key)) : std::nullopt; };
  if (word != "sun") why = "--scan: the Sun only (trakbox calibrate sun --scan)";
  else if (o.has("reading") || o.has("at")) why = "--scan finds the peak itself: no --reading or --at";
  else if (const auto beam = number("beam"); !beam || !(*beam >= 0.2 && *beam <= 60.0))
    why = "--scan needs --beam DEG, the antenna's -3 dB beamwidth, 0.2 to 60";
  else r.beam_deg = *beam;
  if (!why.empty()) return std::nullopt;
  if (const auto shape = o.value("shape"); shape && *shape != "cross" && *shape != "grid") {
    why = "--shape '" + *shape + "': expected cross or grid";
    return std::nullopt;
  }
  r.shape = o.value("shape").value_or("cross") == "grid" ? rotator::ScanShape::grid : rotator::ScanShape::cross;
  const auto readings = number("readings").value_or(5.0), settle = number("settle").value_or(1.0);
  if (readings < 1 || readings > 100 || readings != std::floor(readings) || !(settle >= 0.0 && settle <= 60.0)) {
    why = "--readings 1 to 100, --settle 0 to 60 seconds";
    return std::nullopt;
  }
  r.readings = static_cast<int>(readings);
  r.settle_s = settle;
  r.receiver = o.value("receiver").value_or(r.receiver);
  r.store = o.has("store");
  return r;
}

int scan_on(const std::string& socket, SunScanRequest r) {
  r.socket = socket;
  return run_sun_scan(r);
}

}  // namespace

int run_calibrate(const std::vector<std::string>& args) {
  Subcommand sub;
  if (const auto done = read_subcommand(args, specs(), "calibrate", kUsage, sub)) return *done;
  const std::vector<std::string>& words = sub.words;
  const ParsedOptions& o = sub.options;
  const std::string word = words.empty() ? "" : text::lower(words[0]);
  if (words.size() > 1 || (!word.empty() && word != "undo" && !orbit::parse_body(word))) {
    std::fprintf(stderr, "trakbox calibrate: expected sun, moon or undo (see trakbox calibrate --help)\n");
    return kExitUsage;
  }
  std::optional<SunScanRequest> scan;
  if (o.has("scan")) {
    std::string why;
    scan = scan_request(word, o, why);
    if (!scan) {
      std::fprintf(stderr, "trakbox calibrate: %s (see trakbox calibrate --help)\n", why.c_str());
      return kExitUsage;
    }
  }
  if (const auto socket = o.value("socket")) return scan ? scan_on(*socket, *scan) : through_socket(*socket, word, o);
  const std::filesystem::path dir =
      o.value("state") ? std::filesystem::path(*o.value("state")) : store::default_state_directory();
  LockHolder holder;
  std::string lock_error;
  std::optional<StateLock> lock = StateLock::take(dir, holder, lock_error);
  if (!lock && !lock_error.empty()) {
    std::error_code ec;
    if (!std::filesystem::exists(dir, ec)) {
      std::fprintf(stderr, "trakbox calibrate: %s: no state directory (start trakbox once)\n", dir.c_str());
      return kExitFailure;
    }
    std::fprintf(stderr, "trakbox calibrate: %s\n", lock_error.c_str());
    return kExitFailure;
  }
  const std::string socket = !holder.socket.empty() ? holder.socket : socket_for_state(dir.string());
  if (!lock) return scan ? scan_on(socket, *scan) : through_socket(socket, word, o);
  if (scan) {
    std::fprintf(stderr, "trakbox calibrate: --scan: no station runs on %s; the scan moves its rotator\n", dir.c_str());
    return kExitFailure;
  }
  return on_state_file(dir, o.value("data").value_or(default_data_directory()), word, o);
}

}  // namespace tb::app
