#include "store/model.h"

#include <algorithm>
#include <iterator>
#include <tuple>

#include <nlohmann/json.hpp>

#include "gps/gpsd_client.h"
#include "radio/factory.h"
#include "orbit/time.h"
#include "store/json_fields.h"
#include "store/mode_import.h"
#include "store/settings.h"
#include "util/host_port.h"
#include "util/safe_text.h"
#include "util/text.h"

namespace tb::store {
using nlohmann::json;

namespace {

using json_fields::bad;
using json_fields::boolean;
using json_fields::field;
using json_fields::integer;
using json_fields::num;
using json_fields::path;
using json_fields::text;

// An enum stored by name.
template <typename E, std::size_t N>
E named(const json& j, const std::string& where, const char* key, const std::pair<E, const char*> (&names)[N]) {
  const std::string s = text(j, where, key, 32);
  for (const auto& [e, n] : names)
    if (s == n) return e;
  std::string choices;
  for (const auto& [e, n] : names) choices += (choices.empty() ? "" : ", ") + std::string(n);
  bad(path(where, key), "'" + s + "' is not one of " + choices);
}
template <typename E, std::size_t N>
const char* name_of(E e, const std::pair<E, const char*> (&names)[N]) {
  for (const auto& [v, n] : names)
    if (v == e) return n;
  return names[0].second;
}

constexpr std::pair<radio::Rig, const char*> kRig[] = {{radio::Rig::none, "none"},
                                                       {radio::Rig::kenwood, "kenwood"},
                                                       {radio::Rig::yaesu, "yaesu"},
                                                       {radio::Rig::icom, "icom"}};
constexpr std::pair<radio::PulsePolarity, const char*> kPolarity[] = {{radio::PulsePolarity::normal, "normal"},
                                                                      {radio::PulsePolarity::reverse, "reverse"}};
constexpr std::pair<radio::IcomBandSelect, const char*> kBand[] = {
    {radio::IcomBandSelect::none, "none"}, {radio::IcomBandSelect::main_tx_sub_rx, "main_tx_sub_rx"}};
constexpr std::pair<radio::Mode, const char*> kMode[] = {{radio::Mode::none, "none"}, {radio::Mode::fm, "fm"},
                                                         {radio::Mode::lsb, "lsb"},   {radio::Mode::usb, "usb"},
                                                         {radio::Mode::cw, "cw"}};
constexpr std::pair<radio::DopplerControl, const char*> kDoppler[] = {{radio::DopplerControl::cat, "cat"},
                                                                      {radio::DopplerControl::mic_click, "mic"}};
constexpr std::pair<orbit::ElementFormat, const char*> kFormat[] = {
    {orbit::ElementFormat::nasa, "nasa"},         {orbit::ElementFormat::amsat, "amsat"},
    {orbit::ElementFormat::omm_json, "omm_json"}, {orbit::ElementFormat::omm_xml, "omm_xml"},
    {orbit::ElementFormat::omm_csv, "omm_csv"},   {orbit::ElementFormat::omm_kvn, "omm_kvn"}};

constexpr long long kMaxHz = 1'000'000'000'000LL;  // 1 THz: beyond any radio

json azel(const rotator::AzEl& p) { return json::array({p.az, p.el}); }
rotator::AzEl azel_from(const json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number()) bad(where, "expected [az, el]");
  const double az = j[0].get<double>(), el = j[1].get<double>();
  if (!(az >= 0.0 && az <= 360.0) || !(el >= -90.0 && el <= 180.0)) bad(where, "position " + j.dump() + " out of range");
  return {az, el};
}

json elements_json(const orbit::Elements& e) {
  return {{"name", e.name},
          {"catalog", e.catalog_number},
          {"classification", std::string(1, e.classification)},
          {"designator", e.international_designator},
          {"epoch_year", e.epoch_year},
          {"epoch_day", e.epoch_day},
          {"ndot_over_2", e.ndot_over_2},
          {"nddot_over_6", e.nddot_over_6},
          {"bstar", e.bstar},
          {"ephemeris_type", e.ephemeris_type},
          {"element_set", e.element_set_number},
          {"inclination_deg", e.inclination_deg},
          {"raan_deg", e.raan_deg},
          {"eccentricity", e.eccentricity},
          {"arg_perigee_deg", e.arg_perigee_deg},
          {"mean_anomaly_deg", e.mean_anomaly_deg},
          {"mean_motion_rev_per_day", e.mean_motion_rev_per_day},
          {"revolution", e.revolution_number},
          {"source", name_of(e.source, kFormat)}};
}

orbit::Elements elements_from(const json& j, const std::string& w) {
  orbit::Elements e;
  e.name = ::tb::text::safe_text(text(j, w, "name", 64));  // printable UTF-8 on any terminal (issue 38)
  // Up to 9 digits: OMM numbers beyond Alpha-5's 339999 exist since 2026.
  e.catalog_number = static_cast<int>(integer(j, w, "catalog", 0, 999999999));
  const std::string cls = text(j, w, "classification", 1);
  e.classification = cls.empty() ? 'U' : cls[0];
  e.international_designator = text(j, w, "designator", 16);
  e.epoch_year = static_cast<int>(integer(j, w, "epoch_year", 1957, 2100));
  e.epoch_day = num(j, w, "epoch_day", 1.0, 367.0);
  e.ndot_over_2 = num(j, w, "ndot_over_2", -1.0, 1.0);
  e.nddot_over_6 = num(j, w, "nddot_over_6", -1.0, 1.0);
  e.bstar = num(j, w, "bstar", -1.0, 1.0);
  e.ephemeris_type = static_cast<int>(integer(j, w, "ephemeris_type", 0, 9));
  e.element_set_number = static_cast<int>(integer(j, w, "element_set", 0, 9999));
  e.inclination_deg = num(j, w, "inclination_deg", 0.0, 180.0);
  e.raan_deg = num(j, w, "raan_deg", 0.0, 360.0);
  e.eccentricity = num(j, w, "eccentricity", 0.0, 0.9999999);
  e.arg_perigee_deg = num(j, w, "arg_perigee_deg", 0.0, 360.0);
  e.mean_anomaly_deg = num(j, w, "mean_anomaly_deg", 0.0, 360.0);
  e.mean_motion_rev_per_day = num(j, w, "mean_motion_rev_per_day", 1e-6, 20.0);
  e.revolution_number = static_cast<long>(integer(j, w, "revolution", 0, 9999999));
  e.source = named(j, w, "source", kFormat);
  return e;
}

constexpr std::pair<radio::ReverseAssignment, const char*> kReverse[] = {
    {radio::ReverseAssignment::none, "none"},
    {radio::ReverseAssignment::icom_main_sub, "icom_main_sub"},
    {radio::ReverseAssignment::kenwood_vfo, "kenwood_vfo"}};
constexpr std::pair<radio::RigModel, const char*> kRigModel[] = {{radio::RigModel::generic, "generic"},
                                                                 {radio::RigModel::kenwood_711, "kenwood_711"},
                                                                 {radio::RigModel::yaesu_other, "yaesu_other"},
                                                                 {radio::RigModel::yaesu_847, "yaesu_847"},
                                                                 {radio::RigModel::yaesu_736, "yaesu_736"}};

json radio_entry_json(const radio::SatelliteRadio& r) {
  json j = {{"downlink_hz", r.downlink_hz},     {"downlink_offset_hz", r.downlink_offset_hz},
            {"uplink_hz", r.uplink_hz},         {"uplink_offset_hz", r.uplink_offset_hz},
            {"downlink_mode", name_of(r.downlink_mode, kMode)}, {"uplink_mode", name_of(r.uplink_mode, kMode)},
            {"doppler", name_of(r.doppler, kDoppler)},          {"lcd_ma_display", r.lcd_ma_display},
            {"alternate_uplinks_hz", r.alternate_uplinks_hz},   {"reverse", name_of(r.reverse, kReverse)}};
  // The transponder's passbands and the CTCSS tone: written only when set.
  if (r.downlink_low_hz || r.downlink_high_hz || r.uplink_low_hz || r.uplink_high_hz || r.inverting) {
    j["passbands_hz"] = {{"downlink", {r.downlink_low_hz, r.downlink_high_hz}},
                         {"uplink", {r.uplink_low_hz, r.uplink_high_hz}},
                         {"inverting", r.inverting}};
  }
  if (r.ctcss_tenths_hz > 0) j["ctcss_tenths_hz"] = r.ctcss_tenths_hz;
  return j;
}

// [low, high] in Hz, low <= high.
std::pair<radio::Hz, radio::Hz> band_from(const json& j, const std::string& w, const char* key) {
  const std::string wk = path(w, key);
  const json& b = field(j, w, key);
  if (!b.is_array() || b.size() != 2 || !b[0].is_number_integer() || !b[1].is_number_integer())
    bad(wk, "expected [low, high] in Hz");
  const long long lo = b[0].get<long long>(), hi = b[1].get<long long>();
  if (lo < 0 || hi > kMaxHz || lo > hi) bad(wk, "expected 0 <= low <= high <= " + std::to_string(kMaxHz));
  return {lo, hi};
}

radio::SatelliteRadio radio_entry_from(const json& j, const std::string& w) {
  radio::SatelliteRadio r;
  r.downlink_hz = integer(j, w, "downlink_hz", 0, kMaxHz);
  r.downlink_offset_hz = integer(j, w, "downlink_offset_hz", -kMaxHz, kMaxHz);
  r.uplink_hz = integer(j, w, "uplink_hz", 0, kMaxHz);
  r.uplink_offset_hz = integer(j, w, "uplink_offset_hz", -kMaxHz, kMaxHz);
  r.downlink_mode = named(j, w, "downlink_mode", kMode);
  r.uplink_mode = named(j, w, "uplink_mode", kMode);
  r.doppler = named(j, w, "doppler", kDoppler);
  r.lcd_ma_display = boolean(j, w, "lcd_ma_display");
  // The later firmware's FREQ.DAT fields: absent in state files written before them.
  if (j.contains("alternate_uplinks_hz")) {
    const json& a = j["alternate_uplinks_hz"];
    const std::string wa = path(w, "alternate_uplinks_hz");
    if (!a.is_array() || a.size() > static_cast<std::size_t>(radio::kMaxUplinkChannels - 1))
      bad(wa, "expected a list of up to " + std::to_string(radio::kMaxUplinkChannels - 1) + " frequencies");
    for (const auto& v : a) {
      if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > kMaxHz)
        bad(wa, "expected frequencies in Hz, 0 to " + std::to_string(kMaxHz));
      r.alternate_uplinks_hz.push_back(v.get<long long>());
    }
  }
  if (j.contains("reverse")) r.reverse = named(j, w, "reverse", kReverse);
  // Linear transponders and CTCSS: absent in state files written before them, and for most satellites.
  if (j.contains("passbands_hz")) {
    const std::string wp = path(w, "passbands_hz");
    const json& p = j["passbands_hz"];
    std::tie(r.downlink_low_hz, r.downlink_high_hz) = band_from(p, wp, "downlink");
    std::tie(r.uplink_low_hz, r.uplink_high_hz) = band_from(p, wp, "uplink");
    r.inverting = boolean(p, wp, "inverting");
  }
  if (j.contains("ctcss_tenths_hz")) r.ctcss_tenths_hz = static_cast<int>(integer(j, w, "ctcss_tenths_hz", 0, 3000));
  return r;
}

