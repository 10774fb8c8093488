#include "tracker/operations.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "store/model.h"
#include "tracker/elements_refresh.h"
#include "tracker/station_loop.h"
#include "util/text.h"

namespace tb::tracker {

namespace {

// A name as a client typed it, fit to quote in a sentence: printable ASCII only (anything else
// shown as '?'), at most 40 characters.
std::string quoted(std::string_view name) {
  std::string out = "'";
  for (std::size_t i = 0; i < name.size() && i < 40; ++i) {
    const char c = name[i];
    out.push_back(c >= 0x20 && c < 0x7f ? c : '?');
  }
  if (name.size() > 40) out += "...";
  return out + "'";
}

std::string az_el_text(double az, double el) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "AZ%.1f EL%.1f", az, el);
  return buf;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

StationOps::StationOps(StationLoop& station) : station_(station), model_(station.model()) {}

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
  auto& db = model_.db;
  if (db_index < 0 || db_index >= static_cast<int>(db.satellites.size()))
    return OpResult::refuse("no satellite " + std::to_string(db_index) + " in the database");
  OpResult r;
  if (const int n = db.list_number(db_index); n > 0 && db.marked != n - 1) {
    db.marked = n - 1;
    r.model_changed = true;
  }
  station_.tracker().track_single(db_index);
  station_.antenna_changed();
  r.note = "tracking " + db.satellites[static_cast<std::size_t>(db_index)].name();
  return r;
}

OpResult StationOps::track(std::string_view name) {
  const auto i = find_satellite(name);
  if (!i) return OpResult::refuse("unknown satellite " + quoted(name));
  return track(*i);
}

OpResult StationOps::track_multi(bool priority) {
  auto& db = model_.db;
  if (db.selected.size() < static_cast<std::size_t>(store::kMinMultiTrack))
    return OpResult::refuse("multiple tracking needs two or more satellites in the tracking list (menu 3-2)");
  OpResult r;
  if (model_.priority_mode != priority) {
    model_.priority_mode = priority;
    r.model_changed = true;
  }
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
    if (!i) return OpResult::refuse("unknown satellite " + quoted(name));
    if (std::find(chosen.begin(), chosen.end(), *i) != chosen.end())
      return OpResult::refuse("satellite " + quoted(name) + " is named twice");
    chosen.push_back(*i);
  }
  // Validated: the chosen ones first, the rest of the list after them, at most 15.
  auto& db = model_.db;
  std::vector<int> list = chosen;
  for (const int i : db.selected)
    if (std::find(chosen.begin(), chosen.end(), i) == chosen.end() &&
        list.size() < static_cast<std::size_t>(store::kMaxSelected))
      list.push_back(i);
  db.selected = std::move(list);
  db.multi_count = static_cast<int>(chosen.size());
  db.marked = 0;
  db.normalise();
  OpResult r = track_multi(priority);
  r.model_changed = true;
  return r;
}

OpResult StationOps::stop() {
  station_.stop_antenna();
  OpResult r;
  r.note = "tracking stopped, antenna stopped";
  return r;
}

OpResult StationOps::park() {
  if (!station_.rotator().config().parking_enabled)
    return OpResult::refuse("parking is off (menu 6-4 sets the parking position)");
  OpResult r = rotor_control(true);
  station_.tracker().stop();
  station_.rotator().park();
  station_.antenna_changed();
  r.note = "parking";
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
  // Pointing takes control, as the operator pressing E would; the limits still hold (point clamps).
  OpResult r = rotor_control(true);
  const rotator::AzEl asked{rotator::wrap360(az_deg), el_deg};
  const rotator::AzEl got = station_.point(asked);
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

OpResult StationOps::refresh_elements(std::int64_t now_unix) {
  ElementsRefresh* refresh = station_.refresh();
  if (!refresh) return OpResult::refuse("this trakbox has no element refresh (it runs only with the station)");
  if (const auto why = refresh->refresh_now(now_unix)) return OpResult::refuse(*why);
  OpResult r;
  r.note = "element refresh started";
  return r;
}

}  // namespace tb::tracker
