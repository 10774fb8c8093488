// What the non-interactive commands take when the command line does not say (issue 30, "a command
// line that knows the station"): the station, database and tracking list stored by the menus, the
// time now, and the forms of station, time and frequency an operator types.
//
//   station    LAT,LON[,HEIGHT_M]  degrees (+ north, + east) or with N/S/E/W after the number
//              (48.85N,2.35E), blanks after the commas allowed; or a Maidenhead locator of 4, 6 or
//              8 characters, its centre (JN18du, JN18du,35); the height is 0 m when not given
//   time       ISO 8601 UTC, `now`, or now plus or minus an amount: +2h, +90m, -1d, +30s
//   frequency  a whole number of hertz (437800000), or MHz with a decimal point (437.8), or with a
//              unit (437.8MHz, 145800kHz, 2.4GHz, 437800000Hz)
#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "orbit/elements.h"
#include "orbit/observe.h"
#include "orbit/time.h"
#include "store/model.h"

namespace tb::app {

// A parsed value or why it is refused (a sentence naming what is expected).
template <class T>
struct Parsed {
  std::optional<T> value;
  std::string error;
};

Parsed<orbit::Observer> parse_station_text(std::string_view text);
// The centre of a Maidenhead locator ("JN18du": 48.854167 N, 2.291667 E), height 0.
std::optional<orbit::Observer> maidenhead_centre(std::string_view locator);
Parsed<orbit::UtcTime> parse_time_text(std::string_view text, orbit::UtcTime now);
// The time of a station running on the state directory (--state, else the default), asked quietly
// through its socket; nothing when none runs. A station started with --clock lives at its own time.
std::optional<orbit::UtcTime> running_station_time(const std::optional<std::string>& state_dir);
// The default --start of next, passes and schedule: the running station's time (said on stderr when
// it is not the wall's), else now (issue 60: they used the system clock beside a --clock station).
orbit::UtcTime default_start(const std::optional<std::string>& state_dir, const char* command);

Parsed<std::int64_t> parse_frequency_text(std::string_view text);

// The station, database and tracking list of a state directory (--state, else the default the
// menus use), or of the shipped data when that directory holds no state yet. Loaded once, on first
// use, so that a command given everything never reads the state.
class StoredStation {
 public:
  explicit StoredStation(std::optional<std::filesystem::path> state_dir) : dir_(std::move(state_dir)) {}
  // Each returns nothing and sets error() when the state cannot be read.
  std::optional<orbit::Observer> station();
  // The database's sets, and the tracking list's (in its order; the database's when empty).
  std::optional<std::vector<orbit::Elements>> database();
  std::optional<std::vector<orbit::Elements>> tracking_list();
  // "state /var/lib/trakbox" or "shipped data (no state in DIR yet)": where the values came from.
  // The whole stored model (the rotator's settings for the pass plots' antenna plan).
  const store::Model* model();
  const std::string& source() const { return source_; }
  const std::string& error() const { return error_; }

 private:
  bool load();
  std::optional<std::filesystem::path> dir_;
  bool tried_ = false, ok_ = false;
  orbit::Observer station_;
  std::shared_ptr<store::Model> model_;
  std::vector<orbit::Elements> db_, list_;
  std::string source_, error_;
};

}  // namespace tb::app
