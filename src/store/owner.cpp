#include "store/owner.h"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "store/settings.h"

namespace tb::store {
using nlohmann::json;

const char* to_string(Area a) {
  switch (a) {
    case Area::position: return "position";
    case Area::elements: return "elements";
    case Area::radio_entries: return "radio entries";
    case Area::tracking_list: return "tracking list";
    case Area::station: return "station";
    case Area::rotator: return "rotator";
    case Area::radio: return "radio";
    case Area::control: return "control";
    case Area::sharing: return "sharing";
    case Area::logger: return "logger";
    case Area::gps: return "gps";
    case Area::other: return "other";
    case Area::count: break;
  }
  return "?";
}

const char* to_string(Origin o) {
  switch (o) {
    case Origin::defaults: return "default";
    case Origin::state: return "state";
    case Origin::command_line: return "command line";
    case Origin::menus: return "menus";
    case Origin::host: return "host mode";
    case Origin::web: return "web";
    case Origin::socket: return "trakbox settings";
    case Origin::satrak: return "satrak";
    case Origin::rotctld: return "rotctld";
    case Origin::rigctld: return "rigctld";
    case Origin::pstrotator: return "pstrotator";
    case Origin::signal: return "SIGHUP";
    case Origin::gps: return "gps";
    case Origin::station: return "station";
    case Origin::refresh: return "refresh";
  }
  return "?";
}

Areas areas_of(std::string_view key) {
  auto starts = [&](std::string_view p) { return key.substr(0, p.size()) == p; };
  if (key == "station.lat_deg" || key == "station.lon_deg" || key == "station.height_m") return bit(Area::position);
  if (starts("station.")) return bit(Area::station) | (key == "station.rotor_start" ? bit(Area::rotator) : 0);
  if (starts("rotator") || starts("pass_events.")) return bit(Area::rotator);
  if (key == "rotor_control" || key == "priority_mode") return bit(Area::control) | bit(Area::rotator);
  if (starts("radio.")) return bit(Area::radio);
  if (starts("sharing.")) return bit(Area::sharing);
  if (starts("logger.")) return bit(Area::logger);
  if (starts("gps.")) return bit(Area::gps);
  return bit(Area::other);
}

ModelOwner::ModelOwner(Model initial, Origin from) : model_(std::move(initial)), loaded_from_(from) {}

EditResult ModelOwner::edit(Areas areas, std::string what, Origin origin, const std::function<void(Model&)>& change) {
  EditResult r;
  Model copy = model_;
  change(copy);
  // What the next start reads back: the same reader, the same sentences. A copy the reader refuses
  // never becomes the state (it would be set aside whole at the next start).
  const json after = to_json(copy);
  try {
    (void)model_from_json(after);
  } catch (const std::exception& e) {
    r.refusal = e.what();
    return r;
  }
  if (after == to_json(model_)) return r;
  // Assigned over the model in place (not moved in), so that the storage of its lists is reused and
  // a reader's reference into them stays on the same element wherever the list did not grow.
  model_ = copy;
  r.changed = true;
  for (unsigned a = 0; a < static_cast<unsigned>(Area::count); ++a)
    if (areas & (1u << a)) ++versions_[a];
  announce(Notice{areas, std::move(what), origin});
  return r;
}

void ModelOwner::announce(Notice n) {
  pending_.push_back(std::move(n));
  if (announcing_) return;  // an edit made by a listener: told after the one in progress
  announcing_ = true;
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    const Notice notice = pending_[i];
    for (const auto& f : listeners_) f(notice);
  }
  pending_.clear();
  announcing_ = false;
}

EditResult ModelOwner::set(std::string_view key, const Value& value, Origin origin) {
  return set_json(key, std::visit([](const auto& v) { return json(v); }, value), origin);
}

EditResult ModelOwner::set_json(std::string_view key, const json& value, Origin origin) {
  const Setting* s = find_setting(key);
  if (!s) return {std::string(key) + ": no such setting (trakbox settings lists them)", false};
  if (auto why = refusal(*s, value)) return {std::move(why), false};
  EditResult r = edit(areas_of(key), std::string(key), origin, [&](Model& m) { s->put(m, value); });
  if (r.ok()) origins_[std::string(key)] = origin;
  return r;
}

EditResult ModelOwner::set_typed(std::string_view key, std::string_view typed, Origin origin) {
  const Setting* s = find_setting(key);
  if (!s) return {std::string(key) + ": no such setting (trakbox settings lists them)", false};
  const ParsedSetting p = parse_setting(*s, typed);
  if (!p.value) return {p.error, false};
  return set_json(key, *p.value, origin);
}

EditResult ModelOwner::reset(std::string_view key, Origin origin) {
  const Setting* s = find_setting(key);
  if (!s) return {std::string(key) + ": no such setting (trakbox settings lists them)", false};
  EditResult r = set_json(key, s->get(factory_defaults()), origin);
  if (r.ok()) origins_[std::string(key)] = Origin::defaults;
  return r;
}

Origin ModelOwner::origin_of(std::string_view key) const {
  if (const auto it = origins_.find(key); it != origins_.end()) return it->second;
  const Setting* s = find_setting(key);
  if (s && s->get(model_) == s->get(factory_defaults())) return Origin::defaults;
  return loaded_from_;
}

EditResult ModelOwner::set_position(double lat_deg, double lon_deg, double height_m, Origin origin,
                                    std::optional<orbit::UtcTime> gps_fix_time) {
  // Each number by the table's rule and sentence, before anything is changed.
  const std::pair<const char*, double> parts[] = {
      {"station.lat_deg", lat_deg}, {"station.lon_deg", lon_deg}, {"station.height_m", height_m}};
  for (const auto& [key, v] : parts)
    if (auto why = refusal(*find_setting(key), json(v))) return {std::move(why), false};
  EditResult r = edit(bit(Area::position) | bit(Area::gps), "station position", origin, [&](Model& m) {
    m.station.lat_deg = lat_deg;
    m.station.lon_deg = lon_deg;
    m.station.height_m = height_m;
    m.gps.position_from_gps = gps_fix_time.has_value();
    m.gps.position_time = gps_fix_time;
  });
  if (r.ok())
    for (const auto& [key, v] : parts) origins_[key] = origin;
  return r;
}

EditResult ModelOwner::replace_database(Database db, Areas areas, std::string what, Origin origin) {
  return edit(areas, std::move(what), origin, [&](Model& m) { m.db = std::move(db); });
}

}  // namespace tb::store