// {"downlink": {"from": "satnogs", "value": "435640000"[, "offer_from": ..., "offer_value": ...]}, ...}
json sources_json(const std::map<std::string, radio::FieldSource>& sources) {
  json j = json::object();
  for (const auto& [key, s] : sources) {
    json e = {{"from", s.from}, {"value", s.value}};
    if (!s.offer_from.empty()) e["offer_from"] = s.offer_from, e["offer_value"] = s.offer_value;
    j[key] = std::move(e);
  }
  return j;
}

std::map<std::string, radio::FieldSource> sources_from(const json& j, const std::string& w) {
  if (!j.is_object() || j.size() > static_cast<std::size_t>(ModeField::count))
    bad(w, "expected an object of fields and their sources");
  std::map<std::string, radio::FieldSource> out;
  for (const auto& [key, e] : j.items()) {
    bool known = false;
    for (unsigned i = 0; i < static_cast<unsigned>(ModeField::count); ++i)
      known = known || key == to_string(static_cast<ModeField>(i));
    const std::string wk = path(w, key.c_str());
    if (!known) bad(wk, "not a field of a mode (downlink, uplink, downlink_mode, uplink_mode, passbands, inverting, tone, arm)");
    if (!e.is_object()) bad(wk, "expected {\"from\", \"value\"}");
    radio::FieldSource s;
    s.from = text(e, wk, "from", 16);
    s.value = text(e, wk, "value", 80);
    if (e.contains("offer_from")) s.offer_from = text(e, wk, "offer_from", 16), s.offer_value = text(e, wk, "offer_value", 80);
    out.emplace(key, std::move(s));
  }
  return out;
}

