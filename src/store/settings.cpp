#include "store/settings.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "gps/gpsd_client.h"
#include "radio/factory.h"
#include "orbit/horizon_mask.h"
#include "station/station.h"
#include "store/model.h"
#include "store/refresh.h"
#include "rotator/config.h"
#include "rotator/parking_mask.h"
#include "util/exact_number.h"
#include "util/safe_text.h"
#include "util/text.h"

namespace tb::store {
using nlohmann::json;

namespace {

using T = SettingType;

constexpr std::string_view kOnOff[] = {"on", "off"};  // shown for booleans; typed: on/off, yes/no, true/false
constexpr std::string_view kRotorStart[] = {"north", "south"};
constexpr std::string_view kDownlink[] = {"off", "on", "reverse"};
constexpr std::string_view kCatPolicy[] = {"full_orbit", "aos_only"};
constexpr std::string_view kExclusive[] = {"none", "rotctld", "rigctld", "satrak"};
constexpr std::string_view kBauds[] = {"1200", "2400", "4800", "9600", "19200"};
constexpr std::string_view kRecord[] = {"off", "audio", "iq"};
constexpr std::string_view kCatBauds[] = {"0", "1200", "2400", "4800", "9600", "19200"};

// One field of the model, read and written as the state document holds it.
#define TB_FIELD(expr, type)                                         \
  [](const Model& m) -> json { return m.expr; }, [](Model& m, const json& v) { m.expr = v.get<type>(); }

const std::array kTable = {
    Setting{"station.callsign", T::text, "", 0, 0, {}, 10, "", "4", "the station's callsign, as logged and shown",
            TB_FIELD(station.callsign, std::string)},
    Setting{"station.lat_deg", T::number, "deg", -90, 90, {}, 0, "--station", "4", "latitude, + north",
            TB_FIELD(station.lat_deg, double)},
    Setting{"station.lon_deg", T::number, "deg", -180, 180, {}, 0, "--station", "4", "longitude, + east",
            TB_FIELD(station.lon_deg, double)},
    Setting{"station.height_m", T::number, "m", -500, 9000, {}, 0, "--station", "4",
            "height above the WGS-84 ellipsoid", TB_FIELD(station.height_m, double)},
    Setting{"station.rotor_start", T::choice, "", 0, 0, kRotorStart, 0, "", "4",
            "where the azimuth rotator's end stop is",
            [](const Model& m) -> json { return m.station.rotor_start == station::RotorStart::north ? "north" : "south"; },
            [](Model& m, const json& v) {
              m.station.rotor_start = v.get<std::string>() == "north" ? station::RotorStart::north : station::RotorStart::south;
            }},
    Setting{"station.com_baud", T::integer, "bps", 1200, 19200, kBauds, 0, "", "4",
            "the serial line's speed for the menus", TB_FIELD(station.com_baud, int)},
    Setting{"station.horizon_mask", T::text, "", 0, 0, {}, 8000, "--horizon-mask", "4",
            "where the sky is hidden: AZ EL pairs joined by ';', or a step list AZ EL ... AZ (\"\": none)",
            [](const Model& m) -> json { return m.station.horizon_mask; },
            [](Model& m, const json& v) {
              const auto read = orbit::read_horizon_mask(v.get<std::string>());
              m.station.horizon_mask = read.mask ? read.mask->text() : "";
            }},
    Setting{"rotator.az_travel_deg", T::number, "deg", rotator::limits::kTravelMinDeg, rotator::limits::kTravelMaxDeg,
            {}, 0, "--az-travel", "6-1", "azimuth travel from the rotor stop (450 for an overlap rotator)",
            TB_FIELD(rotator.az_travel_deg, double)},
    Setting{"rotator.az_dead_band", T::integer, "counts", rotator::limits::kDeadBand.lo, rotator::limits::kDeadBand.hi,
            {}, 0, "", "6-3", "azimuth counts ignored when pointing", TB_FIELD(rotator.az_dead_band, int)},
    Setting{"rotator.el_dead_band", T::integer, "counts", rotator::limits::kDeadBand.lo, rotator::limits::kDeadBand.hi,
            {}, 0, "", "6-3", "elevation counts ignored when pointing", TB_FIELD(rotator.el_dead_band, int)},
    Setting{"rotator.az_skew", T::integer, "counts", rotator::limits::kSkew.lo, rotator::limits::kSkew.hi, {}, 0, "",
            "6-3", "counts added to the azimuth reading", TB_FIELD(rotator.az_skew, int)},
    Setting{"rotator.el_skew", T::integer, "counts", rotator::limits::kSkew.lo, rotator::limits::kSkew.hi, {}, 0, "",
            "6-3", "counts added to the elevation reading", TB_FIELD(rotator.el_skew, int)},
    Setting{"rotator.az_offset_deg", T::number, "deg", -rotator::limits::kSkyOffsetMaxDeg,
            rotator::limits::kSkyOffsetMaxDeg, {}, 0, "", "",
            "degrees added to the azimuth reading: the sky calibration (trakbox calibrate)",
            TB_FIELD(rotator.az_offset_deg, double)},
    Setting{"rotator.el_offset_deg", T::number, "deg", -rotator::limits::kSkyOffsetMaxDeg,
            rotator::limits::kSkyOffsetMaxDeg, {}, 0, "", "",
            "degrees added to the elevation reading: the sky calibration (trakbox calibrate)",
            TB_FIELD(rotator.el_offset_deg, double)},
    Setting{"rotator.parking_enabled", T::boolean, "", 0, 0, kOnOff, 0, "", "6-4",
            "the antenna parks after a pass and at the stop", TB_FIELD(rotator.parking_enabled, bool)},
    Setting{"rotator.limits_enabled", T::boolean, "", 0, 0, kOnOff, 0, "", "6-4",
            "the rotation limits below are in force", TB_FIELD(rotator.limits_enabled, bool)},
    Setting{"rotator.az_limit_min", T::number, "deg", -360, 720, {}, 0, "", "6-4",
            "the allowed azimuth sector's start (clockwise to the max)", TB_FIELD(rotator.az_limit_min, double)},
    Setting{"rotator.az_limit_max", T::number, "deg", -360, 720, {}, 0, "", "6-4", "the allowed azimuth sector's end",
            TB_FIELD(rotator.az_limit_max, double)},
    Setting{"rotator.el_limit_min", T::number, "deg", -90, 180, {}, 0, "", "6-4", "the lowest elevation allowed",
            TB_FIELD(rotator.el_limit_min, double)},
    Setting{"rotator.el_limit_max", T::number, "deg", -90, 180, {}, 0, "", "6-4", "the highest elevation allowed",
            TB_FIELD(rotator.el_limit_max, double)},
    Setting{"rotator.cross_limit_sector", T::boolean, "", 0, 0, kOnOff, 0, "--cross-limit-sector", "6-4",
            "limits that split the travel may be crossed between passes", TB_FIELD(rotator.cross_limit_sector, bool)},
    Setting{"rotator.el_flip_allowed", T::boolean, "", 0, 0, kOnOff, 0, "", "6-1",
            "the elevation goes over the top to 180 deg (flip)", TB_FIELD(rotator.el_flip_allowed, bool)},
    Setting{"rotator.az_rate_deg_s", T::number, "deg/s", 0.01, 100, {}, 0, "", "",
            "the azimuth motor's full-speed rate", TB_FIELD(rotator.az_rate_deg_s, double)},
    Setting{"rotator.el_rate_deg_s", T::number, "deg/s", 0.01, 100, {}, 0, "", "",
            "the elevation motor's full-speed rate", TB_FIELD(rotator.el_rate_deg_s, double)},
    Setting{"rotator.coast_s", T::number, "s", 0, 10, {}, 0, "", "", "the motors' spin-up and coast time constant",
            TB_FIELD(rotator.coast_s, double)},
    Setting{"rotator.stall_s", T::number, "s", 0.1, 600, {}, 0, "", "",
            "an axis driven this long without moving is stalled", TB_FIELD(rotator.stall_s, double)},
    Setting{"radio.uplink_correction", T::boolean, "", 0, 0, kOnOff, 0, "", "6-7", "Doppler on the uplink",
            TB_FIELD(radio.uplink_correction, bool)},
    Setting{"radio.downlink_correction", T::choice, "", 0, 0, kDownlink, 0, "", "6-7",
            "Doppler on the downlink (reverse: a high-side converter)",
            [](const Model& m) -> json { return kDownlink[static_cast<int>(m.radio.downlink_correction)]; },
            [](Model& m, const json& v) {
              const auto s = v.get<std::string>();
              m.radio.downlink_correction = s == "off"  ? radio::DownlinkCorrection::off
                                            : s == "on" ? radio::DownlinkCorrection::on
                                                        : radio::DownlinkCorrection::reverse;
            }},
    Setting{"radio.cat_policy", T::choice, "", 0, 0, kCatPolicy, 0, "", "6-7",
            "CAT commands the whole orbit or only while the satellite is up",
            [](const Model& m) -> json { return kCatPolicy[static_cast<int>(m.radio.cat_policy)]; },
            [](Model& m, const json& v) {
              m.radio.cat_policy =
                  v.get<std::string>() == "full_orbit" ? radio::CatPolicy::full_orbit : radio::CatPolicy::aos_only;
            }},
    Setting{"radio.cat_baud", T::integer, "bps", 0, 19200, kCatBauds, 0, "", "6-7",
            "the CAT port's speed (0: the rig's standard)", TB_FIELD(radio.cat_baud, int)},
    Setting{"radio.dial_follow", T::boolean, "", 0, 0, kOnOff, 0, "", "6-7",
            "a turn of the dial moves the spot on linear transponders", TB_FIELD(radio.dial_follow, bool)},
    Setting{"radio.dial_rest_ms", T::integer, "ms", 0, 10000, {}, 0, "--dial-rest", "6-7",
            "the knob rests this long before the other link follows", TB_FIELD(radio.dial_rest_ms, int)},
    Setting{"radio.doppler_step_ssb_hz", T::integer, "Hz", 10, 1000, {}, 0, "--doppler-step", "6-7",
            "SSB/CW Doppler updates this far apart", TB_FIELD(radio.doppler_step_ssb_hz, long long)},
    Setting{"radio.doppler_step_fm_hz", T::integer, "Hz", 10, 10000, {}, 0, "--doppler-step", "6-7",
            "FM Doppler updates this far apart", TB_FIELD(radio.doppler_step_fm_hz, long long)},
    Setting{"radio.uplink_radio", T::text, "", 0, 0, {}, 256, "--uplink-radio", "6-7",
            "a second radio for the uplink (\"\": one radio)", TB_FIELD(radio.uplink_radio, std::string)},
    Setting{"radio.record", T::choice, "", 0, 0, kRecord, 0, "--record", "",
            "the receiver records each pass of the satellite it is tuned to, AOS to LOS (GQRX, SDR++)",
            [](const Model& m) -> json { return radio::to_string(m.radio.record); },
            [](Model& m, const json& v) {
              const auto s = v.get<std::string>();
              m.radio.record = s == "audio" ? radio::Record::audio : s == "iq" ? radio::Record::iq : radio::Record::off;
            }},
    Setting{"radio.record_satellites", T::text, "", 0, 0, {}, 256, "--record-satellites", "",
            "the satellites recorded, comma-separated (\"\": every one)", TB_FIELD(radio.record_satellites, std::string)},
    Setting{"rotor_control", T::boolean, "", 0, 0, kOnOff, 0, "--rotor-control", "6-R",
            "the antenna follows what is tracked (the E key)", TB_FIELD(rotor_control, bool)},
    Setting{"priority_mode", T::boolean, "", 0, 0, kOnOff, 0, "", "M", "multiple tracking in priority order",
            TB_FIELD(priority_mode, bool)},
    Setting{"event_min_el_deg", T::number, "deg", -2, 90, {}, 0, "--event-min-el", "",
            "no AOS/LOS event for a pass whose maximum stays under this", TB_FIELD(event_min_el_deg, double)},
    Setting{"refresh.interval_hours", T::number, "h", kRefreshMinHours, kRefreshMaxHours, {}, 0,
            "--elements-refresh-hours", "3-5", "hours between element refreshes",
            TB_FIELD(refresh.interval_hours, double)},
    Setting{"pass_events.rotor_start_el_deg", T::number, "deg", -90, 90, {}, 0, "", "6-9",
            "the rotor starts following above this elevation", TB_FIELD(pass_events.rotor_start_el_deg, double)},
    Setting{"pass_events.output_on_el_deg", T::number, "deg", -90, 90, {}, 0, "", "6-9",
            "the AOS output line goes on above this", TB_FIELD(pass_events.output_on_el_deg, double)},
    Setting{"pass_events.output_off_el_deg", T::number, "deg", -90, 90, {}, 0, "", "6-9",
            "the AOS output line goes off below this", TB_FIELD(pass_events.output_off_el_deg, double)},
    Setting{"rotator_error_detection", T::boolean, "", 0, 0, kOnOff, 0, "", "6-9",
            "a stalled rotator is declared in error", TB_FIELD(rotator_error_detection, bool)},
    Setting{"drivers.rotator", T::text, "", 0, 0, {}, 256, "--rotator", "", "the rotator driven (\"\": simulated)",
            TB_FIELD(rotator_driver, std::string)},
    Setting{"drivers.radio", T::text, "", 0, 0, {}, 256, "--radio", "", "the radio driven (\"\": simulated)",
            TB_FIELD(radio_driver, std::string)},
    Setting{"gps.source", T::text, "", 0, 0, {}, 300, "--gps", "4", "the GPS receiver (gpsd:HOST:PORT; \"\": none)",
            TB_FIELD(gps.source, std::string)},
    Setting{"gps.follow", T::boolean, "", 0, 0, kOnOff, 0, "--gps-follow", "4",
            "the station's position follows the receiver's fix", TB_FIELD(gps.follow, bool)},
    Setting{"gps.threshold_m", T::number, "m", station::kGpsThresholdMinM, station::kGpsThresholdMaxM, {}, 0,
            "--gps-threshold", "4", "the fix must move this far before the station follows",
            TB_FIELD(gps.threshold_m, double)},
    Setting{"sharing.handback_s", T::integer, "s", 0, 86400, {}, 0, "--handback", "",
            "an outside client silent this long hands back (0: at its disconnect)", TB_FIELD(sharing.handback_s, int)},
    Setting{"sharing.exclusive", T::choice, "", 0, 0, kExclusive, 0, "--exclusive", "",
            "while a client of this kind holds, others are refused",
            [](const Model& m) -> json { return m.sharing.exclusive.empty() ? "none" : m.sharing.exclusive; },
            [](Model& m, const json& v) {
              const auto s = v.get<std::string>();
              m.sharing.exclusive = s == "none" ? "" : s;
            }},
    Setting{"sharing.standby", T::boolean, "", 0, 0, kOnOff, 0, "", "",
            "standby: nothing moves by itself (trakbox standby)", TB_FIELD(sharing.standby, bool)},
    Setting{"sharing.satnogs_station", T::integer, "", 0, 1000000000, {}, 0, "--satnogs-station", "3-5",
            "the SatNOGS station sharing the antenna (0: none)", TB_FIELD(sharing.satnogs_station, int)},
    Setting{"sharing.satnogs_url", T::text, "", 0, 0, {}, 512, "--satnogs-url", "",
            "the SatNOGS Network read (\"\": the public one)", TB_FIELD(sharing.satnogs_url, std::string)},
    Setting{"logger.spec", T::text, "", 0, 0, {}, 1024, "--logger", "", "cloudlog:URL or wavelog:URL (\"\": none)",
            TB_FIELD(logger.spec, std::string)},
    Setting{"logger.key_file", T::text, "", 0, 0, {}, 4096, "--logger-key-file", "",
            "the file holding the logger's API key", TB_FIELD(logger.key_file, std::string)},
    Setting{"logger.station_id", T::integer, "", 0, 1000000000, {}, 0, "--logger-station-id", "",
            "the logger's station profile (0: not given)", TB_FIELD(logger.station_id, int)},
};
#undef TB_FIELD

// A number as written: whole numbers without an exponent (100000, not 1e+05), others exactly.
std::string number_text(double v) {
  if (std::isfinite(v) && v == std::floor(v) && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  return text::exact_number(v);
}

std::string with_unit(const Setting& s, const std::string& v) {
  return s.unit.empty() ? v : v + " " + std::string(s.unit);
}

std::string list(std::span<const std::string_view> words) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i)
    out += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + std::string(words[i]);
  return out;
}

// A text setting's own rule beyond its length, for the settings that name something.
std::optional<std::string> text_rule(const Setting& s, const std::string& v) {
  if (v.empty()) return std::nullopt;
  if (std::any_of(v.begin(), v.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }))
    return "control characters are not taken";
  const std::string_view k = s.key;
  if (k == "gps.source") {
    std::string why;
    if (!gps::parse_gps_spec(v, why)) return why;
  } else if (k == "radio.uplink_radio") {
    const auto spec = radio::parse_radio_spec(v, "uplink radio");
    if (!spec.spec) return spec.error;
  } else if (k == "station.horizon_mask") {
    if (auto r = orbit::read_horizon_mask(v); !r.mask) return r.error;
  } else if (k == "radio.record_satellites") {
    for (const std::string_view name : text::split(v, ','))
      if (text::trim(name).empty()) return "expected satellite names separated by commas (an empty name found)";
  } else if (k == "sharing.satnogs_url") {
    if (v.rfind("http://", 0) != 0 && v.rfind("https://", 0) != 0) return "expected an http:// or https:// URL";
  } else if (k == "logger.spec") {
    if (v.rfind("cloudlog:", 0) != 0 && v.rfind("wavelog:", 0) != 0) return "expected cloudlog:URL or wavelog:URL";
  }
  return std::nullopt;
}

}  // namespace

