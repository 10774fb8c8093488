// Station elements (menu 4): who and where the station is, and how its azimuth rotator is built.
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "orbit/horizon_mask.h"
#include "orbit/observe.h"

namespace tb::station {

// "Rotor start" is where the azimuth rotator's end stop is: North (0..360 degrees of travel from
// north through east) or South (180 through 360 to 180, the stop in the south).
enum class RotorStart { north, south };

struct StationConfig {
  // The manual's menu-4 example shows these factory values.
  std::string callsign = "NOCALL";
  double lat_deg = 27.391;     // + north
  double lon_deg = 128.657;    // + east
  double height_m = 50.0;      // above sea level (taken as above the WGS-84 ellipsoid)
  RotorStart rotor_start = RotorStart::south;
  int com_baud = 9600;         // 1200, 2400, 4800, 9600 (the manual), up to 19200 here
  // The horizon mask (issue 57; --horizon-mask FILE): HorizonMask::text()'s one line, "" for none.
  std::string horizon_mask;

  orbit::Observer observer() const { return {lat_deg, lon_deg, height_m}; }
  // The mask to search passes with (PassOptions::mask), nothing when there is none.
  std::shared_ptr<const orbit::HorizonMask> mask() const { return orbit::shared_horizon_mask(horizon_mask); }
  friend bool operator==(const StationConfig&, const StationConfig&) = default;
};

// The GPS receiver (--gps, menus 4 and 5, Satrak GPS_SETTINGS=) and where the station's position
// came from (docs/gps.md).
inline constexpr double kGpsThresholdMinM = 1.0, kGpsThresholdMaxM = 100000.0;
struct GpsSettings {
  std::string source;           // "gpsd:HOST:PORT"; "" none
  bool follow = false;          // the station's position follows the receiver's confirmed fix
  double threshold_m = 100.0;   // moving only when the fix is farther than this from it
  bool position_from_gps = false;            // the position was last set from the receiver
  std::optional<orbit::UtcTime> position_time;  // the GPS time of that fix
  friend bool operator==(const GpsSettings&, const GpsSettings&) = default;
};

const char* to_string(RotorStart r);  // "North" / "South"

// Degrees as an operator types them: "48.85", "-2.35", or with the hemisphere after the number,
// "48.85N", "2.35 W" (`pos` and `neg` are 'N','S' or 'E','W', either case). A letter and a sign
// together ("-48.85N") are refused. Nothing when it is not one of these.
std::optional<double> parse_hemisphere_degrees(std::string_view text, char pos, char neg);
// The centre of a Maidenhead locator of 4, 6 or 8 characters, any case ("JN18du": 48.854167 N,
// 2.291667 E), height 0; nothing when the text is not one. Menu 4 and `--station` take them.
std::optional<orbit::Observer> maidenhead_centre(std::string_view locator);
// The 6-character locator of a position ("JN18du" for 48.8566 N, 2.3522 E): field and square upper
// case, subsquare lower case, as operators write it.
std::string maidenhead_locator(double lat_deg, double lon_deg);

// A horizon mask as an operator types it (menu 4, the page's Station card; issue 57): any form
// orbit::read_horizon_mask takes ("AZ EL; AZ EL ..." on one line, pairs per line, the step list
// AZ EL ... AZ), or "none" (any case) or nothing for no mask. `text` is what station.horizon_mask
// keeps (HorizonMask::text(), "" for none); otherwise `error` is the reader's sentence ("horizon
// mask pair 3: azimuth 400 is outside 0..360").
struct MaskEntry {
  std::optional<std::string> text;
  std::string error;
};
MaskEntry read_mask_entry(std::string_view typed);
// "none", or the mask's describe() ("interpolated, 6 points, 0.0..25.0 deg").
std::string describe_mask(const StationConfig& st);

}  // namespace tb::station