// A satellite: its elements, the chosen mode's record as "radio" (what a trakbox from before modes
// reads), every mode and the chosen one's name.
json satellite_json(const Satellite& s) {
  json modes = json::array();
  for (const radio::SatelliteMode& m : modes_of(s)) {
    json mj = {{"name", m.name}, {"radio", radio_entry_json(m.radio)}};
    if (m.arm_tone_tenths_hz > 0) mj["arm_tone_tenths_hz"] = m.arm_tone_tenths_hz;
    if (!m.sources.empty()) mj["sources"] = sources_json(m.sources);
    modes.push_back(std::move(mj));
  }
  return {{"elements", elements_json(s.elements)}, {"radio", radio_entry_json(s.radio)}, {"modes", modes},
          {"mode", chosen_mode(s)}};
}

// The modes of a satellite (w its path): names valid and different (case aside), at most
// radio::kMaxModes, the chosen one among them; `radio` becomes the chosen one's record.
void modes_from(const json& j, const std::string& w, Satellite& s) {
  const json& ms = field(j, w, "modes");
  const std::string wm = path(w, "modes");
  if (!ms.is_array() || ms.size() > radio::kMaxModes)
    bad(wm, "expected a list of up to " + std::to_string(radio::kMaxModes) + " modes");
  for (std::size_t k = 0; k < ms.size(); ++k) {
    const std::string wk = wm + "[" + std::to_string(k) + "]";
    radio::SatelliteMode m;
    m.name = text(ms[k], wk, "name", radio::kMaxModeName);
    if (const std::string why = radio::mode_name_problem(m.name); !why.empty()) bad(path(wk, "name"), why);
    for (const auto& x : s.modes)
      if (::tb::text::iequals(x.name, m.name)) bad(path(wk, "name"), "'" + m.name + "' is given twice");
    m.radio = radio_entry_from(field(ms[k], wk, "radio"), path(wk, "radio"));
    if (ms[k].contains("arm_tone_tenths_hz"))
      m.arm_tone_tenths_hz = static_cast<int>(integer(ms[k], wk, "arm_tone_tenths_hz", 0, 3000));
    // Where each field came from (issue 59's imports); absent before them: every value the operator's.
    if (ms[k].contains("sources")) m.sources = sources_from(ms[k]["sources"], path(wk, "sources"));
    s.modes.push_back(std::move(m));
  }
  s.mode = text(j, w, "mode", radio::kMaxModeName);
  for (const auto& m : s.modes)
    if (m.name == s.mode) {
      s.radio = m.radio;
      return;
    }
  if (!s.modes.empty() || !s.mode.empty())
    bad(path(w, "mode"), "'" + s.mode + "' is not one of the satellite's modes");
}

}  // namespace