std::span<const Setting> settings() { return kTable; }

const Setting* find_setting(std::string_view key) {
  for (const Setting& s : kTable)
    if (s.key == key) return &s;
  return nullptr;
}

std::optional<std::string> refusal(const Setting& s, const json& v) {
  const std::string key(s.key);
  switch (s.type) {
    case T::number:
    case T::integer: {
      const bool whole = s.type == T::integer;
      if (!v.is_number() || (whole && !v.is_number_integer()))
        return key + ": " + (v.is_number() ? number_text(v.get<double>()) + " is not a whole number"
                                          : std::string(whole ? "expected a whole number" : "expected a number")) +
               " (" + range_text(s) + ")";
      const double d = v.get<double>();
      if (!std::isfinite(d) || d < s.lo || d > s.hi)
        return key + ": " + number_text(d) + " is outside " + range_text(s);
      if (!s.choices.empty()) {
        const std::string t = std::to_string(v.get<long long>());
        if (std::find(s.choices.begin(), s.choices.end(), t) == s.choices.end())
          return key + ": " + t + " is not one of " + list(s.choices);
      }
      return std::nullopt;
    }
    case T::boolean:
      if (!v.is_boolean()) return key + ": expected on or off (true or false)";
      return std::nullopt;
    case T::choice: {
      if (!v.is_string()) return key + ": expected one of " + list(s.choices);
      const std::string t = v.get<std::string>();
      if (std::find(s.choices.begin(), s.choices.end(), t) == s.choices.end())
        return key + ": '" + text::visible_bytes(t.substr(0, 40)) + "' is not one of " + list(s.choices);
      return std::nullopt;
    }
    case T::text: {
      if (!v.is_string()) return key + ": expected text";
      const std::string t = v.get<std::string>();
      if (t.size() > s.max_len) return key + ": longer than " + std::to_string(s.max_len) + " characters";
      if (const auto why = text_rule(s, t)) {
        const std::string shown_value = text::visible_bytes(t.substr(0, 60));
        // Some rules quote the value themselves ("...; found 'nmea:/dev/ttyUSB0'").
        return key + ": " + (why->find(shown_value) != std::string::npos ? "" : "'" + shown_value + "': ") + *why;
      }
      return std::nullopt;
    }
  }
  return std::nullopt;
}

