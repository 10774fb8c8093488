#include "cli/cli_defaults.h"

#include <cctype>
#include <chrono>
#include <cmath>

#include <cstdio>

#include <nlohmann/json.hpp>

#include "cli/attach_client.h"
#include "live/station_app.h"
#include "live/station_socket.h"
#include "orbit/time.h"
#include "util/json_limits.h"
#include "cli/tracker_config.h"
#include "station/station.h"
#include "store/model.h"
#include "store/settings.h"
#include "store/state_file.h"
#include "util/text.h"

namespace tb::app {

std::optional<orbit::Observer> maidenhead_centre(std::string_view loc) { return station::maidenhead_centre(loc); }

Parsed<orbit::Observer> parse_station_text(std::string_view text) {
  // The one reading of a typed position (store/settings.h), which host mode's QTH shares.
  const store::ParsedPosition p = store::parse_position(text);
  Parsed<orbit::Observer> r;
  if (!p.ok()) r.error = p.error;
  else r.value = orbit::Observer{p.lat_deg, p.lon_deg, p.height_m.value_or(0.0)};
  return r;
}

Parsed<orbit::UtcTime> parse_time_text(std::string_view text, orbit::UtcTime now) {
  Parsed<orbit::UtcTime> r;
  const std::string t(text::trim(text));
  if (t == "now") {
    r.value = now;
    return r;
  }
  if (!t.empty() && (t[0] == '+' || t[0] == '-') && t.size() >= 3) {
    const char unit = static_cast<char>(std::tolower(static_cast<unsigned char>(t.back())));
    const double per = unit == 's' ? 1.0 : unit == 'm' ? 60.0 : unit == 'h' ? 3600.0 : unit == 'd' ? 86400.0 : 0.0;
    const auto amount = text::parse_double(std::string_view(t).substr(1, t.size() - 2));
    if (per > 0.0 && amount && *amount >= 0.0 && *amount * per <= 366.0 * 86400.0) {
      r.value = orbit::add_seconds(now, (t[0] == '-' ? -1.0 : 1.0) * *amount * per);
      return r;
    }
  }
  if (const auto iso = orbit::parse_iso8601(t)) {
    r.value = iso;
    return r;
  }
  r.error = "expected ISO8601 UTC (YYYY-MM-DD or YYYY-MM-DDTHH:MM[:SS[.fff]][Z]), now, or now plus or minus an "
            "amount (+2h, -30m, +1d, +90s), found '" + std::string(text) + "'";
  return r;
}

Parsed<std::int64_t> parse_frequency_text(std::string_view text) {
  Parsed<std::int64_t> r;
  std::string t(text::trim(text));
  double scale = 0.0;  // 0: by the form of the number
  for (const auto& [unit, s] : {std::pair{"ghz", 1e9}, {"mhz", 1e6}, {"khz", 1e3}, {"hz", 1.0}}) {
    const std::string lower_t = text::lower(t);
    const std::size_t n = std::string_view(unit).size();
    if (lower_t.size() > n && lower_t.compare(lower_t.size() - n, n, unit) == 0) {
      scale = s;
      t = std::string(text::trim(std::string_view(t).substr(0, t.size() - n)));
      break;
    }
  }
  const bool digits_only = !t.empty() && t.find_first_not_of("0123456789") == std::string::npos;
  const bool decimal = !t.empty() && t.find_first_not_of("0123456789.") == std::string::npos &&
                       std::count(t.begin(), t.end(), '.') == 1 && t != ".";
  std::optional<double> hz;
  if (scale > 0.0 && (digits_only || decimal)) hz = *text::parse_double(t) * scale;
  else if (scale == 0.0 && digits_only) hz = *text::parse_double(t);
  // A decimal point without a unit: MHz, where no radio frequency in hertz has a fraction (a
  // number of hertz with a point, 437800000.5, stays ambiguous and is refused).
  else if (scale == 0.0 && decimal && *text::parse_double(t) < 1e6) hz = *text::parse_double(t) * 1e6;
  if (hz && *hz <= 1e12 && std::abs(*hz - std::round(*hz)) < 1e-3) {
    r.value = static_cast<std::int64_t>(std::llround(*hz));
    return r;
  }
  r.error = "expected a frequency: whole hertz (437800000), MHz with a decimal point (437.8), or a number with "
            "Hz, kHz, MHz or GHz, at most 1000 GHz, found '" + std::string(text) + "'";
  return r;
}

bool StoredStation::load() {
  if (tried_) return ok_;
  tried_ = true;
  const std::filesystem::path dir = dir_ ? *dir_ : store::default_state_directory();
  store::Model m;
  const store::StateFile file(dir);
  const store::LoadOutcome loaded = file.load(/*read_only=*/true);
  if (loaded.kind == store::LoadOutcome::Kind::loaded) {
    try {
      m = store::model_from_json(loaded.data);
    } catch (const std::exception& e) {
      error_ = "the state in " + dir.string() + " cannot be read (" + e.what() + "); give the values on the command line";
      return false;
    }
    source_ = "state " + dir.string();
  } else if (loaded.kind == store::LoadOutcome::Kind::fresh) {
    std::vector<std::string> notes;
    m = defaults_with_data(default_data_directory(), notes);
    source_ = "shipped data (no state in " + dir.string() + " yet)";
  } else {
    error_ = "the state in " + dir.string() + " cannot be read (" + loaded.reason + "); give the values on the command line";
    return false;
  }
  station_ = m.station.observer();
  model_ = std::make_shared<store::Model>(m);
  for (const auto& s : m.db.satellites) db_.push_back(s.elements);
  for (const int i : m.db.selected)
    if (i >= 0 && static_cast<std::size_t>(i) < db_.size()) list_.push_back(db_[static_cast<std::size_t>(i)]);
  if (list_.empty()) list_ = db_;
  ok_ = true;
  return true;
}

const store::Model* StoredStation::model() {
  if (!load()) return nullptr;
  return model_.get();
}

std::optional<orbit::Observer> StoredStation::station() {
  if (!load()) return std::nullopt;
  return station_;
}

std::optional<std::vector<orbit::Elements>> StoredStation::database() {
  if (!load()) return std::nullopt;
  return db_;
}

std::optional<std::vector<orbit::Elements>> StoredStation::tracking_list() {
  if (!load()) return std::nullopt;
  return list_;
}

std::optional<orbit::UtcTime> running_station_time(const std::optional<std::string>& state_dir) {
  const std::string dir = state_dir ? *state_dir : store::default_state_directory().string();
  bool not_running = false;
  const auto text = station_request(socket_for_state(dir), "next", "status", not_running, true);
  if (!text) return std::nullopt;
  std::string why;
  const nlohmann::json doc = json_limits::parse_bounded<nlohmann::json>(*text, why);
  if (!doc.is_object() || !doc.contains("time") || !doc["time"].is_string()) return std::nullopt;
  return orbit::parse_iso8601(doc["time"].get<std::string>());
}

orbit::UtcTime default_start(const std::optional<std::string>& state_dir, const char* command) {
  const orbit::UtcTime wall = std::chrono::time_point_cast<std::chrono::microseconds>(std::chrono::system_clock::now());
  const auto t = running_station_time(state_dir);
  // A station running on a clock of its own (--clock): its time, said (beyond a minute from the wall's).
  if (!t) return wall;
  if (std::chrono::abs(*t - wall) > std::chrono::minutes(1))
    std::fprintf(stderr, "trakbox %s: from the running station's clock, %s (give --start to choose)\n", command,
                 orbit::format_iso8601(*t, 0).c_str());
  return *t;
}

}  // namespace tb::app