Model factory_defaults() { return Model{}; }

namespace {
std::string replace_dots(std::string_view key) {
  std::string p(key);
  std::replace(p.begin(), p.end(), '.', '/');
  return p;
}
}  // namespace

json to_json(const Model& m) {
  json j;
  // Every setting of the table (store/settings.h) in its form (the enums by name), then what the
  // table does not hold: spans, positions, the database, the choice, the lists.
  for (const Setting& s : settings()) j[json::json_pointer("/" + replace_dots(s.key))] = s.get(m);
  j["sharing"]["exclusive"] = m.sharing.exclusive;  // "" for none, as the document always had it
  const auto& r = m.rotator;
  json presets = json::array();
  for (const auto& p : r.presets) presets.push_back(azel(p));
  j["rotator"]["az_span"] = {r.az_span.min, r.az_span.max};
  j["rotator"]["el_span"] = {r.el_span.min, r.el_span.max};
  j["rotator"]["parking"] = azel(r.parking);
  j["rotator"]["presets"] = presets;
  j["rotator"]["sky_calibration"] = {{"source", r.sky.source},
                                     {"time", r.sky.time},
                                     {"previous_az_offset_deg", r.sky.previous_az_offset_deg},
                                     {"previous_el_offset_deg", r.sky.previous_el_offset_deg},
                                     {"previous_source", r.sky.previous_source},
                                     {"previous_time", r.sky.previous_time}};
  const auto& rc = m.radio;
  j["radio"].update({{"rig", name_of(rc.rig, kRig)},
                     {"icom_rx_address", rc.icom_rx_address},
                     {"icom_tx_address", rc.icom_tx_address},
                     {"icom_band_select", name_of(rc.icom_band_select, kBand)},
                     {"icom_four_byte_frequency", rc.icom_four_byte_frequency},
                     {"ft736_wide_fm", rc.ft736_wide_fm},
                     {"rig_model", name_of(rc.rig_model, kRigModel)},
                     {"corrections", rc.corrections},
                     {"tx_corrections", rc.tx_corrections},
                     {"parking",
                      {{"enabled", rc.parking.enabled},
                       {"rx_hz", rc.parking.rx_hz},
                       {"tx_hz", rc.parking.tx_hz},
                       {"rx_mode", name_of(rc.parking.rx_mode, kMode)},
                       {"tx_mode", name_of(rc.parking.tx_mode, kMode)}}},
                     {"mic_click",
                      {{"centre_adc", rc.mic_click.centre_adc},
                       {"reference_adc", rc.mic_click.reference_adc},
                       {"step_hz", rc.mic_click.step_hz},
                       {"cat_at_aos", rc.mic_click.cat_at_aos},
                       {"auto_up_at_aos", rc.mic_click.auto_up_at_aos},
                       {"polarity", name_of(rc.mic_click.polarity, kPolarity)},
                       {"park_pulse_width_digit", rc.mic_click.park_pulse_width_digit},
                       {"park_pulse_interval_digit", rc.mic_click.park_pulse_interval_digit}}}});
  json sats = json::array();
  for (const auto& s : m.db.satellites) sats.push_back(satellite_json(s));
  j["db"] = {{"satellites", sats}, {"selected", m.db.selected}, {"marked", m.db.marked},
             {"multi_count", m.db.multi_count}};
  j["clock_offset_us"] = m.clock_offset.count();
  j["tracking"] = {{"mode", m.tracking.mode == TrackingChoice::Mode::single  ? "single"
                            : m.tracking.mode == TrackingChoice::Mode::multi ? "multi"
                                                                              : "list"},
                   {"catalog_number", m.tracking.catalog_number},
                   {"name", m.tracking.name}};
  j["refresh"].update(to_json(m.refresh));
  j["gps"]["position_from_gps"] = m.gps.position_from_gps;
  j["gps"]["position_time_us"] =
      m.gps.position_time ? json(m.gps.position_time->time_since_epoch().count()) : json();
  j["udp_events"] = m.udp_events;
  json res = json::array();
  for (const Reservation& x : m.sharing.reservations)
    res.push_back({{"id", x.id}, {"start_unix", x.start_unix}, {"end_unix", x.end_unix}, {"note", x.note}});
  j["sharing"]["reservations"] = res;
  return j;
}