std::string range_text(const Setting& s) {
  switch (s.type) {
    case T::number:
    case T::integer:
      if (!s.choices.empty()) return list(s.choices) + (s.unit.empty() ? "" : " " + std::string(s.unit));
      return with_unit(s, number_text(s.lo) + " .. " + number_text(s.hi));
    case T::boolean: return "on or off";
    case T::choice: return list(s.choices);
    case T::text: return "text, at most " + std::to_string(s.max_len) + " characters";
  }
  return "";
}

std::string shown(const Setting& s, const json& v) {
  switch (s.type) {
    case T::number: return with_unit(s, number_text(v.get<double>()));
    case T::integer: return with_unit(s, std::to_string(v.get<long long>()));
    case T::boolean: return v.get<bool>() ? "on" : "off";
    case T::choice: return v.get<std::string>();
    case T::text: {
      const std::string t = v.get<std::string>();
      return t.empty() ? "\"\"" : t;
    }
  }
  return "";
}

ParsedSetting parse_setting(const Setting& s, std::string_view typed) {
  ParsedSetting r;
  const std::string t(text::trim(typed));
  json v;
  switch (s.type) {
    case T::number: {
      const auto d = text::parse_double(t);
      if (!d) {
        r.error = std::string(s.key) + ": '" + text::visible_bytes(t.substr(0, 40)) + "' is not a number (" +
                  range_text(s) + ")";
        return r;
      }
      v = *d;
      break;
    }
    case T::integer: {
      const auto d = text::parse_double(t);
      if (d && std::isfinite(*d) && *d == std::floor(*d) && std::abs(*d) < 9e15) v = static_cast<long long>(*d);
      else if (d) v = *d;  // refused below as not whole
      else {
        r.error = std::string(s.key) + ": '" + text::visible_bytes(t.substr(0, 40)) + "' is not a whole number (" +
                  range_text(s) + ")";
        return r;
      }
      break;
    }
    case T::boolean: {
      const std::string l = text::lower(t);
      if (l == "on" || l == "yes" || l == "true" || l == "1") v = true;
      else if (l == "off" || l == "no" || l == "false" || l == "0") v = false;
      else {
        r.error = std::string(s.key) + ": '" + text::visible_bytes(t.substr(0, 40)) + "': expected on or off";
        return r;
      }
      break;
    }
    case T::choice: v = text::lower(t); break;
    case T::text: v = (t == "\"\"" || t == "none") ? std::string() : t; break;
  }
  if (auto why = refusal(s, v)) {
    r.error = std::move(*why);
    return r;
  }
  r.value = std::move(v);
  return r;
}

