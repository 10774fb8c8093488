#include "tracker/operations.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "rotator/parking_mask.h"
#include "store/model.h"
#include "tracker/elements_refresh.h"
#include "tracker/station_loop.h"
#include "util/exact_number.h"
#include "util/closest.h"
#include "util/text.h"

namespace tb::tracker {

namespace {

// A name as a client typed it, fit to quote in a sentence: printable ASCII only (anything else
// shown as '?'), at most 40 characters.
std::string sat_quoted(std::string_view name) {
  std::string out = "'";
  for (std::size_t i = 0; i < name.size() && i < 40; ++i) {
    const char c = name[i];
    out.push_back(c >= 0x20 && c < 0x7f ? c : '?');
  }
  if (name.size() > 40) out += "...";
  return out + "'";
}

using text::az_el_text;

std::string number(double v) { return text::exact_number(v); }

}  // namespace

StationOps::StationOps(StationLoop& station, Requester who, bool confirmed)
    : station_(station), model_(station.model()), who_(std::move(who)), confirmed_(confirmed) {}

store::Origin StationOps::origin() const {
  switch (who_.kind) {
    case HolderKind::web: return store::Origin::web;
    case HolderKind::host: return store::Origin::host;
    case HolderKind::rotctld: return store::Origin::rotctld;
    case HolderKind::rigctld: return store::Origin::rigctld;
    case HolderKind::satrak: return store::Origin::satrak;
    case HolderKind::pstrotator: return store::Origin::pstrotator;
    case HolderKind::tracking:
    case HolderKind::satnogs:
    case HolderKind::standby: return store::Origin::station;
    case HolderKind::menus: break;
  }
  return store::Origin::menus;
}

std::optional<OpResult> StationOps::ask(Resource r, bool to_tracking) {
  Control::Answer a = station_.control().request(r, who_, station_.now(), confirmed_, to_tracking);
  station_.apply(a.changes);
  if (a.granted) return std::nullopt;
  if (a.confirm) {
    OpResult o = OpResult::refuse(a.confirm->label + " holds the " + std::string(resource_name(r)) +
                                  ": confirm to take it back");
    o.confirm = a.confirm;
    return o;
  }
  return OpResult::refuse(a.refusal.value_or("the " + std::string(resource_name(r)) + " is held"));
}

std::optional<int> StationOps::find_satellite(std::string_view name) const {
  const auto& db = model_.db;
  if (const auto exact = db.find(name)) return exact;
  const std::string want = text::upper(text::trim(name, text::kWhitespace));
  if (want.empty()) return std::nullopt;
  for (std::size_t i = 0; i < db.satellites.size(); ++i)
    if (text::upper(db.satellites[i].name()) == want) return static_cast<int>(i);
  return std::nullopt;
}

OpResult StationOps::track(int db_index) {
  const auto& db = model_.db;
  if (const auto body = body_target(db_index)) return track_body(*body);
  if (db_index < 0 || db_index >= static_cast<int>(db.satellites.size()))
    return OpResult::refuse("no satellite " + std::to_string(db_index) + " in the database");
  if (auto no = ask(Resource::antenna, true)) return *no;
  if (auto no = ask(Resource::radio, true)) return *no;
  OpResult r;
  if (const int n = db.list_number(db_index); n > 0 && db.marked != n - 1)
    r.model_changed = station_.owner()
                          .edit(store::bit(store::Area::tracking_list), "marked satellite", origin(),
                                [&](store::Model& m) { m.db.marked = n - 1; })
                          .changed;
  station_.tracker().track_single(db_index);
  station_.antenna_changed();
  r.note = "tracking " + db.satellites[static_cast<std::size_t>(db_index)].name();
  return r;
}

std::string StationOps::unknown_satellite(std::string_view name) const {
  std::vector<std::string> names;
  for (const auto& s : model_.db.satellites) names.push_back(s.name());
  return "unknown satellite " + sat_quoted(name) + text::did_you_mean(name, names);
}

OpResult StationOps::track_body(orbit::Body body) {
  if (auto no = ask(Resource::antenna, true)) return *no;
  if (auto no = ask(Resource::radio, true)) return *no;
  station_.tracker().track_single(target_index(body));
  station_.antenna_changed();
  OpResult r;
  r.note = fmt::format("tracking {}", orbit::body_name(body));
  return r;
}

OpResult StationOps::track(std::string_view name) {
  // A satellite of that name first (a database may hold one called SUN); else the Sun or the Moon.
  if (const auto body = orbit::parse_body(text::trim(name, text::kWhitespace)); body && !find_satellite(name))
    return track_body(*body);
  const auto i = find_satellite(name);
  if (!i) return OpResult::refuse(unknown_satellite(name));
  return track(*i);
}

OpResult StationOps::track_multi(bool priority) {
  const auto& db = model_.db;
  if (db.selected.size() < static_cast<std::size_t>(store::kMinMultiTrack))
    return OpResult::refuse("multiple tracking needs two or more satellites in the tracking list (menu 3-2)");
  if (auto no = ask(Resource::antenna, true)) return *no;
  if (auto no = ask(Resource::radio, true)) return *no;
  OpResult r;
  r.model_changed = station_.owner().set("priority_mode", priority, origin()).changed;
  station_.tracker().track_multi(priority);
  station_.antenna_changed();
  const int n = std::min<int>(db.multi_count, static_cast<int>(db.selected.size()));
  r.note = std::string("multiple tracking (") + (priority ? "priority" : "normal") + ") of #1-#" + std::to_string(n);
  return r;
}

OpResult StationOps::track_list(const std::vector<std::string>& names, bool priority) {
  if (names.size() < static_cast<std::size_t>(store::kMinMultiTrack) ||
      names.size() > static_cast<std::size_t>(store::kMaxMultiTrack))
    return OpResult::refuse("multiple tracking takes " + std::to_string(store::kMinMultiTrack) + " to " +
                            std::to_string(store::kMaxMultiTrack) + " satellites; " + std::to_string(names.size()) +
                            " given");
  std::vector<int> chosen;
  for (const std::string& name : names) {
    const auto i = find_satellite(name);
    if (!i) return OpResult::refuse(unknown_satellite(name));
    if (std::find(chosen.begin(), chosen.end(), *i) != chosen.end())
      return OpResult::refuse("satellite " + sat_quoted(name) + " is named twice");
    chosen.push_back(*i);
  }
  if (auto no = ask(Resource::antenna, true)) return *no;
  if (auto no = ask(Resource::radio, true)) return *no;
  // Validated: the chosen ones first, the rest of the list after them, at most 15; those that no
  // longer fit are named in the note (issue 46: never dropped without a word).
  store::Database db = model_.db;
  std::vector<int> list = chosen;
  std::string dropped;
  for (const int i : db.selected) {
    if (std::find(chosen.begin(), chosen.end(), i) != chosen.end()) continue;
    if (list.size() < static_cast<std::size_t>(store::kMaxSelected)) list.push_back(i);
    else dropped += (dropped.empty() ? "" : ", ") + db.satellites[static_cast<std::size_t>(i)].name();
  }
  db.selected = std::move(list);
  db.multi_count = static_cast<int>(chosen.size());
  db.marked = 0;
  db.normalise();
  const store::EditResult kept = station_.owner().edit(store::bit(store::Area::tracking_list), "tracking list",
                                                       origin(), [&](store::Model& m) { m.db = db; });
  if (!kept.ok()) return OpResult::refuse(*kept.refusal);
  OpResult r = track_multi(priority);
  r.model_changed = true;
  if (!dropped.empty())
    r.note += "; the tracking list holds " + std::to_string(store::kMaxSelected) + ": " + dropped + " left it";
  return r;
}

OpResult StationOps::stop() {
  // Stop always stops the motors (a safety action: in standby, under --exclusive, whoever holds);
  // it takes the antenna when the controller grants it, else the holder keeps it.
  const std::optional<OpResult> no = station_.control().standby() ? std::nullopt : ask(Resource::antenna);
  station_.rotator().stop();
  station_.antenna_changed();
  OpResult r;
  r.note = no ? "antenna stopped; " + station_.control().holder(Resource::antenna).label + " still holds it"
              : "antenna stopped";
  return r;
}

std::optional<std::string> StationOps::parking_into_mask() const {
  return rotator::parking_mask_warning(model_.rotator, model_.station.mask().get());
}

OpResult StationOps::park() {
  if (!station_.rotator().config().parking_enabled)
    return OpResult::refuse("parking is off (menu 6-4 sets the parking position)");
  if (auto no = ask(Resource::antenna)) return *no;
  OpResult r = rotor_control(true);
  if (!outside()) station_.tracker().stop();  // an outside client's park suspends tracking, as a move does
  station_.rotator().park();
  station_.antenna_changed();
  r.note = "parking";
  if (const auto w = parking_into_mask()) {  // said, not moved: the parking position is the operator's
    spdlog::warn("antenna: parks into the horizon mask: {}", *w);
    r.note += "; WARNING: " + *w;
  }
  return r;
}

OpResult StationOps::rotor_control(bool on) {
  OpResult r;
  if (station_.rotor_control() != on) r.model_changed = true;
  station_.set_rotor_control(on);
  r.note = std::string("rotor control ") + (on ? "on" : "off");
  return r;
}

OpResult StationOps::go_to(double az_deg, double el_deg) {
  if (!std::isfinite(az_deg) || az_deg < 0.0 || az_deg > 360.0)
    return OpResult::refuse("azimuth " + number(az_deg) + " out of range: expected 0 to 360");
  const double top = station_.rotator().config().el_top_deg();  // 90, or 180 for a flip rotator
  if (!std::isfinite(el_deg) || el_deg < 0.0 || el_deg > top)
    return OpResult::refuse("elevation " + number(el_deg) + " out of range: expected 0 to " + number(top));
  if (auto no = ask(Resource::antenna)) return *no;
  // Pointing takes control, as the operator pressing E would; the limits still hold (point clamps).
  // The operator's goto ends tracking; an outside client's suspends it until its hold ends.
  OpResult r = rotor_control(true);
  const rotator::AzEl asked{rotator::wrap360(az_deg), el_deg};
  const rotator::AzEl got =
      outside() ? station_.point_held(asked, who_.label, kind_name(who_.kind)) : station_.point(asked);
  r.commanded = got;
  r.note = "pointing at " + az_el_text(got.az, got.el);
  if (rotator::azimuth_distance(asked.az, got.az) > 0.05 || std::abs(asked.el - got.el) > 0.05)
    r.note = "limited to " + az_el_text(got.az, got.el);
  return r;
}

OpResult StationOps::doppler(bool on) {
  station_.set_doppler(on);
  OpResult r;
  r.note = std::string("Doppler ") + (on ? "on" : "off");
  return r;
}

OpResult StationOps::take_radio() {
  if (auto no = ask(Resource::radio)) return *no;
  return {};
}

OpResult StationOps::standby(bool on) {
  if (is_outside(who_.kind)) return OpResult::refuse("standby is the operator's");
  OpResult r;
  // Stored (and so on disk) before it is acknowledged.
  r.model_changed = station_.owner().set("sharing.standby", on, origin()).changed;
  if (on) {
    station_.apply(station_.control().set_standby(true, station_.now()));
    if (station_.rotator().config().parking_enabled) {
      rotor_control(true);
      station_.rotator().park();
      if (const auto w = parking_into_mask()) spdlog::warn("antenna: parks into the horizon mask: {}", *w);
    } else {
      station_.rotator().stop();
    }
    station_.antenna_changed();
    r.note = "standby on: nothing moves by itself";
  } else {
    station_.apply(station_.control().set_standby(false, station_.now()));
    r.note = "standby off";
  }
  return r;
}

OpResult StationOps::reserve(orbit::UtcTime start, orbit::UtcTime end, std::string note) {
  if (end <= start) return OpResult::refuse("a reservation ends after it starts");
  const orbit::UtcTime now = station_.now();
  if (end <= now) return OpResult::refuse("that reservation is over already (" + orbit::format_iso8601(end) + ")");
  if (note.size() > 200) return OpResult::refuse("the note of a reservation takes 200 bytes at most");
  const auto& list = model_.sharing.reservations;
  const auto unix_s = [](orbit::UtcTime t) {
    return static_cast<std::int64_t>(std::chrono::duration_cast<std::chrono::seconds>(t.time_since_epoch()).count());
  };
  std::vector<store::Reservation> kept;
  for (const auto& r : list)
    if (r.end_unix > unix_s(now)) kept.push_back(r);
  if (kept.size() >= store::kMaxReservations)
    return OpResult::refuse("the station keeps " + std::to_string(store::kMaxReservations) + " reservations at most");
  store::Reservation r{"op-" + std::to_string(unix_s(start)), unix_s(start), unix_s(end), std::move(note)};
  kept.push_back(r);
  std::sort(kept.begin(), kept.end(), [](const auto& a, const auto& b) { return a.start_unix < b.start_unix; });
  const store::EditResult done = station_.owner().edit(store::bit(store::Area::sharing), "reservation", origin(),
                                                       [&](store::Model& m) { m.sharing.reservations = kept; });
  if (!done.ok()) return OpResult::refuse(*done.refusal);
  OpResult o;
  o.model_changed = true;
  o.note = "reserved " + orbit::format_iso8601(start) + " to " + orbit::format_iso8601(end) + " (" + r.id + ")";
  return o;
}

OpResult StationOps::take_back() {
  if (auto no = ask(Resource::antenna, true)) return *no;
  if (auto no = ask(Resource::radio, true)) return *no;
  OpResult r;
  r.note = "trakbox's tracking holds the antenna and the radio";
  return r;
}

OpResult StationOps::refresh_elements(std::int64_t now_unix) {
  ElementsRefresh* refresh = station_.refresh();
  if (!refresh) return OpResult::refuse("this trakbox has no element refresh (it runs only with the station)");
  // The sources' servers block addresses that ask too often (CelesTrak: once per two hours): a
  // manual refresh at most every 10 minutes per source, whichever front end asks (issue 46), in the
  // station's clock (--clock-rate makes it pass faster, as the tests want).
  const orbit::UtcTime now = refresh->station_now();
  if (const auto next = refresh->manual_next(now)) {
    const auto wait = std::chrono::ceil<std::chrono::seconds>(*next - now).count();
    const std::string at = orbit::format_iso8601(*next).substr(11, 8);
    return OpResult::refuse("the elements were refreshed less than 10 minutes ago: the next manual refresh at " + at +
                            " UTC, in " + std::to_string(wait) + " s");
  }
  if (const auto why = refresh->refresh_now(now_unix)) return OpResult::refuse(*why);
  refresh->note_manual(now);
  OpResult r;
  r.note = "element refresh started";
  return r;
}

}  // namespace tb::tracker
