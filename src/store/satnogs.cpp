#include "store/satnogs.h"

#include "util/json_limits.h"

#include <map>
#include <optional>

#include <nlohmann/json.hpp>

#include "util/text.h"

#include "util/safe_text.h"

namespace tb::store {

using json = nlohmann::json;

namespace {

struct Transmitter {
  std::string description, type, mode;
  std::optional<radio::Hz> up_low, up_high, down_low, down_high;
  bool invert = false;
};

std::optional<radio::Hz> hz(const json& o, const char* key) {
  const auto it = o.find(key);
  if (it == o.end() || !it->is_number()) return std::nullopt;
  const double v = it->get<double>();
  if (!(v > 0 && v < 1e12)) return std::nullopt;
  return static_cast<radio::Hz>(v + 0.5);
}

std::string str(const json& o, const char* key) {
  const auto it = o.find(key);
  return it != o.end() && it->is_string() ? it->get<std::string>() : std::string();
}

radio::Hz centre(radio::Hz low, std::optional<radio::Hz> high) { return high && *high > low ? (low + *high) / 2 : low; }

radio::Mode mode_of(const std::string& satnogs_mode) {
  const std::string m = text::upper(satnogs_mode);
  if (m == "USB") return radio::Mode::usb;
  if (m == "LSB") return radio::Mode::lsb;
  if (m == "CW") return radio::Mode::cw;
  // FM voice, and the data modes heard through an FM receiver (AFSK, FSK, GFSK, GMSK ...).
  if (m.rfind("FM", 0) == 0 || m.find("FSK") != std::string::npos || m.find("GMSK") != std::string::npos ||
      m == "APRS")
    return radio::Mode::fm;
  return radio::Mode::usb;  // SSB, BPSK, LoRa...: USB is how a station listens to them
}

std::string mhz(radio::Hz h) { return radio::format_mhz(h); }

}  // namespace

SatnogsImport import_satnogs(Database& db, std::string_view json_text, bool replace) {
  SatnogsImport r;
  std::string why;
  const json list = json_limits::parse_bounded<json>(json_text, why);
  if (why.starts_with("nested")) {
    r.error = "not a SatNOGS transmitter list (JSON nested deeper than " + std::to_string(json_limits::kMaxDepth) +
              " levels)";
    return r;
  }
  if (list.is_discarded() || !list.is_array()) {
    r.error = "not a SatNOGS transmitter list (expected a JSON array of transmitters)";
    return r;
  }
  std::map<long long, std::vector<Transmitter>> active;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& o = list[i];
    if (!o.is_object() || !o.contains("norad_cat_id")) {
      r.error = "transmitter " + std::to_string(i + 1) + ": not a transmitter object (no norad_cat_id)";
      return r;
    }
    const json& n = o["norad_cat_id"];
    if (n.is_null()) continue;  // transmitters of objects without a catalog number yet
    if (!n.is_number_integer()) {
      r.error = "transmitter " + std::to_string(i + 1) + ": norad_cat_id is not a whole number";
      return r;
    }
    const bool alive = !o.contains("alive") || (o["alive"].is_boolean() && o["alive"].get<bool>());
    if (!alive || str(o, "status") != "active") continue;
    // The description is shown to the operator: printable UTF-8 whatever the download held, and
    // not a paragraph (util/safe_text.h; cut at 80 bytes, a cut character replaced).
    Transmitter t{text::safe_text(str(o, "description").substr(0, 80)), str(o, "type"), str(o, "mode"), hz(o, "uplink_low"), hz(o, "uplink_high"),
                  hz(o, "downlink_low"), hz(o, "downlink_high"),
                  o.contains("invert") && o["invert"].is_boolean() && o["invert"].get<bool>()};
    if (!t.down_low) continue;  // an uplink alone is nothing to listen to
    active[n.get<long long>()].push_back(std::move(t));
  }
  for (Satellite& sat : db.satellites) {
    const auto it = active.find(sat.elements.catalog_number);
    if (it == active.end()) {
      ++r.without_transmitter;
      continue;
    }
    if (!replace && (sat.radio.has_downlink() || sat.radio.has_uplink())) {
      r.kept.push_back(sat.name());
      continue;
    }
    const std::vector<Transmitter>& ts = it->second;
    const Transmitter* pick = &ts.front();
    for (const Transmitter& t : ts)
      if (t.up_low && t.type != "Transmitter") {
        pick = &t;
        break;
      }
    radio::SatelliteRadio radio = sat.radio;
    radio.downlink_hz = centre(*pick->down_low, pick->down_high);
    radio.downlink_offset_hz = 0;
    radio.uplink_hz = pick->up_low ? centre(*pick->up_low, pick->up_high) : 0;
    radio.uplink_offset_hz = 0;
    radio.alternate_uplinks_hz.clear();  // the list has one uplink per transmitter
    // A transponder needs all four edges to be followed (down_low every kept transmitter has);
    // without one it has no passbands, and its uplink is the low edge when it has one.
    const bool linear = pick->type == "Transponder" && pick->down_high && pick->up_low && pick->up_high;
    // The passband edges, for dial follow (radio/doppler.h); none for other transmitters.
    radio.downlink_low_hz = linear ? *pick->down_low : 0;
    radio.downlink_high_hz = linear ? *pick->down_high : 0;
    radio.uplink_low_hz = linear ? *pick->up_low : 0;
    radio.uplink_high_hz = linear ? *pick->up_high : 0;
    radio.inverting = linear && pick->invert;
    if (linear && !radio.has_passbands()) {  // edges the wrong way round: no transponder to follow
      radio.downlink_low_hz = radio.downlink_high_hz = radio.uplink_low_hz = radio.uplink_high_hz = 0;
      radio.inverting = false;
    }
    if (linear) {
      radio.downlink_mode = radio::Mode::usb;
      radio.uplink_mode = pick->invert ? radio::Mode::lsb : radio::Mode::usb;
    } else {
      radio.downlink_mode = mode_of(pick->mode);
      radio.uplink_mode = pick->up_low ? radio.downlink_mode : radio::Mode::none;
    }
    sat.radio = radio;
    std::string line = sat.name() + ": downlink " + mhz(radio.downlink_hz) + " " + radio::to_string(radio.downlink_mode);
    if (radio.has_uplink()) line += ", uplink " + mhz(radio.uplink_hz) + " " + radio::to_string(radio.uplink_mode);
    if (linear) line += pick->invert ? " (inverting transponder)" : " (transponder)";
    if (!pick->description.empty()) line += " (" + pick->description + ")";
    r.updated.push_back(line);
  }
  return r;
}

}  // namespace tb::store
