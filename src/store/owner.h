// The one owner of the station's stored state (issue 55): every change of store::Model goes through
// here, as a named edit that checks the whole changed model as the state reader will read it back,
// applies it, and announces what changed. Everyone else holds `const Model&`
// (scripts/check-architecture.py refuses a writable Model outside this file and model.cpp).
//
//   front end (menus, host, web, rotctld, Satrak, PstRotator, socket, SIGHUP, GPS, command line)
//        |  named edit: set("station.height_m", 120), set_position(...), replace_database(...)
//        v
//   ModelOwner: copy -> change -> model_from_json(to_json(copy)) -> apply -> version[area]++
//        |  Notice{areas, what, origin}
//        v
//   listeners: the station loop (reconfigure), the pass cache, the Satrak unit, the saver, the feed
//
// So a value the reader would refuse at the next start is refused now, with the reader's sentence
// ("station.height_m: 12000 is outside -500 .. 9000 m"), and nothing was changed. Pure apart from
// the listeners it calls.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "store/model.h"

namespace tb::store {

// The parts of the state whose change someone listens for, each with its own version.
enum class Area : unsigned {
  position,       // station.lat/lon/height: passes, look angles, the pass cache
  elements,       // the database's element sets (uploads, refreshes, SIGHUP)
  radio_entries,  // the database's radio records (freq/mode), tones
  tracking_list,  // db.selected, marked, multi_count
  station,        // the rest of station.* (callsign, rotor start, COM speed)
  rotator,        // rotator.*, rotor control, error detection, pass_events
  radio,          // radio.* (CAT, Doppler practice, corrections)
  control,        // rotor control, tracking choice, priority mode
  sharing,        // sharing.*: handback, exclusive, standby, reservations, SatNOGS
  logger,         // logger.*
  gps,            // gps.*
  other,          // drivers, udp events, refresh settings, clock offset, events
  count
};
const char* to_string(Area a);

using Areas = unsigned;  // a set of Area bits
constexpr Areas bit(Area a) { return 1u << static_cast<unsigned>(a); }
constexpr Areas kAllAreas = (1u << static_cast<unsigned>(Area::count)) - 1;  // a whole new model

// Who asked: for the log and for `trakbox settings`' "from".
enum class Origin { defaults, state, command_line, menus, host, web, socket, satrak, rotctld, rigctld, pstrotator,
                    signal, gps, station, refresh };
const char* to_string(Origin o);

struct Notice {
  Areas areas = 0;
  std::string what;  // "station.height_m", "database", "tracking choice"
  Origin origin = Origin::station;
  bool changes(Area a) const { return (areas & bit(a)) != 0; }
};

struct EditResult {
  std::optional<std::string> refusal;  // nothing changed, and why
  bool changed = false;                // the model differs from before (a notice went out)
  bool ok() const { return !refusal; }
};

class ModelOwner {
 public:
  explicit ModelOwner(Model initial = factory_defaults(), Origin from = Origin::state);
  ModelOwner(const ModelOwner&) = delete;
  ModelOwner& operator=(const ModelOwner&) = delete;
  // Moved only before anyone reads through it (the start hands it to the station).
  ModelOwner(ModelOwner&&) = default;
  ModelOwner& operator=(ModelOwner&&) = delete;

  const Model& model() const { return model_; }
  std::uint64_t version(Area a) const { return versions_[static_cast<unsigned>(a)]; }

  // Called after every applied edit, in the order they were added. A listener may read the model
  // and may make further edits (they are announced after the one in progress).
  void listen(std::function<void(const Notice&)> f) { listeners_.push_back(std::move(f)); }

  // The one general edit: `change` applied to a copy, the whole copy checked as the state reader
  // reads it back, then applied and announced as `areas`. Nothing changes when it is refused.
  EditResult edit(Areas areas, std::string what, Origin origin, const std::function<void(Model&)>& change);

  // A setting of the table (store/settings.h), by key: a value, its JSON form, or as typed ("9000",
  // "on"). Whole numbers are taken for number settings too.
  using Value = std::variant<bool, long long, double, std::string>;
  EditResult set(std::string_view key, const Value& value, Origin origin);
  EditResult set_json(std::string_view key, const nlohmann::json& value, Origin origin);
  EditResult set_typed(std::string_view key, std::string_view typed, Origin origin);
  // Back to the factory value.
  EditResult reset(std::string_view key, Origin origin);
  // Where each setting's value came from (a setting never set here: state or defaults).
  Origin origin_of(std::string_view key) const;

  // The station's position (menu 4, --station, the page, host QTH, a followed GPS fix): each
  // number checked by the table; from_gps records the fix's time and marks the position as the
  // receiver's (a typed position clears that).
  EditResult set_position(double lat_deg, double lon_deg, double height_m, Origin origin,
                          std::optional<orbit::UtcTime> gps_fix_time = std::nullopt);
  // A whole new database (menus 2 and 3 uploads, 6-9's station file, SIGHUP's freq/mode file,
  // the element refresh): checked whole, then it replaces the old one.
  EditResult replace_database(Database db, Areas areas, std::string what, Origin origin);

 private:
  Model model_;
  std::array<std::uint64_t, static_cast<unsigned>(Area::count)> versions_{};
  std::vector<std::function<void(const Notice&)>> listeners_;
  std::map<std::string, Origin, std::less<>> origins_;
  Origin loaded_from_;
  std::vector<Notice> pending_;
  bool announcing_ = false;
  void announce(Notice n);
};

// The areas a setting of the table belongs to ("station.lat_deg": position; "rotator.*": rotator).
Areas areas_of(std::string_view key);

}  // namespace tb::store
