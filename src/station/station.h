// Station elements (menu 4): who and where the station is, and how its azimuth rotator is built.
#pragma once
#include <optional>
#include <string>

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

  orbit::Observer observer() const { return {lat_deg, lon_deg, height_m}; }
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

}  // namespace tb::station
