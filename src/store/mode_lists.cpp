// The readers of store/mode_import.h: SatNOGS DB, Gpredict .trsp, SatPC32 Doppler.SQF and
// SubTone.SQF, OscarWatch satellite_database.json. Each reads the whole text or refuses it with one
// sentence naming the file, the line (or JSON path) and the field.
#include <cmath>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "store/mode_import.h"
#include "util/json_limits.h"
#include "util/safe_text.h"
#include "util/text.h"

namespace tb::store {

using json = nlohmann::json;

namespace {

// A read problem: where, and what was expected.
struct Bad {
  std::string what;
};

[[noreturn]] void bad(std::string what) { throw Bad{std::move(what)}; }

bool is_word_char(char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'); }

bool has_word(const std::string& upper_text, std::string_view word) {
  for (std::size_t at = upper_text.find(word); at != std::string::npos; at = upper_text.find(word, at + 1)) {
    const bool left = at == 0 || !is_word_char(upper_text[at - 1]);
    const std::size_t end = at + word.size();
    if (left && (end == upper_text.size() || !is_word_char(upper_text[end]))) return true;
  }
  return false;
}

// A mode name from free text: what radio::mode_name_problem takes, spaces as '-', at most 16.
std::string clean_name(std::string_view label) {
  std::string out;
  for (const char c : text::trimmed(label)) {
    if (out.size() == radio::kMaxModeName) break;
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' ||
                    c == '+' || c == '/' || c == '.' || c == '_';
    if (ok) out.push_back(c);
    else if (c == ' ' && !out.empty() && out.back() != '-') out.push_back('-');
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out;
}

// The mode's name: a known way of working named in the label ("Mode V/U FM voice" -> FM, "CW
// beacon" -> CW, "APRS", "SSTV", "FT4"), a linear transponder "SSB", else the list's modulation
// ("GMSK"), else after the downlink's radio mode.
std::string mode_name_for(std::string_view label, std::string_view modulation, radio::Mode down, bool linear) {
  const std::string u = text::upper(label), m = text::upper(modulation);
  for (const char* w : {"APRS", "SSTV", "FT4", "FT8", "PSK31", "CW", "FM", "SSB"})
    if (has_word(u, w)) return w;
  if (linear || has_word(u, "LINEAR") || has_word(u, "TRANSPONDER")) return "SSB";
  for (const char* w : {"APRS", "SSTV", "CW", "FM", "SSB"})
    if (has_word(m, w)) return w;
  if (const std::string c = clean_name(modulation); !c.empty() && radio::mode_name_problem(c).empty()) return c;
  if (down == radio::Mode::usb || down == radio::Mode::lsb) return "SSB";
  if (down == radio::Mode::none) return "default";
  return radio::to_string(down);
}

// A rig's mode name as the lists write it: USB, LSB, CW(-N), FM, FMN, FM-N, FM-W, DATA-USB, SSB.
std::optional<radio::Mode> rig_mode(std::string_view t) {
  std::string u = text::upper(text::trimmed(t));
  if (u.starts_with("DATA-")) u = u.substr(5);
  if (u.starts_with("FM")) return radio::Mode::fm;
  if (u.starts_with("CW")) return radio::Mode::cw;
  if (u == "USB" || u == "SSB") return radio::Mode::usb;
  if (u == "LSB") return radio::Mode::lsb;
  return std::nullopt;
}

// SatNOGS' modulation names: FM and the data modes an FM receiver hears (AFSK, FSK, GMSK); USB for
// SSB, CW and the rest (BPSK, LoRa ...: USB is how a station listens to them).
radio::Mode satnogs_mode(const std::string& satnogs_mode) {
  const std::string m = text::upper(satnogs_mode);
  if (m == "LSB") return radio::Mode::lsb;
  if (m == "CW") return radio::Mode::cw;
  if (m.starts_with("FM") || m.find("FSK") != std::string::npos || m.find("GMSK") != std::string::npos || m == "APRS")
    return radio::Mode::fm;
  return radio::Mode::usb;
}

radio::Hz centre(radio::Hz low, radio::Hz high) { return high > low ? low + (high - low) / 2 : low; }

// The fields a transponder or transmitter with these edges gives (0: not given).
struct Edges {
  radio::Hz down_low = 0, down_high = 0, up_low = 0, up_high = 0;
  bool invert = false;
  bool linear() const { return down_low > 0 && down_high > down_low && up_low > 0 && up_high > up_low; }
};

// A list's receive-only entry (a beacon, telemetry) says nothing of the mode's uplink: a gap, not
// "no uplink" (the FM voice mode it may be named after keeps its uplink, without a conflict).
unsigned uplink_given(const radio::SatelliteRadio& r) {
  return r.uplink_hz > 0 ? field_bit(ModeField::uplink) | field_bit(ModeField::uplink_mode) : 0u;
}

ListedMode from_edges(const Edges& e, std::string_view label, std::string_view modulation, bool transponder) {
  ListedMode l;
  radio::SatelliteRadio& r = l.mode.radio;
  const bool linear = transponder && e.linear();
  r.downlink_hz = centre(e.down_low, e.down_high);
  r.uplink_hz = e.up_low > 0 ? centre(e.up_low, e.up_high) : 0;
  if (linear) {
    r.downlink_low_hz = e.down_low, r.downlink_high_hz = e.down_high;
    r.uplink_low_hz = e.up_low, r.uplink_high_hz = e.up_high;
    r.inverting = e.invert;
    r.downlink_mode = radio::Mode::usb;
    r.uplink_mode = e.invert ? radio::Mode::lsb : radio::Mode::usb;
    l.given |= field_bit(ModeField::passbands) | field_bit(ModeField::inverting);
  } else {
    r.downlink_mode = satnogs_mode(std::string(modulation));
    r.uplink_mode = r.uplink_hz > 0 ? r.downlink_mode : radio::Mode::none;
  }
  l.given |= field_bit(ModeField::downlink) | field_bit(ModeField::downlink_mode) | uplink_given(r);
  l.mode.name = mode_name_for(label, modulation, r.downlink_mode, linear);
  return l;
}

// Names within one satellite made different: "SSB", "SSB-2", ...
void distinct_names(std::vector<ListedMode>& modes) {
  std::map<std::string, int> seen;  // satellite key + upper(name) -> count
  for (ListedMode& l : modes) {
    const std::string sat = l.catalog > 0 ? std::to_string(l.catalog) : (l.names.empty() ? "" : l.names.front());
    const int n = ++seen[sat + "\n" + text::upper(l.mode.name)];
    if (n == 1) continue;
    const std::string suffix = "-" + std::to_string(n);
    l.mode.name = l.mode.name.substr(0, radio::kMaxModeName - suffix.size()) + suffix;
  }
}

// ---- SatNOGS DB transmitters JSON

std::optional<radio::Hz> satnogs_hz(const json& o, const char* key, const std::string& where) {
  const auto it = o.find(key);
  if (it == o.end() || it->is_null()) return std::nullopt;
  if (!it->is_number() || !(it->get<double>() >= 0 && it->get<double>() < 1e12))
    bad(fmt::format("{}, field {}: expected a frequency in Hz or null", where, key));
  const auto v = static_cast<radio::Hz>(std::llround(it->get<double>()));
  return v > 0 ? std::optional(v) : std::nullopt;
}

std::string str(const json& o, const char* key) {
  const auto it = o.find(key);
  return it != o.end() && it->is_string() ? text::safe_text(it->get<std::string>().substr(0, 80)) : std::string();
}

void read_satnogs(std::string_view text, const std::string& file, ModeList& out) {
  std::string why;
  const json list = json_limits::parse_bounded<json>(text, why);
  if (why.starts_with("nested"))
    bad(fmt::format("{}: not a SatNOGS transmitter list (JSON nested deeper than {} levels)", file, json_limits::kMaxDepth));
  if (list.is_discarded() || !list.is_array())
    bad(file + ": not a SatNOGS transmitter list (expected a JSON array of transmitters)");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& o = list[i];
    std::string where = fmt::format("{}: transmitter {}", file, i + 1);
    if (!o.is_object() || !o.contains("norad_cat_id")) bad(where + ": not a transmitter object (no norad_cat_id)");
    if (const std::string uuid = str(o, "uuid"); !uuid.empty()) where += " (" + uuid + ")";
    const json& n = o["norad_cat_id"];
    if (n.is_null()) continue;  // an object without a catalog number yet
    if (!n.is_number_integer() || n.get<long long>() <= 0) bad(where + ", field norad_cat_id: expected a catalog number");
    if (o.contains("alive") && !o["alive"].is_boolean()) bad(where + ", field alive: expected true or false");
    const bool alive = !o.contains("alive") || o["alive"].get<bool>();
    Edges e{satnogs_hz(o, "downlink_low", where).value_or(0), satnogs_hz(o, "downlink_high", where).value_or(0),
            satnogs_hz(o, "uplink_low", where).value_or(0), satnogs_hz(o, "uplink_high", where).value_or(0),
            o.contains("invert") && o["invert"].is_boolean() && o["invert"].get<bool>()};
    if (!alive || str(o, "status") != "active") {
      ++out.not_offered;
      continue;
    }
    if (e.down_low <= 0) continue;  // an uplink alone is nothing to listen to
    ListedMode l = from_edges(e, str(o, "description"), str(o, "mode"), str(o, "type") == "Transponder");
    l.catalog = n.get<long long>();
    out.modes.push_back(std::move(l));
  }
}

// ---- Lines (trsp, SQF)

template <class F>
void each_line(std::string_view text, F&& f) {
  int no = 0;
  for (std::string_view line : text::split(text, '\n')) {
    ++no;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::string t = text::trimmed(line);
    if (t.empty() || t.front() == ';' || t.front() == '#') continue;
    f(no, t);
  }
}

// ---- Gpredict .trsp

long long trsp_catalog(const std::string& file) {
  std::string stem = file.substr(file.find_last_of('/') == std::string::npos ? 0 : file.find_last_of('/') + 1);
  if (text::iequals(std::string_view(stem).substr(stem.size() > 5 ? stem.size() - 5 : 0), ".trsp"))
    stem.resize(stem.size() - 5);
  const auto n = text::parse_integer<long long>(stem);
  if (!n || *n <= 0) bad(file + ": a Gpredict transponder file is named by the satellite's catalog number, as 44909.trsp");
  return *n;
}

struct TrspGroup {
  std::string name;
  int line = 0;
  Edges edges;
  std::string mode;
};

void trsp_key(TrspGroup& g, const std::string& where, const std::string& key, const std::string& value) {
  radio::Hz* hz = key == "UP_LOW" ? &g.edges.up_low : key == "UP_HIGH" ? &g.edges.up_high
                : key == "DOWN_LOW" ? &g.edges.down_low : key == "DOWN_HIGH" ? &g.edges.down_high : nullptr;
  if (hz) {
    const auto v = text::parse_integer<long long>(value);
    if (!v || *v < 0 || *v >= 1'000'000'000'000) bad(fmt::format("{}, {}: found \"{}\", expected a frequency in Hz", where, key, value));
    *hz = *v;
  } else if (key == "INVERT") {
    const std::string v = text::upper(value);
    if (v != "TRUE" && v != "FALSE" && v != "1" && v != "0")
      bad(fmt::format("{}, INVERT: found \"{}\", expected true or false", where, value));
    g.edges.invert = v == "TRUE" || v == "1";
  } else if (key == "MODE") {
    g.mode = text::safe_text(value.substr(0, 40));
  }  // BAUD and keys of later Gpredict versions carry nothing trakbox keeps
}

void read_trsp(std::string_view text, const std::string& file, ModeList& out) {
  const long long catalog = trsp_catalog(file);
  std::vector<TrspGroup> groups;
  each_line(text, [&](int no, const std::string& t) {
    const std::string where = fmt::format("{}: line {}", file, no);
    if (t.front() == '[') {
      if (t.back() != ']' || t.size() < 3) bad(where + ": found \"" + text::safe_text(t.substr(0, 40)) + "\", expected [transponder name]");
      groups.push_back({text::safe_text(t.substr(1, t.size() - 2)), no, {}, {}});
      return;
    }
    const std::size_t eq = t.find('=');
    if (eq == std::string::npos) bad(where + ": found \"" + text::safe_text(t.substr(0, 40)) + "\", expected KEY=VALUE or [group]");
    if (groups.empty()) bad(where + ": " + text::safe_text(t.substr(0, eq)) + " before any [group]");
    trsp_key(groups.back(), where, text::upper(text::trimmed(t.substr(0, eq))), text::trimmed(t.substr(eq + 1)));
  });
  for (const TrspGroup& g : groups) {
    if (g.edges.down_low <= 0) continue;  // an uplink alone is nothing to listen to
    const std::string m = text::upper(g.mode);
    const bool transponder = m == "USB" || m == "LSB" || m == "SSB" || m == "CW" || m.empty();
    ListedMode l = from_edges(g.edges, g.name, g.mode, transponder);
    l.catalog = catalog;
    l.line = g.line;
    out.modes.push_back(std::move(l));
  }
}

// ---- SatPC32 Doppler.SQF and SubTone.SQF

// Decimal kHz ("435640", "145993.61") to Hz, exactly; nullopt when not that.
std::optional<radio::Hz> khz(std::string_view t) {
  const auto v = radio::parse_mhz(t);  // the digits read as MHz: 1 kHz is 1000 of these units
  // Not below 1 MHz: "435.64" is MHz written where kHz belong, not 435.64 kHz.
  if (!v || *v % 1000 != 0 || (*v != 0 && *v < 1'000'000'000)) return std::nullopt;
  return *v / 1000;
}

void read_sqf(std::string_view text, const std::string& file, ModeList& out) {
  each_line(text, [&](int no, const std::string& t) {
    const auto f = text::split(t, ',');
    const std::string where = fmt::format("{}: line {}", file, no);
    if (f.size() < 8 || f.size() > 9)
      bad(fmt::format("{}: found {} fields, expected name,down kHz,up kHz,down mode,up mode,NOR|REV,down offset,"
                      "up offset[,comment]", where, f.size()));
    const auto field = [&](std::size_t k) { return text::trimmed(f[k]); };
    ListedMode l;
    l.line = no;
    l.names = {text::safe_text(field(0))};
    if (l.names.front().empty()) bad(where + ", field 1 (name): empty");
    radio::SatelliteRadio& r = l.mode.radio;
    const auto down = khz(field(1)), up = khz(field(2));
    if (!down || *down == 0) bad(where + ", field 2 (downlink): found \"" + text::safe_text(field(1)) + "\", expected kHz such as 435640");
    if (!up) bad(where + ", field 3 (uplink): found \"" + text::safe_text(field(2)) + "\", expected kHz such as 145965, or 0");
    r.downlink_hz = *down, r.uplink_hz = *up;
    const auto dm = rig_mode(field(3)), um = rig_mode(field(4));
    if (!dm) bad(where + ", field 4 (downlink mode): found \"" + text::safe_text(field(3)) + "\", expected USB, LSB, CW or FM");
    if (!um) bad(where + ", field 5 (uplink mode): found \"" + text::safe_text(field(4)) + "\", expected USB, LSB, CW or FM");
    r.downlink_mode = *dm, r.uplink_mode = r.uplink_hz > 0 ? *um : radio::Mode::none;
    const std::string dir = text::upper(field(5));
    if (dir != "NOR" && dir != "REV") bad(where + ", field 6: found \"" + text::safe_text(field(5)) + "\", expected NOR or REV");
    r.inverting = dir == "REV";
    for (std::size_t k : {6u, 7u})
      if (!text::parse_double(field(k)))
        bad(fmt::format("{}, field {} ({} offset): found \"{}\", expected a number", where, k + 1, k == 6 ? "downlink" : "uplink",
                        text::safe_text(field(k))));
    const std::string comment = f.size() > 8 ? field(8) : std::string();  // the mode's name, "Mode A"
    l.mode.name = mode_name_for(comment, comment, r.downlink_mode, false);
    l.given = field_bit(ModeField::downlink) | field_bit(ModeField::downlink_mode) | uplink_given(r) |
              field_bit(ModeField::inverting);
    out.modes.push_back(std::move(l));
  });
}

// A CTCSS tone in Hz (60.0 to 300.0, one decimal) as tenths; nullopt when not that.
std::optional<int> tone_tenths(double hz) {
  const double tenths = hz * 10;
  if (!(hz >= 60.0 && hz <= 300.0) || std::fabs(tenths - std::round(tenths)) > 1e-6) return std::nullopt;
  return static_cast<int>(std::lround(tenths));
}

void read_subtone(std::string_view text, const std::string& file, ModeList& out) {
  each_line(text, [&](int no, const std::string& t) {
    const auto f = text::split(t, ',');
    const std::string where = fmt::format("{}: line {}", file, no);
    if (f.size() < 2 || f.size() > 3) bad(fmt::format("{}: found {} fields, expected name,tone Hz", where, f.size()));
    ListedMode l;
    l.line = no;
    l.names = {text::safe_text(text::trimmed(f[0]))};
    const auto hz = text::parse_double(text::trimmed(f[1]));
    const auto tone = hz ? tone_tenths(*hz) : std::nullopt;
    if (l.names.front().empty()) bad(where + ", field 1 (name): empty");
    if (!tone) bad(where + ", field 2 (tone): found \"" + text::safe_text(text::trimmed(f[1])) + "\", expected a CTCSS tone from 60.0 to 300.0 Hz");
    l.mode.radio.ctcss_tenths_hz = *tone;
    l.mode.name = "tone";
    l.given = field_bit(ModeField::tone);
    l.fm_uplinks = true;
    out.modes.push_back(std::move(l));
  });
}

// ---- OscarWatch satellite_database.json

std::optional<radio::Hz> json_khz(const json& o, const char* key, const std::string& where, bool required) {
  const auto it = o.find(key);
  if (it == o.end() || it->is_null()) {
    if (required) bad(fmt::format("{}.{}: missing, expected kHz such as 435640", where, key));
    return std::nullopt;
  }
  if (!it->is_number() || !(it->get<double>() >= 0 && it->get<double>() < 1e9))
    bad(fmt::format("{}.{}: expected kHz such as 435640", where, key));
  return static_cast<radio::Hz>(std::llround(it->get<double>() * 1000));
}

std::optional<int> json_tone(const json& o, const char* key, const std::string& where) {
  const auto it = o.find(key);
  if (it == o.end() || it->is_null() || (it->is_number() && it->get<double>() == 0)) return std::nullopt;
  const auto tone = it->is_number() ? tone_tenths(it->get<double>()) : std::nullopt;
  if (!tone) bad(fmt::format("{}.{}: expected a CTCSS tone from 60.0 to 300.0 Hz", where, key));
  return tone;
}

radio::Mode json_rig_mode(const json& o, const char* key, const std::string& where) {
  const std::string t = o.contains(key) && o[key].is_string() ? o[key].get<std::string>() : "";
  const auto m = rig_mode(t);
  if (!m) bad(fmt::format("{}.{}: found \"{}\", expected USB, LSB, CW or FM (FMN, DATA-USB ...)", where, key, text::safe_text(t.substr(0, 20))));
  return *m;
}

ListedMode oscarwatch_mode(const json& o, const std::string& where) {
  if (!o.is_object()) bad(where + ": expected a mode object");
  ListedMode l;
  radio::SatelliteRadio& r = l.mode.radio;
  const std::string type = o.contains("type") && o["type"].is_string() ? o["type"].get<std::string>() : "";
  r.downlink_hz = *json_khz(o, "downlink", where, true);
  if (r.downlink_hz <= 0) bad(where + ".downlink: expected kHz above 0");
  r.uplink_hz = json_khz(o, "uplink", where, false).value_or(0);
  r.downlink_mode = json_rig_mode(o, "downlink_mode", where);
  r.uplink_mode = r.uplink_hz > 0 ? json_rig_mode(o, "uplink_mode", where) : radio::Mode::none;
  l.given = field_bit(ModeField::downlink) | field_bit(ModeField::downlink_mode) | uplink_given(r);
  if (o.contains("doppler") && !o["doppler"].is_null()) {
    const std::string d = o["doppler"].is_string() ? text::upper(o["doppler"].get<std::string>()) : "";
    if (d != "NOR" && d != "REV") bad(where + ".doppler: expected \"NOR\" or \"REV\"");
    r.inverting = d == "REV";
    l.given |= field_bit(ModeField::inverting);
  }
  if (const auto t = json_tone(o, "ctcss", where)) r.ctcss_tenths_hz = *t, l.given |= field_bit(ModeField::tone);
  if (const auto t = json_tone(o, "ctcss_arm", where)) l.mode.arm_tone_tenths_hz = *t, l.given |= field_bit(ModeField::arm);
  l.mode.name = mode_name_for(type, type, r.downlink_mode, false);
  return l;
}

long long oscarwatch_catalog(const json& s, const std::string& where) {
  if (!s.contains("norad_id") || s["norad_id"].is_null()) return 0;
  const json& n = s["norad_id"];
  std::optional<long long> v;
  if (n.is_number_integer()) v = n.get<long long>();
  else if (n.is_string()) v = text::parse_integer<long long>(n.get<std::string>());
  if (!v || *v <= 0) bad(where + ".norad_id: expected a catalog number such as \"44909\"");
  return *v;
}

void read_oscarwatch(std::string_view text, const std::string& file, ModeList& out) {
  std::string why;
  const json doc = json_limits::parse_bounded<json>(text, why);
  const json* sats = &doc;
  if (doc.is_object() && doc.contains("satellites")) sats = &doc["satellites"];
  if (doc.is_discarded() || !sats->is_array())
    bad(file + ": not an OscarWatch satellite database (expected a JSON list of satellites, each with name and modes)");
  for (std::size_t i = 0; i < sats->size(); ++i) {
    const json& s = (*sats)[i];
    std::string where = fmt::format("{}: satellites[{}]", file, i);
    if (!s.is_object() || !s.contains("name") || !s["name"].is_string() || !s.contains("modes") || !s["modes"].is_array())
      bad(where + ": expected an object with name and modes");
    const std::string name = text::safe_text(s["name"].get<std::string>().substr(0, 40));
    where += " (" + name + ")";
    std::vector<std::string> names{name};
    if (s.contains("alternative_names") && s["alternative_names"].is_array())
      for (const json& a : s["alternative_names"])
        if (a.is_string()) names.push_back(text::safe_text(a.get<std::string>().substr(0, 40)));
    const long long catalog = oscarwatch_catalog(s, where);
    for (std::size_t k = 0; k < s["modes"].size(); ++k) {
      ListedMode l = oscarwatch_mode(s["modes"][k], fmt::format("{}, modes[{}]", where, k));
      l.catalog = catalog;
      l.names = names;
      out.modes.push_back(std::move(l));
    }
  }
}

}  // namespace

const char* to_string(ListFormat f) {
  switch (f) {
    case ListFormat::satnogs: return "satnogs";
    case ListFormat::trsp: return "trsp";
    case ListFormat::sqf: return "sqf";
    case ListFormat::subtone: return "subtone";
    case ListFormat::oscarwatch: return "oscarwatch";
  }
  return "";
}

std::optional<ListFormat> parse_list_format(std::string_view t) {
  for (const ListFormat f : {ListFormat::satnogs, ListFormat::trsp, ListFormat::sqf, ListFormat::subtone, ListFormat::oscarwatch})
    if (text::iequals(t, to_string(f))) return f;
  return std::nullopt;
}

const char* source_name(ListFormat f) {
  switch (f) {
    case ListFormat::satnogs: return "satnogs";
    case ListFormat::trsp: return "gpredict";
    case ListFormat::sqf:
    case ListFormat::subtone: return "satpc32";
    case ListFormat::oscarwatch: return "oscarwatch";
  }
  return "";
}

std::optional<ListFormat> guess_list_format(std::string_view content, std::string_view file_name) {
  const std::string name = text::upper(file_name.substr(file_name.find_last_of('/') == std::string_view::npos
                                                             ? 0 : file_name.find_last_of('/') + 1));
  if (name.ends_with(".TRSP")) return ListFormat::trsp;
  if (name.starts_with("SUBTONE")) return ListFormat::subtone;
  if (name.ends_with(".SQF")) return ListFormat::sqf;
  const std::string head = text::trimmed(content.substr(0, 4096));
  if (head.starts_with("[")) {
    if (head.find("\"norad_cat_id\"") != std::string::npos) return ListFormat::satnogs;
    if (head.find("\"modes\"") != std::string::npos) return ListFormat::oscarwatch;
    if (head.find("UP_LOW") != std::string::npos || head.find("DOWN_LOW") != std::string::npos) return ListFormat::trsp;
  }
  if (head.starts_with("{") && head.find("\"modes\"") != std::string::npos) return ListFormat::oscarwatch;
  return std::nullopt;
}

ModeList read_mode_list(ListFormat format, std::string_view content, std::string_view file_name) {
  ModeList out;
  out.format = format;
  const std::string file = text::safe_text(file_name);
  try {
    switch (format) {
      case ListFormat::satnogs: read_satnogs(content, file, out); break;
      case ListFormat::trsp: read_trsp(content, file, out); break;
      case ListFormat::sqf: read_sqf(content, file, out); break;
      case ListFormat::subtone: read_subtone(content, file, out); break;
      case ListFormat::oscarwatch: read_oscarwatch(content, file, out); break;
    }
  } catch (const Bad& b) {
    out.modes.clear();
    out.error = b.what;
  }
  distinct_names(out.modes);
  return out;
}

}  // namespace tb::store
