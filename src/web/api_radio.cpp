#include "web/api_radio.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "station/station.h"
#include "store/settings.h"
#include "util/text.h"

namespace tb::web {

namespace {

using json = nlohmann::json;

// The value as the client sent it, short enough to quote.
std::string shown(const json& v) {
  std::string s = v.dump(-1, ' ', true, json::error_handler_t::replace);
  if (s.size() > 30) s = s.substr(0, 30) + "...";
  return s;
}

// A whole number of Hz (1.0e8 counts; 12.5 does not).
std::optional<long long> whole_hz(const json& v) {
  if (v.is_number_integer()) return v.get<long long>();
  if (!v.is_number_float()) return std::nullopt;
  const double d = v.get<double>();
  if (!std::isfinite(d) || d != std::floor(d) || std::abs(d) > 1e13) return std::nullopt;
  return static_cast<long long>(d);
}

}  // namespace

namespace {

// {"horizon_mask":TEXT} (issue 57), alone or with the rest of a station body: the mask is read first
// (a malformed one is the 400 with the reader's sentence), then the rest is done, then the mask
// stored; a refusal of either leaves the mask as it was.
std::optional<std::string> with_mask(tracker::StationOps& ops, double stored_height_m, const json& b,
                                     tracker::OpResult& done) {
  const json& v = b["horizon_mask"];
  if (!v.is_string())
    return "station: \"horizon_mask\" must be text: AZ EL pairs (one a line, or joined by ';'), a step list "
           "AZ EL ... AZ, or \"none\"; not " + shown(v);
  const station::MaskEntry entry = station::read_mask_entry(v.get<std::string>());
  if (!entry.text) return "station: " + entry.error;
  if (auto why = store::refusal(*store::find_setting("station.horizon_mask"), json(*entry.text))) {
    done = tracker::OpResult::refuse(*why);  // more than the state keeps
    return std::nullopt;
  }
  json rest = b;
  rest.erase("horizon_mask");
  tracker::OpResult before;
  if (!rest.empty())
    if (auto bad = station_request(ops, stored_height_m, rest, before); bad || !before.ok()) {
      done = before;
      return bad;
    }
  done = ops.set_horizon_mask(*entry.text);
  if (done.ok() && !rest.empty()) {
    done.note = before.note + ", " + done.note;
    done.model_changed = done.model_changed || before.model_changed;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> radio_request(tracker::StationOps& ops, const json& b, tracker::OpResult& done) {
  const char* expected =
      "radio: expected {\"doppler\":true|false}, {\"spot_hz\":HZ}, {\"rx_offset_hz\":HZ,\"tx_offset_hz\":HZ} or "
      "{\"tone_hz\":HZ} or {\"mode\":\"FT4\"[,\"satellite\":\"RS-44\"]}";
  const bool offsets = b.contains("rx_offset_hz") || b.contains("tx_offset_hz");
  const bool mode = b.contains("mode");
  const int groups = b.contains("doppler") + b.contains("spot_hz") + offsets + b.contains("tone_hz") + mode;
  if (groups != 1 || b.size() > (offsets || mode ? 2u : 1u) || (mode && b.size() == 2 && !b.contains("satellite")))
    return expected;
  if (mode) {
    if (!b["mode"].is_string()) return "radio: \"mode\" must be the name of one of the satellite's modes, not " + shown(b["mode"]);
    const json sat = b.value("satellite", json(""));
    if (!sat.is_string()) return "radio: \"satellite\" must be a satellite's name, not " + shown(sat);
    done = ops.choose_mode(sat.get<std::string>(), b["mode"].get<std::string>());
  } else if (b.contains("doppler")) {
    if (!b["doppler"].is_boolean()) return "radio: \"doppler\" must be true or false, not " + shown(b["doppler"]);
    done = ops.doppler(b["doppler"].get<bool>());
  } else if (b.contains("spot_hz")) {
    const auto hz = whole_hz(b["spot_hz"]);
    if (!hz) return "radio: \"spot_hz\" must be a whole number of Hz, e.g. 435640000, not " + shown(b["spot_hz"]);
    done = ops.tune_spot(*hz);
  } else if (offsets) {
    std::optional<long long> rx, tx;
    for (const char* key : {"rx_offset_hz", "tx_offset_hz"}) {
      if (!b.contains(key)) continue;
      const auto hz = whole_hz(b[key]);
      if (!hz) return std::string("radio: \"") + key + "\" must be a whole number of Hz, e.g. -250, not " + shown(b[key]);
      (key[0] == 'r' ? rx : tx) = *hz;
    }
    done = ops.tune_offsets(rx, tx);
  } else {
    if (!b["tone_hz"].is_number())
      return "radio: \"tone_hz\" must be a number of Hz, e.g. 67.0 (0 for none), not " + shown(b["tone_hz"]);
    done = ops.tune_tone(b["tone_hz"].get<double>());
  }
  return std::nullopt;
}

std::optional<std::string> station_request(tracker::StationOps& ops, double stored_height_m, const json& b,
                                           tracker::OpResult& done) {
  const char* expected = "station: expected {\"locator\":\"JN58td\"} or {\"lat_deg\":N,\"lon_deg\":E,\"height_m\":M}, "
                         "and or else {\"callsign\":\"W1AW\"}, {\"horizon_mask\":\"AZ EL; AZ EL ...\"|\"none\"}";
  if (b.contains("horizon_mask")) return with_mask(ops, stored_height_m, b, done);
  if (b.contains("callsign") && !b["callsign"].is_string())
    return "station: \"callsign\" must be text such as \"W1AW\", not " + shown(b["callsign"]);
  const bool places = b.contains("locator") || b.contains("lat_deg") || b.contains("lon_deg") || b.contains("height_m");
  if (b.contains("callsign") && !places) {
    done = ops.set_callsign(b["callsign"].get<std::string>());
    return std::nullopt;
  }
  if (b.contains("callsign")) {
    // Both: the callsign checked first by its setting's rule, so that a refused one changes nothing;
    // then the place; the callsign stored once the place was taken.
    const std::string call_text = text::upper(b["callsign"].get<std::string>());
    if (auto why = store::refusal(*store::find_setting("station.callsign"), json(call_text))) {
      done = tracker::OpResult::refuse(*why);
      return std::nullopt;
    }
    json place = b;
    place.erase("callsign");
    if (auto bad = station_request(ops, stored_height_m, place, done); bad || !done.ok()) return bad;
    const tracker::OpResult call = ops.set_callsign(b["callsign"].get<std::string>());
    if (!call.ok()) {
      done = call;
      return std::nullopt;
    }
    done.note += ", " + call.note;
    done.model_changed = done.model_changed || call.model_changed;
    return std::nullopt;
  }
  double height = stored_height_m;
  if (b.contains("height_m")) {
    if (!b["height_m"].is_number()) return "station: \"height_m\" must be metres, not " + shown(b["height_m"]);
    height = b["height_m"].get<double>();
  }
  if (b.contains("locator")) {
    if (!b["locator"].is_string()) return "station: \"locator\" must be a Maidenhead locator such as \"JN58td\"";
    const auto o = station::maidenhead_centre(b["locator"].get<std::string>());
    if (!o) return "station: '" + shown(b["locator"]) + "' is not a Maidenhead locator of 4, 6 or 8 characters (JN58td)";
    done = ops.set_station(o->lat_deg, o->lon_deg, b.contains("height_m") ? height : 0.0);
    return std::nullopt;
  }
  if (!b.contains("lat_deg") || !b.contains("lon_deg") || !b["lat_deg"].is_number() || !b["lon_deg"].is_number())
    return expected;
  done = ops.set_station(b["lat_deg"].get<double>(), b["lon_deg"].get<double>(), height);
  return std::nullopt;
}

}  // namespace tb::web