std::optional<std::string> setting_warning(std::string_view key, const Model& m) {
  if (key != "station.horizon_mask" && key != "rotator.parking_enabled" && key != "rotator.el_flip_allowed")
    return std::nullopt;
  return rotator::parking_mask_warning(m.rotator, m.station.mask().get());
}

json read_setting(const json& object, std::string_view key) {
  const Setting* s = find_setting(key);
  if (!s) throw std::logic_error("read_setting: no setting " + std::string(key));
  const std::string leaf(key.substr(key.rfind('.') == std::string_view::npos ? 0 : key.rfind('.') + 1));
  if (!object.is_object()) throw std::runtime_error(std::string(key.substr(0, key.size() - leaf.size() - 1)) + ": expected an object");
  const auto it = object.find(leaf);
  if (it == object.end()) throw std::runtime_error(std::string(key) + ": missing");
  if (auto why = refusal(*s, *it)) throw std::runtime_error(*why);
  return *it;
}

json settings_document(const Model& m, const std::function<std::string(std::string_view)>& from) {
  const Model defaults = factory_defaults();
  json list = json::array();
  for (const Setting& s : kTable) {
    const json v = s.get(m);
    static constexpr const char* kTypes[] = {"number", "integer", "boolean", "choice", "text"};
    json e{{"key", s.key},
           {"value", v},
           {"shown", shown(s, v)},
           {"type", kTypes[static_cast<int>(s.type)]},
           {"range", range_text(s)},
           {"default", s.get(defaults)},
           {"from", from(s.key)},
           {"help", s.help}};
    if (!s.unit.empty()) e["unit"] = s.unit;
    if (!s.option.empty()) e["option"] = s.option;
    if (!s.menu.empty()) e["menu"] = s.menu;
    list.push_back(std::move(e));
  }
  return json{{"settings", std::move(list)}};
}

