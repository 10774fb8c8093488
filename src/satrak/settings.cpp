#include "satrak/settings.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "rotator/config.h"
#include "rotator/satrak/commands.h"
#include "store/json_fields.h"

#include "util/safe_text.h"

namespace tb::satrak {
using nlohmann::json;

namespace {

using store::json_fields::bad;
using store::json_fields::boolean;
using store::json_fields::field;
using store::json_fields::integer;
using store::json_fields::num;
using store::json_fields::path;

// A string the Satrak frame can carry back: no control characters and none of its separators.
std::string text(const json& j, const std::string& where, const char* key, std::size_t max_len) {
  std::string s = store::json_fields::text(j, where, key, max_len);
  if (!frame_text(s)) bad(path(where, key), "holds a control character, ',', '*' or '$'");
  return s;
}

std::string file_name(const json& j, const std::string& where, const char* key) {
  std::string s = text(j, where, key, limits::kNameMax);
  if (!s.empty() && !safe_file_name(s)) bad(path(where, key), "'" + s + "' is not a plain file name (no '/', no '..')");
  return s;
}

orbit::UtcTime time_of(const json& j, const std::string& where, const char* key) {
  const std::string s = text(j, where, key, 40);
  const auto t = orbit::parse_iso8601(s);
  if (!t) bad(path(where, key), "expected an ISO 8601 UTC time, found '" + s + "'");
  return *t;
}

// A text field that may be absent (state files written before it existed): "" then.
std::string optional_text(const json& j, const std::string& where, const char* key, std::size_t max_len) {
  if (!j.is_object() || !j.contains(key)) return {};
  return text(j, where, key, max_len);
}

// The plain fields, one row each: written by to_json and read by settings_from_json from the same
// table (key, member, the range the reader accepts).
struct BoolField {
  const char* key;
  bool Settings::*member;
};
struct IntField {
  const char* key;
  int Settings::*member;
  long long lo, hi;
};
struct NumField {
  const char* key;
  double Settings::*member;
  double lo, hi;
};
using namespace limits;
constexpr BoolField kBoolFields[] = {
    {"rtc_auto_update", &Settings::rtc_auto_update},
    {"auto_track", &Settings::auto_track},
    {"gps_auto", &Settings::gps_auto},
};
constexpr IntField kIntFields[] = {
    {"time_offset_ms", &Settings::time_offset_ms, -kTimeOffsetMs, kTimeOffsetMs},
    {"go_to_start_before_ms", &Settings::go_to_start_before_ms, 0, kGoToStartBeforeMs},
    {"position_base", &Settings::position_base, 0, 1},
    {"sspa_manual", &Settings::sspa_manual, 0, 2},
    {"sspa_auto_option", &Settings::sspa_auto_option, 0, 3},
};
constexpr NumField kNumFields[] = {
    {"az_offset_deg", &Settings::az_offset_deg, -kAzOffsetDeg, kAzOffsetDeg},
    {"el_offset_deg", &Settings::el_offset_deg, -kElOffsetDeg, kElOffsetDeg},
    {"min_elevation_deg", &Settings::min_elevation_deg, kMinElevationLo, kMinElevationHi},
    {"north_offset_deg", &Settings::north_offset_deg, -kNorthOffsetDeg, kNorthOffsetDeg},
    {"el_threshold_deg", &Settings::el_threshold_deg, kThresholdLo, kThresholdHi},
    {"tle_period_days", &Settings::tle_period_days, 0, kPeriodDays},
    {"reduction_x", &Settings::reduction_x, 1e-6, kReductionMax},
    {"reduction_y", &Settings::reduction_y, 1e-6, kReductionMax},
};

}  // namespace

double adc_from_sensor(double sensor_counts) {
  return sensor_counts * rotator::kAdcMaxCount / limits::kSensorMaxCount;
}

int sensor_from_adc(double adc_counts) {
  const double s = std::round(adc_counts * limits::kSensorMaxCount / rotator::kAdcMaxCount);
  return static_cast<int>(std::clamp(s, 0.0, static_cast<double>(limits::kSensorMaxCount)));
}

bool frame_text(std::string_view s) {
  for (unsigned char c : s)
    if (c < 0x20 || c == 0x7F || c == ',' || c == '*' || c == '$') return false;
  return text::is_safe_text(s);   // and printable UTF-8: no invalid bytes, no C1 controls (issue 38)
}

bool safe_file_name(std::string_view name) {
  if (name.empty() || name.size() > limits::kNameMax || !frame_text(name)) return false;
  if (name.front() == '.' || name.find("..") != std::string_view::npos) return false;
  return name.find_first_of("/\\") == std::string_view::npos;
}

json to_json(const Settings& s) {
  json j;
  for (const auto& f : kBoolFields) j[f.key] = s.*f.member;
  for (const auto& f : kIntFields) j[f.key] = s.*f.member;
  for (const auto& f : kNumFields) j[f.key] = s.*f.member;
  j["source"] = static_cast<int>(s.source);
  if (s.window) j["window"] = {{"start", orbit::format_iso8601(s.window->start)}, {"stop", orbit::format_iso8601(s.window->stop)}};
  else j["window"] = nullptr;
  j["tle_file"] = s.tle_file;
  j["satellite"] = s.satellite;
  j["http"] = {{"url", s.http.url}, {"period_days", s.http.period_days}, {"on_error", static_cast<int>(s.http.on_error)}};
  j["ftp"] = {{"host", s.ftp.host},           {"user", s.ftp.user},
              {"password", s.ftp.password},   {"port", s.ftp.port},
              {"file", s.ftp.file},           {"satellite", s.ftp.satellite},
              {"period_days", s.ftp.period_days}, {"on_error", static_cast<int>(s.ftp.on_error)}};
  j["gps_lat_text"] = s.gps_lat_text;
  j["gps_lon_text"] = s.gps_lon_text;
  // 16: the sensor references are the protocol's 16-bit counts. Files without the key (written
  // before) hold 10-bit ADC counts there.
  j["sensor_ref_bits"] = 16;
  j["az_sensor_ref"] = s.az_sensor_ref;
  j["el_sensor_ref"] = s.el_sensor_ref;
  j["az_angle_ref"] = s.az_angle_ref;
  j["el_angle_ref"] = s.el_angle_ref;
  return j;
}

Settings settings_from_json(const json& j, const std::string& w) {
  Settings s;
  for (const auto& f : kBoolFields) s.*f.member = boolean(j, w, f.key);
  for (const auto& f : kIntFields) s.*f.member = static_cast<int>(integer(j, w, f.key, f.lo, f.hi));
  for (const auto& f : kNumFields) s.*f.member = num(j, w, f.key, f.lo, f.hi);
  s.source = static_cast<TleSource>(integer(j, w, "source", 0, 2));
  const json& win = field(j, w, "window");
  if (!win.is_null()) {
    TrackWindow tw{time_of(win, w + ".window", "start"), time_of(win, w + ".window", "stop")};
    if (tw.stop <= tw.start) bad(w + ".window", "stop must be after start");
    s.window = tw;
  }
  s.tle_file = file_name(j, w, "tle_file");
  s.satellite = text(j, w, "satellite", kNameMax);
  {
    const std::string wh = w + ".http";
    const json& h = field(j, w, "http");
    s.http.url = text(h, wh, "url", kUrlMax);
    s.http.period_days = num(h, wh, "period_days", 0, kPeriodDays);
    s.http.on_error = static_cast<ErrorAction>(integer(h, wh, "on_error", 0, 1));
  }
  {
    const std::string wf = w + ".ftp";
    const json& f = field(j, w, "ftp");
    s.ftp.host = text(f, wf, "host", kUrlMax);
    s.ftp.user = text(f, wf, "user", kNameMax);
    s.ftp.password = text(f, wf, "password", kNameMax);
    s.ftp.port = static_cast<int>(integer(f, wf, "port", 1, 65535));
    s.ftp.file = file_name(f, wf, "file");
    s.ftp.satellite = text(f, wf, "satellite", kNameMax);
    s.ftp.period_days = num(f, wf, "period_days", 0, kPeriodDays);
    s.ftp.on_error = static_cast<ErrorAction>(integer(f, wf, "on_error", 0, 1));
  }
  s.gps_lat_text = optional_text(j, w, "gps_lat_text", 40);
  if (!s.gps_lat_text.empty() && !parse_latitude(s.gps_lat_text))
    bad(path(w, "gps_lat_text"), "expected a latitude like 41.02N, found '" + s.gps_lat_text + "'");
  s.gps_lon_text = optional_text(j, w, "gps_lon_text", 40);
  if (!s.gps_lon_text.empty() && !parse_longitude(s.gps_lon_text))
    bad(path(w, "gps_lon_text"), "expected a longitude like 29.17E, found '" + s.gps_lon_text + "'");
  if (j.contains("sensor_ref_bits")) {
    if (integer(j, w, "sensor_ref_bits", 16, 16) != 16) bad(path(w, "sensor_ref_bits"), "expected 16");
    s.az_sensor_ref = static_cast<int>(integer(j, w, "az_sensor_ref", 0, kSensorMaxCount));
    s.el_sensor_ref = static_cast<int>(integer(j, w, "el_sensor_ref", 0, kSensorMaxCount));
  } else {
    // Written before the references were 16-bit: 10-bit ADC counts, scaled up (the skews in the
    // Model, which are what point the antenna, are not touched).
    s.az_sensor_ref = sensor_from_adc(static_cast<double>(integer(j, w, "az_sensor_ref", -100000, 100000)));
    s.el_sensor_ref = sensor_from_adc(static_cast<double>(integer(j, w, "el_sensor_ref", -100000, 100000)));
  }
  auto angle = [&](const char* key, double lo, double hi) {
    std::string t = optional_text(j, w, key, 40);
    if (t.empty()) return t;
    const auto v = parse_number(t);
    if (!v || *v < lo || *v > hi)
      bad(path(w, key), "expected a number of degrees in " + format_fixed(lo, 0) + " .. " + format_fixed(hi, 0) +
                            ", found '" + t + "'");
    return t;
  };
  s.az_angle_ref = angle("az_angle_ref", -kAzAngleRefDeg, kAzAngleRefDeg);
  s.el_angle_ref = angle("el_angle_ref", kElAngleRefLo, kElAngleRefHi);
  return s;
}

}  // namespace tb::satrak
