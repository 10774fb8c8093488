// What the Satrak protocol sets that trakbox's Model has no place for. One value, persisted by the
// program beside the Model in the state document (data["satrak"]), validated field by field like
// the Model: settings_from_json throws std::runtime_error naming the field ("satrak.north_offset_deg:
// value 400 outside -360 .. 360").
//
// What each setting does is in docs/satrak.md, "Settings and their effects".
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "orbit/time.h"

namespace tb::satrak {

// Where the element set comes from (SETTINGS? X11).
enum class TleSource : int { file = 0, web = 1, ftp = 2 };

// Update error action of SATELLITE_HTTP / SATELLITE_FTP.
enum class ErrorAction : int { stop_tracking = 0, continue_last_data = 1 };

struct TrackWindow {
  orbit::UtcTime start{};
  orbit::UtcTime stop{};
  friend bool operator==(const TrackWindow&, const TrackWindow&) = default;
};

struct HttpSource {
  std::string url;                // http:// or https://
  double period_days = 1.0;       // download again after this long (0: only when set)
  ErrorAction on_error = ErrorAction::continue_last_data;
  friend bool operator==(const HttpSource&, const HttpSource&) = default;
};

struct FtpSource {
  std::string host;               // IP address or host name; or a whole ftp://, ftps://, sftp:// URL
  std::string user;
  std::string password;           // kept in the state document; SATELLITE_FTP? shows it masked
  int port = 21;
  std::string file;               // remote file name; also the local name in the TLE directory
  std::string satellite;          // satellite name in that file
  double period_days = 1.0;
  ErrorAction on_error = ErrorAction::continue_last_data;
  friend bool operator==(const FtpSource&, const FtpSource&) = default;
};

struct Settings {
  // SETTINGS X1..X12 (X11, the TLE source, is `source` below).
  bool rtc_auto_update = false;     // X1: kept and reported (no GPS receiver here)
  int time_offset_ms = 0;           // X2: tracking points where the satellite is at now + this
  double az_offset_deg = 0.0;       // X3: added to the satellite's azimuth while tracking
  double el_offset_deg = 0.0;       // X4: added to its elevation while tracking
  int go_to_start_before_ms = 0;    // X5: pre-positioning this long before the track starts
  int position_base = 0;            // X6: 0 resolver+encoder, 1 resolver: kept and reported
  double min_elevation_deg = 0.0;   // X7: the lowest elevation the Satrak interface commands
  double north_offset_deg = 0.0;    // X8: true azimuth = axis angle X + north offset
  int sspa_manual = 0;              // X9: 0 off, 1 on, 2 auto
  int sspa_auto_option = 0;         // X10: 0 tracking, 1 carrier lock, 2 both, 3 either
  TleSource source = TleSource::file;  // X11
  double el_threshold_deg = 0.0;    // X12: the satellite is followed at or above this elevation

  // START_STOP_TIME and TRACK_AUTO_ENABLE.
  std::optional<TrackWindow> window;
  bool auto_track = false;

  // SATELLITE=: file in the TLE directory, satellite name in it, update period in days.
  std::string tle_file;
  std::string satellite;
  double tle_period_days = 0.0;     // the file counts as out of date when older (0: never)

  HttpSource http;
  FtpSource ftp;

  // GPS_SETTINGS X1 (the position itself is the station's, in the Model).
  bool gps_auto = false;
  // GPS_SETTINGS X2/X3 as they were written ("41.02N", "-33.9"; "" when none was). GPS_SETTINGS?
  // answers them while they still name the station's position (menu 4 may have changed it since).
  std::string gps_lat_text;
  std::string gps_lon_text;

  // ANGLE_SETTINGS: the sensor counts the angle references are given for, in the protocol's 16-bit
  // sensor range (0..65535; the document's example is 39049), scaled to the 10-bit ADC when the
  // skew is computed (adc_from_sensor).
  int az_sensor_ref = 0;
  int el_sensor_ref = 0;
  // The angle references as they were given ("160.0"; "" when none was). ANGLE_SETTINGS? answers
  // them while the skew in force still makes the sensor reference read them.
  std::string az_angle_ref;
  std::string el_angle_ref;

  // REDUCTION: gear reduction per axis, kept and reported.
  double reduction_x = 1.0;
  double reduction_y = 1.0;

  friend bool operator==(const Settings&, const Settings&) = default;
};

// Allowed ranges, shared by the protocol and the JSON reader.
namespace limits {
inline constexpr int kTimeOffsetMs = 600'000;          // +-10 minutes
inline constexpr double kAzOffsetDeg = 180.0;
inline constexpr double kElOffsetDeg = 90.0;
inline constexpr int kGoToStartBeforeMs = 3'600'000;   // one hour
inline constexpr double kMinElevationLo = -10.0, kMinElevationHi = 90.0;
inline constexpr double kNorthOffsetDeg = 360.0;
inline constexpr double kThresholdLo = -10.0, kThresholdHi = 90.0;
inline constexpr double kPeriodDays = 365.0;
inline constexpr double kReductionMax = 1e6;
inline constexpr std::size_t kNameMax = 128;           // file, satellite, user, password
inline constexpr std::size_t kUrlMax = 400;
inline constexpr int kSensorMaxCount = 65535;          // ANGLE_SETTINGS sensor counts: 16 bits
inline constexpr double kAzAngleRefDeg = 360.0;        // ANGLE_SETTINGS X angle: -360 .. 360
inline constexpr double kElAngleRefLo = -90.0, kElAngleRefHi = 180.0;
}  // namespace limits

// ANGLE_SETTINGS' 16-bit sensor counts <-> the 10-bit ADC counts of trakbox's rotator interface,
// full scale to full scale (0 -> 0, 65535 -> 1023). sensor_from_adc rounds and clamps.
double adc_from_sensor(double sensor_counts);
int sensor_from_adc(double adc_counts);

nlohmann::json to_json(const Settings& s);
// Throws std::runtime_error naming the field when anything is missing, of the wrong type or out of
// range. `where` prefixes the field names.
Settings settings_from_json(const nlohmann::json& j, const std::string& where = "satrak");

// Text a reply frame can carry back as one field: printable UTF-8 (util/safe_text.h: no invalid
// bytes, no control characters, C1 included), no `,` (the field separator), `*` (the checksum
// mark) or `$` (the frame start). Every text setting the unit takes
// is checked with this before it is stored, and the state file's reader checks the same, so what
// the unit stores always reads back.
bool frame_text(std::string_view s);

// A file name the TLE or image directory may hold: not empty, at most 128 bytes, frame_text, no
// `/`, no `\`, not `.` or `..` (nor containing `..`), not starting with `.`.
bool safe_file_name(std::string_view name);

}  // namespace tb::satrak
