#include "live/station_command.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "live/station_app.h"
#include "orbit/sky.h"
#include "orbit/time.h"
#include "store/mode_import.h"
#include "store/owner.h"
#include "store/settings.h"
#include "tracker/station_loop.h"
#include "tracker/operations.h"
#include "util/json_limits.h"
#include "util/safe_text.h"
#include "util/text.h"

namespace tb::app {

bool is_station_command(const std::string& line) {
  return line.rfind("standby", 0) == 0 || line.rfind("reserve", 0) == 0 || line.rfind("settings", 0) == 0 ||
         line.rfind("track ", 0) == 0 || line.rfind("calibrate", 0) == 0 || line.rfind("radio ", 0) == 0;
}

namespace {

// `trakbox settings`: the list as JSON (one line); `settings set KEY VALUE` and `settings reset
// KEY` through the model's one door, which checks, stores and announces (the station reconfigures
// and saves before the answer).
std::string settings_command(StationApp& app, const std::vector<std::string>& w) {
  store::ModelOwner& owner = app.owner();
  if (w.size() == 1) {
    return store::settings_document(owner.model(), [&owner](std::string_view key) {
             return std::string(store::to_string(owner.origin_of(key)));
           }).dump();
  }
  store::EditResult r;
  if (w.size() >= 4 && w[1] == "set") {
    std::string value;
    for (std::size_t i = 3; i < w.size(); ++i) value += (value.empty() ? "" : " ") + w[i];
    r = owner.set_typed(w[2], value, store::Origin::socket);
  } else if (w.size() == 3 && w[1] == "reset") {
    r = owner.reset(w[2], store::Origin::socket);
  } else {
    return "refused: expected settings, settings set KEY VALUE or settings reset KEY";
  }
  if (!r.ok()) return "refused: " + *r.refusal;
  const store::Setting* s = store::find_setting(w[2]);
  std::string now = w[2] + " = " + store::shown(*s, s->get(owner.model()));
  if (const auto warn = store::setting_warning(w[2], owner.model())) now += "; WARNING: " + *warn;
  if (!r.changed) return "ok: " + now + " (unchanged)";
  if (const auto& failed = app.station().save_failure()) return "ok: " + now + " (NOT SAVED: " + *failed + ")";
  return "ok: " + now;
}

// `trakbox track SAT [--mode NAME]`, sent as "track [--mode NAME] SAT": single tracking of SAT in
// that mode (issue 59). The mode is checked before anything changes; then chosen, then tracked, so
// the radio goes to the mode's spot at once.
tracker::OpResult track_command(tracker::StationOps& ops, const StationApp& app, const std::vector<std::string>& w) {
  std::size_t first = 1;
  std::string mode;
  if (w.size() >= 4 && w[1] == "--mode") {
    mode = w[2];
    first = 3;
  }
  std::string sat;
  for (std::size_t i = first; i < w.size(); ++i) sat += (sat.empty() ? "" : " ") + w[i];
  if (sat.empty()) return tracker::OpResult::refuse("expected track SAT [--mode NAME]");
  const auto db = ops.find_satellite(sat);
  if (!db) return tracker::OpResult::refuse("unknown satellite '" + text::safe_text(sat) + "'");
  tracker::OpResult chosen;
  if (!mode.empty()) {
    const store::Satellite& s = app.model().db.satellites[static_cast<std::size_t>(*db)];
    chosen = ops.choose_mode(s.name(), mode);
    if (!chosen.ok()) return chosen;
  }
  tracker::OpResult r = ops.track(*db);
  if (!r.ok()) return r;
  r.model_changed = r.model_changed || chosen.model_changed;
  if (!chosen.note.empty()) r.note += (r.note.empty() ? "" : "; ") + chosen.note;
  return r;
}

// The sun-noise scan's moves (`trakbox calibrate sun --scan`, cli/calibrate_scan.cpp): a goto as the
// holder "sun scan", so that anyone else's Stop, move or standby shows as another holder and ends
// the scan; the answer says where the antenna was sent (inside the limits).
std::string scan_goto(StationApp& app, const std::vector<std::string>& w) {
  const auto az = text::parse_double(w[2]), el = text::parse_double(w[3]);
  if (!az || !el) return "refused: expected calibrate goto AZ EL";
  tracker::StationOps ops(app.station(), {tracker::HolderKind::menus, "sun scan"}, false);
  const tracker::OpResult r = ops.go_to(*az, *el);
  if (!r.ok()) return "refused: " + *r.refusal;
  return fmt::format("ok: commanded {:.4f} {:.4f}", r.commanded ? r.commanded->az : *az,
                     r.commanded ? r.commanded->el : *el);
}

// The scan's result stored: `calibrate store-scan TIME DAZ DEL`.
tracker::OpResult store_scan(tracker::StationOps& ops, const std::vector<std::string>& w) {
  const auto t = orbit::parse_iso8601(w[2]);
  const auto daz = text::parse_double(w[3]), del = text::parse_double(w[4]);
  if (!t || !daz || !del) return tracker::OpResult::refuse("expected calibrate store-scan TIME DAZ DEL");
  return ops.calibrate_scan(*t, *daz, *del);
}

// `trakbox calibrate`: the stored offsets; `calibrate sun|moon`: the rotator's reading now against
// the body's position; `calibrate undo` (tracker/operations.h). Saved before the answer.
std::string calibrate_command(StationApp& app, const std::vector<std::string>& w) {
  tracker::StationOps ops(app.station(), tracker::Requester::menus(), true);
  if (w.size() == 1) return "ok: " + tracker::calibration_text(app.model().rotator);
  tracker::OpResult r;
  if (w.size() == 4 && w[1] == "goto") return scan_goto(app, w);
  if (w.size() == 5 && w[1] == "store-scan") r = store_scan(ops, w);
  else if (w.size() == 2 && w[1] == "undo") r = ops.calibrate_undo();
  else if (const auto body = w.size() == 2 ? orbit::parse_body(w[1]) : std::nullopt) r = ops.calibrate(*body);
  else return "refused: expected calibrate, calibrate sun, calibrate moon or calibrate undo";
  if (!r.ok()) return "refused: " + *r.refusal;
  if (r.model_changed)
    if (const auto why = app.save()) return "ok: " + r.note + " (NOT SAVED: " + *why + ")";
  return "ok: " + r.note;
}

// `trakbox radio import|diff` (cli/radio_client.cpp): "radio {json}", answered in one JSON line; an
// import is one named edit of the radio entries (the station re-tunes and saves before the answer).
std::string radio_command(StationApp& app, const std::string& body) {
  std::string why;
  const nlohmann::json request = json_limits::parse_bounded<nlohmann::json>(body, why);
  if (request.is_discarded()) return nlohmann::json{{"error", "not a radio request: " + why}}.dump();
  nlohmann::json answer = store::radio_request(app.owner(), request, store::Origin::socket);
  if (answer.value("changed", false))
    if (const auto& failed = app.station().save_failure())
      answer["lines"].push_back("NOT SAVED: " + *failed);
  return answer.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace

std::string run_station_command(StationApp& app, const std::string& line) {
  if (line.rfind("radio ", 0) == 0) return radio_command(app, line.substr(6));
  std::vector<std::string> w;
  for (const std::string_view piece : text::split(line, ' '))
    if (!piece.empty()) w.emplace_back(piece);
  if (w.empty()) return "refused: nothing asked";
  if (w[0] == "settings") return settings_command(app, w);
  if (w[0] == "calibrate") return calibrate_command(app, w);
  tracker::StationOps ops(app.station(), tracker::Requester::menus(), true);
  tracker::OpResult r;
  if (w.size() == 2 && w[0] == "standby" && (w[1] == "on" || w[1] == "off")) {
    r = ops.standby(w[1] == "on");
  } else if (w[0] == "track") {
    r = track_command(ops, app, w);
  } else if (w[0] == "standby") {
    return "refused: expected standby on or standby off";
  } else if (w.size() >= 3 && w[0] == "reserve") {
    const auto start = orbit::parse_iso8601(w[1]);
    const auto end = orbit::parse_iso8601(w[2]);
    if (!start || !end)
      return "refused: expected reserve START END [NOTE] with ISO 8601 UTC times, e.g. 2026-05-21T12:20:00Z";
    std::string note;
    for (std::size_t i = 3; i < w.size(); ++i) note += (note.empty() ? "" : " ") + w[i];
    r = ops.reserve(*start, *end, text::safe_text(note));
  } else {
    return "refused: expected reserve START END [NOTE]";
  }
  if (!r.ok()) return "refused: " + *r.refusal;
  if (r.model_changed)
    if (const auto why = app.save()) return "ok: " + r.note + " (NOT SAVED: " + *why + ")";
  return "ok: " + r.note;
}

}  // namespace tb::app