namespace {

// A setting of the table (store/settings.h) read from its parent object with the table's rule and
// sentence, put into the model; take_if: only when present (fields added after the first format).
void take(Model& m, const json& parent, std::string_view key) { find_setting(key)->put(m, read_setting(parent, key)); }
void take_if(Model& m, const json& parent, std::string_view key) {
  if (parent.is_object() && parent.contains(std::string(key.substr(key.rfind('.') + 1)))) take(m, parent, key);
}

// The parts of the document, each validated as it is read (store/json_fields.h: a problem throws,
// naming the field).
void station_from(const json& j, Model& m) {
  const json& s = field(j, "", "station");
  for (const char* key : {"station.callsign", "station.lat_deg", "station.lon_deg", "station.height_m",
                          "station.rotor_start", "station.com_baud"})
    take(m, s, key);
  // Absent before the horizon mask (issue 57): none.
  take_if(m, s, "station.horizon_mask");
}

rotator::SkyCalibration sky_calibration_from(const json& j, const std::string& w) {
  rotator::SkyCalibration k;
  const double most = rotator::limits::kSkyOffsetMaxDeg;
  k.source = text(j, w, "source", 16);
  k.time = text(j, w, "time", 32);
  k.previous_az_offset_deg = num(j, w, "previous_az_offset_deg", -most, most);
  k.previous_el_offset_deg = num(j, w, "previous_el_offset_deg", -most, most);
  k.previous_source = text(j, w, "previous_source", 16);
  k.previous_time = text(j, w, "previous_time", 32);
  for (const std::string* t : {&k.time, &k.previous_time})
    if (!t->empty() && !orbit::parse_iso8601(*t)) bad(w + ".time", "'" + *t + "' is not an ISO 8601 UTC time");
  for (const std::string* src : {&k.source, &k.previous_source})
    if (!src->empty() && *src != "sun" && *src != "moon" && *src != "sun scan")
      bad(w + ".source", "'" + *src + "': expected sun, moon, sun scan or nothing");
  return k;
}

void rotator_from(const json& j, Model& m) {
  rotator::RotatorConfig& c = m.rotator;
  const std::string w = "rotator";
  const json& r = field(j, "", "rotator");
  auto span = [&](const char* key) {
    const json& v = field(r, w, key);
    if (!v.is_array() || v.size() != 2 || !v[0].is_number_integer() || !v[1].is_number_integer())
      bad(w + "." + key, "expected [min, max] counts");
    return rotator::AxisSpan{v[0].get<int>(), v[1].get<int>()};
  };
  c.az_span = span("az_span");
  c.el_span = span("el_span");
  for (const char* key : {"rotator.az_travel_deg", "rotator.az_dead_band", "rotator.el_dead_band", "rotator.az_skew",
                          "rotator.el_skew", "rotator.parking_enabled", "rotator.limits_enabled",
                          "rotator.az_limit_min", "rotator.az_limit_max", "rotator.el_limit_min",
                          "rotator.el_limit_max", "rotator.el_flip_allowed", "rotator.az_rate_deg_s",
                          "rotator.el_rate_deg_s", "rotator.coast_s", "rotator.stall_s"})
    take(m, r, key);
  c.parking = azel_from(field(r, w, "parking"), w + ".parking");
  // Absent in state files written before it: the limits are barriers.
  take_if(m, r, "rotator.cross_limit_sector");
  // Absent before the sky calibration (issue 58): no offsets, no record.
  for (const char* key : {"rotator.az_offset_deg", "rotator.el_offset_deg"}) take_if(m, r, key);
  if (r.contains("sky_calibration")) c.sky = sky_calibration_from(r["sky_calibration"], w + ".sky_calibration");
  const json& p = field(r, w, "presets");
  if (!p.is_array() || p.size() != c.presets.size()) bad(w + ".presets", "expected 5 positions");
  for (std::size_t i = 0; i < c.presets.size(); ++i)
    c.presets[i] = azel_from(p[i], w + ".presets[" + std::to_string(i) + "]");
  if (const auto problems = rotator::validate(c); !problems.empty()) bad(w, problems.front());
}

void radio_from(const json& j, Model& m) {
  radio::RadioConfig& c = m.radio;
  const std::string w = "radio";
  const json& r = field(j, "", "radio");
  c.rig = named(r, w, "rig", kRig);
  c.icom_rx_address = static_cast<std::uint8_t>(integer(r, w, "icom_rx_address", 0, 255));
  c.icom_tx_address = static_cast<std::uint8_t>(integer(r, w, "icom_tx_address", 0, 255));
  c.icom_band_select = named(r, w, "icom_band_select", kBand);
  c.icom_four_byte_frequency = boolean(r, w, "icom_four_byte_frequency");
  for (const char* key : {"radio.uplink_correction", "radio.downlink_correction", "radio.cat_policy"}) take(m, r, key);
  c.ft736_wide_fm = boolean(r, w, "ft736_wide_fm");
  const std::string wm = w + ".mic_click";
  const json& mc = field(r, w, "mic_click");
  c.mic_click.centre_adc = static_cast<int>(integer(mc, wm, "centre_adc", 0, 1023));
  c.mic_click.reference_adc = static_cast<int>(integer(mc, wm, "reference_adc", 0, 1023));
  c.mic_click.step_hz = integer(mc, wm, "step_hz", 1, 100000);
  c.mic_click.cat_at_aos = boolean(mc, wm, "cat_at_aos");
  c.mic_click.auto_up_at_aos = boolean(mc, wm, "auto_up_at_aos");
  c.mic_click.polarity = named(mc, wm, "polarity", kPolarity);
  // The later firmware's STATION.DAT items: absent in state files written before them.
  if (mc.contains("park_pulse_width_digit"))
    c.mic_click.park_pulse_width_digit = static_cast<int>(integer(mc, wm, "park_pulse_width_digit", -1, 9));
  if (mc.contains("park_pulse_interval_digit"))
    c.mic_click.park_pulse_interval_digit = static_cast<int>(integer(mc, wm, "park_pulse_interval_digit", -1, 9));
  if (r.contains("rig_model")) c.rig_model = named(r, w, "rig_model", kRigModel);
  // The CAT speed, dial follow, the second radio, the operating practice: absent in state files
  // written before them.
  for (const char* key : {"radio.cat_baud", "radio.dial_follow", "radio.uplink_radio", "radio.dial_rest_ms",
                          "radio.doppler_step_ssb_hz", "radio.doppler_step_fm_hz", "radio.record",
                          "radio.record_satellites"})
    take_if(m, r, key);
  if (r.contains("corrections")) {
    const json& cs = field(r, w, "corrections");
    if (!cs.is_object()) bad(path(w, "corrections"), "expected an object of \"SATELLITE MODE\": Hz");
    for (const auto& [key, value] : cs.items())
      c.corrections[key] = integer(cs, path(w, "corrections"), key.c_str(), -1'000'000, 1'000'000);
  }
  if (r.contains("tx_corrections")) {
    const json& cs = field(r, w, "tx_corrections");
    if (!cs.is_object()) bad(path(w, "tx_corrections"), "expected an object of \"SATELLITE MODE\": Hz");
    for (const auto& [key, value] : cs.items())
      c.tx_corrections[key] = integer(cs, path(w, "tx_corrections"), key.c_str(), -1'000'000, 1'000'000);
  }
  if (r.contains("parking")) {
    const std::string wp = w + ".parking";
    const json& p = field(r, w, "parking");
    c.parking.enabled = boolean(p, wp, "enabled");
    c.parking.rx_hz = integer(p, wp, "rx_hz", 0, kMaxHz);
    c.parking.tx_hz = integer(p, wp, "tx_hz", 0, kMaxHz);
    c.parking.rx_mode = named(p, wp, "rx_mode", kMode);
    c.parking.tx_mode = named(p, wp, "tx_mode", kMode);
  }
}

Database database_from(const json& j, std::vector<std::size_t>* migrated) {
  Database db;
  const json& d = field(j, "", "db");
  const json& sats = field(d, "db", "satellites");
  if (!sats.is_array()) bad("db.satellites", "expected a list");
  if (sats.size() > static_cast<std::size_t>(kMaxDatabase)) bad("db.satellites", "more than 32 satellites");
  for (std::size_t i = 0; i < sats.size(); ++i) {
    const std::string w = "db.satellites[" + std::to_string(i) + "]";
    Satellite s;
    s.elements = elements_from(field(sats[i], w, "elements"), w + ".elements");
    s.radio = radio_entry_from(field(sats[i], w, "radio"), w + ".radio");
    if (sats[i].contains("modes")) {
      modes_from(sats[i], w, s);
    } else {  // a state from before modes: its one record becomes its one mode
      settle_modes(s);
      if (migrated && !s.modes.empty()) migrated->push_back(i);
    }
    db.satellites.push_back(std::move(s));
  }
  const json& sel = field(d, "db", "selected");
  if (!sel.is_array() || sel.size() > static_cast<std::size_t>(kMaxSelected)) bad("db.selected", "expected up to 15 numbers");
  for (std::size_t i = 0; i < sel.size(); ++i) {
    if (!sel[i].is_number_integer()) bad("db.selected", "expected whole numbers");
    const int v = sel[i].get<int>();
    if (v < 0 || v >= static_cast<int>(db.satellites.size())) bad("db.selected", "entry " + std::to_string(v) + " is not in the database");
    db.selected.push_back(v);
  }
  db.marked = static_cast<int>(integer(d, "db", "marked", -1, kMaxSelected - 1));
  db.multi_count = static_cast<int>(integer(d, "db", "multi_count", kMinMultiTrack, kMaxMultiTrack));
  db.normalise();
  return db;
}

// A state from before modes kept the operator's corrections per satellite and link mode ("RS-44 USB"
// for the downlink, "RS-44 LSB" for the uplink); now they are per satellite and mode name
// ("RS-44 SSB"). Each is copied to its mode's key (the old key stays: nothing is lost).
void migrate_corrections(Model& m, const std::vector<std::size_t>& migrated) {
  for (const std::size_t i : migrated) {
    const Satellite& s = m.db.satellites[i];
    const std::string now = s.name() + " " + s.mode;
    if (const auto it = m.radio.corrections.find(s.name() + " " + radio::to_string(s.radio.downlink_mode));
        it != m.radio.corrections.end())
      m.radio.corrections.try_emplace(now, it->second);
    if (const auto it = m.radio.tx_corrections.find(s.name() + " " + radio::to_string(s.radio.uplink_mode));
        it != m.radio.tx_corrections.end())
      m.radio.tx_corrections.try_emplace(now, it->second);
  }
}

TrackingChoice tracking_from(const json& t) {
  TrackingChoice c;
  const std::string w = "tracking";
  const std::string mode = text(t, w, "mode", 10);
  if (mode == "single") c.mode = TrackingChoice::Mode::single;
  else if (mode == "multi") c.mode = TrackingChoice::Mode::multi;
  else if (mode != "list") bad(path(w, "mode"), "expected list, single or multi; found '" + mode + "'");
  c.catalog_number = static_cast<int>(integer(t, w, "catalog_number", 0, 999999999));
  c.name = text(t, w, "name", 64);
  return c;
}

void gps_from(const json& g, Model& m) {
  station::GpsSettings& s = m.gps;
  const std::string w = "gps";
  for (const char* key : {"gps.source", "gps.follow", "gps.threshold_m"}) take(m, g, key);
  s.position_from_gps = boolean(g, w, "position_from_gps");
  const json& t = field(g, w, "position_time_us");
  if (!t.is_null())
    s.position_time = orbit::UtcTime(std::chrono::microseconds(integer(g, w, "position_time_us", 0, 1LL << 52)));
}

void sharing_from(const json& j, Model& m) {
  if (!j.is_object()) bad("sharing", "expected an object");
  Sharing& s = m.sharing;
  // The state document writes "" for none, as the table shows "none".
  if (j.contains("exclusive") && j["exclusive"] == "") {
    json copy = j;
    copy["exclusive"] = "none";
    take(m, copy, "sharing.exclusive");
  } else {
    take(m, j, "sharing.exclusive");
  }
  for (const char* key : {"sharing.handback_s", "sharing.standby"}) take(m, j, key);
  for (const char* key : {"sharing.satnogs_station", "sharing.satnogs_url"}) take_if(m, j, key);
  if (j.contains("reservations")) {
    const json& r = j["reservations"];
    if (!r.is_array() || r.size() > kMaxReservations)
      bad("sharing.reservations", "expected a list of at most " + std::to_string(kMaxReservations));
    for (std::size_t i = 0; i < r.size(); ++i) {
      const std::string w = "sharing.reservations[" + std::to_string(i) + "]";
      Reservation x;
      x.id = text(r[i], w, "id", 32);
      x.start_unix = integer(r[i], w, "start_unix", 0, 1LL << 40);
      x.end_unix = integer(r[i], w, "end_unix", 0, 1LL << 40);
      if (x.end_unix <= x.start_unix) bad(w + ".end_unix", "expected after start_unix");
      x.note = text(r[i], w, "note", 200);
      s.reservations.push_back(std::move(x));
    }
  }
}

std::vector<std::string> udp_events_from(const json& u) {
  if (!u.is_array()) bad("udp_events", "expected a list of HOST:PORT");
  if (u.size() > kMaxUdpEvents) bad("udp_events", "more than " + std::to_string(kMaxUdpEvents) + " destinations");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < u.size(); ++i) {
    const std::string w = "udp_events[" + std::to_string(i) + "]";
    if (!u[i].is_string()) bad(w, "expected HOST:PORT");
    std::string why;
    const std::string text = u[i].get<std::string>();
    const auto t = inet::parse_host_port(text, why);
    if (!t) bad(w, "'" + text + "': " + why);
    out.push_back(inet::host_port_text(*t));
  }
  return out;
}

}  // namespace