std::string settings_text(const json& document) {
  std::string out;
  for (const json& e : document.at("settings")) {
    std::string where = e.value("option", "");
    if (e.contains("menu")) where += (where.empty() ? "menu " : ", menu ") + e["menu"].get<std::string>();
    out += fmt::format("{:<32} {:<18} {:<13} {}{}\n", e["key"].get<std::string>(), e["shown"].get<std::string>(),
                       e["from"].get<std::string>(), e["range"].get<std::string>(),
                       where.empty() ? "" : "  (" + where + ")");
  }
  return out;
}

ParsedPosition parse_position(std::string_view typed) {
  const std::string expected =
      "LAT,LON[,HEIGHT_M] in degrees (+ north, + east, or 48.85N,2.35E; W and S for west and south) "
      "or a Maidenhead locator (JN18du[,HEIGHT_M])";
  ParsedPosition r;
  auto fail = [&](const std::string& why) {
    r.error = why.empty() ? "expected " + expected + ", found '" + std::string(typed) + "'"
                          : why + " in '" + std::string(typed) + "'; expected " + expected;
    return r;
  };
  std::string why;
  auto in_range = [&why](const char* key, double v) {
    if (auto no = refusal(*find_setting(key), json(v))) why = std::move(*no);
    return why.empty();
  };
  auto height = [&](std::string_view item) -> bool {
    const auto h = text::parse_double(text::trim(item));
    if (!h) why = "the height is not a number of metres";
    else if (in_range("station.height_m", *h)) r.height_m = *h;
    return why.empty();
  };
  const std::vector<std::string_view> items = text::split(typed, ',');
  if (!items.empty()) {
    if (const auto centre = station::maidenhead_centre(text::trim(items[0]))) {
      if (items.size() > 2) return fail("");
      r.lat_deg = centre->lat_deg;
      r.lon_deg = centre->lon_deg;
      r.height_m = 0.0;
      if (items.size() == 2 && !height(items[1])) return fail(why);
      return r;
    }
  }
  if (items.size() < 2 || items.size() > 3) return fail("");
  auto letter = [](std::string_view item, char pos, char neg) {
    const std::string_view t = text::trim(item);
    return !t.empty() && (text::to_upper(t.back()) == pos || text::to_upper(t.back()) == neg);
  };
  const auto lat = station::parse_hemisphere_degrees(text::trim(items[0]), 'N', 'S');
  const auto lon = station::parse_hemisphere_degrees(text::trim(items[1]), 'E', 'W');
  if (!lat) return fail("the latitude is not a number of degrees (N or S may follow)");
  if (!lon) return fail("the longitude is not a number of degrees (E or W may follow)");
  if (!in_range("station.lat_deg", *lat)) return fail(why);
  // East longitudes past 180 (0..360, as some programs write them) are the same place west.
  const double east = !letter(items[1], 'E', 'W') && *lon > 180.0 && *lon <= 360.0 ? *lon - 360.0 : *lon;
  if (!in_range("station.lon_deg", east)) return fail(why);
  r.lat_deg = *lat;
  r.lon_deg = east;
  if (items.size() == 3 && !height(items[2])) return fail(why);
  return r;
}

Bounds bounds(std::string_view key) {
  const Setting* s = find_setting(key);
  if (!s || (s->type != T::number && s->type != T::integer))
    throw std::logic_error("bounds: no number setting " + std::string(key));
  return {s->lo, s->hi};
}

}  // namespace tb::store