Model model_from_json(const json& j) {
  if (!j.is_object()) bad("state", "expected an object");
  Model m;
  station_from(j, m);
  rotator_from(j, m);
  radio_from(j, m);
  std::vector<std::size_t> migrated;
  m.db = database_from(j, &migrated);
  migrate_corrections(m, migrated);
  m.clock_offset = std::chrono::microseconds(integer(j, "", "clock_offset_us", -(100LL * 365 * 86400 * 1000000),
                                                     100LL * 365 * 86400 * 1000000));
  take(m, j, "rotor_control");
  take(m, j, "priority_mode");
  // Absent in state files written before the choice was kept (issue 39): the tracking list's rule.
  if (j.contains("tracking")) m.tracking = tracking_from(j["tracking"]);
  take_if(m, j, "event_min_el_deg");
  // Absent in state files written before the scheduled refresh existed.
  if (j.contains("refresh")) m.refresh = refresh_settings_from_json(j["refresh"], "refresh");
  // Absent in state files written before the later firmware's STATION.DAT was read.
  if (j.contains("pass_events")) {
    const json& p = j["pass_events"];
    for (const char* key : {"pass_events.rotor_start_el_deg", "pass_events.output_on_el_deg",
                            "pass_events.output_off_el_deg"})
      take(m, p, key);
  }
  take_if(m, j, "rotator_error_detection");
  // Absent in state files written before the drivers were remembered (issue 30).
  if (j.contains("drivers")) {
    take(m, j["drivers"], "drivers.rotator");
    take(m, j["drivers"], "drivers.radio");
  }
  // Absent in state files written before the GPS receiver existed.
  if (j.contains("gps")) gps_from(j["gps"], m);
  // Absent in state files written before --udp-events was stored.
  if (j.contains("udp_events")) m.udp_events = udp_events_from(j["udp_events"]);
  // Absent in state files written before the station was shared (issue 44).
  if (j.contains("sharing")) sharing_from(j["sharing"], m);
  // Absent in state files written before the logger (issue 45).
  if (j.contains("logger")) {
    const json& l = j["logger"];
    if (!l.is_object()) bad("logger", "expected an object");
    for (const char* key : {"logger.spec", "logger.key_file", "logger.station_id"}) take(m, l, key);
  }
  return m;
}

}  // namespace tb::store
