#include "logbook/adif.h"

#include <charconv>
#include <map>

#include "util/text.h"

namespace tb::logbook {
namespace {

void field(std::string& out, std::string_view name, std::string_view value) {
  if (value.empty()) return;
  out += '<';
  out += name;
  out += ':';
  out += std::to_string(value.size());
  out += '>';
  out += value;
  out += ' ';
}

std::string two(unsigned v) { return std::string{static_cast<char>('0' + v / 10), static_cast<char>('0' + v % 10)}; }

std::string date_text(std::int64_t t) {  // YYYYMMDD
  int y;
  unsigned m, d;
  civil_from_days((t >= 0 ? t : t - 86399) / 86400, y, m, d);
  return std::to_string(y) + two(m) + two(d);
}

std::string time_text(std::int64_t t) {  // HHMMSS
  const std::int64_t s = ((t % 86400) + 86400) % 86400;
  return two(static_cast<unsigned>(s / 3600)) + two(static_cast<unsigned>(s / 60 % 60)) + two(static_cast<unsigned>(s % 60));
}

std::string number_text(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

void write_record(std::string& out, const Qso& q) {
  field(out, "CALL", q.call);
  field(out, "QSO_DATE", date_text(q.time_on));
  field(out, "TIME_ON", time_text(q.time_on));
  field(out, "MODE", q.mode);
  field(out, "SUBMODE", q.submode);
  field(out, "BAND", q.band);
  if (q.uplink_hz > 0) field(out, "FREQ", mhz_text(q.uplink_hz));
  field(out, "BAND_RX", q.band_rx);
  if (q.downlink_hz > 0) field(out, "FREQ_RX", mhz_text(q.downlink_hz));
  field(out, "PROP_MODE", "SAT");
  field(out, "SAT_NAME", q.lotw_name);
  field(out, "SAT_MODE", sat_mode(q.uplink_hz, q.downlink_hz));
  field(out, "GRIDSQUARE", q.grid);
  field(out, "MY_GRIDSQUARE", q.my_grid);
  field(out, "STATION_CALLSIGN", q.station_call);
  field(out, "RST_SENT", q.rst_sent);
  field(out, "RST_RCVD", q.rst_rcvd);
  if (q.power_w > 0) field(out, "TX_PWR", number_text(q.power_w));
  field(out, "COMMENT", q.note);
  field(out, "APP_TRAKBOX_SAT", q.sat_name);
  if (q.norad > 0) field(out, "APP_TRAKBOX_NORAD", std::to_string(q.norad));
  if (q.uplink_tuned_hz > 0) field(out, "APP_TRAKBOX_FREQ_TUNED", std::to_string(q.uplink_tuned_hz));
  if (q.downlink_tuned_hz > 0) field(out, "APP_TRAKBOX_FREQ_RX_TUNED", std::to_string(q.downlink_tuned_hz));
  field(out, "APP_TRAKBOX_SOURCE", source_name(q.source));
  out += "<EOR>\n";
}

}  // namespace

std::string adif_record(const Qso& q) {
  std::string out;
  write_record(out, q);
  return out;
}

namespace {

// One field of the file: its upper-cased name and its bytes.
struct Field {
  std::string name;
  std::string_view data;
};

// The next field or marker at or after `at`: the name, and for a field with a length its data.
// Empty name at the end of the text; an error names what is wrong.
struct Scan {
  std::string_view text;
  std::size_t at = 0;
  std::string error;
  bool next(Field& f) {
    const auto lt = text.find('<', at);
    if (lt == std::string_view::npos) {
      at = text.size();
      f = {};
      return true;
    }
    const auto gt = text.find('>', lt);
    if (gt == std::string_view::npos) return error = "a '<' without its '>'", false;
    const std::string_view spec = text.substr(lt + 1, gt - lt - 1);
    const auto colon = spec.find(':');
    f.name = text::upper(text::trim(spec.substr(0, colon), text::kWhitespace));
    if (f.name.empty()) return error = "a field without a name", false;
    for (const char c : f.name)
      if (!(text::is_digit(c) || (c >= 'A' && c <= 'Z') || c == '_'))
        return error = "'" + f.name.substr(0, 40) + "' is not a field name", false;
    at = gt + 1;
    f.data = {};
    if (colon == std::string_view::npos) {  // <EOR>, <EOH>
      if (f.name == "EOR" || f.name == "EOH") return true;
      return error = f.name + ": a field without a length", false;
    }
    std::string_view len = spec.substr(colon + 1);
    if (const auto c2 = len.find(':'); c2 != std::string_view::npos) len = len.substr(0, c2);  // :TYPE
    const auto n = text::parse_integer<std::size_t>(len);
    if (!n || len.front() == '+') return error = f.name + ": '" + std::string(len.substr(0, 20)) + "' is not a length", false;
    if (*n > text.size() - at) return error = f.name + ": its length " + std::to_string(*n) + " runs past the end of the file", false;
    f.data = text.substr(at, *n);
    at += *n;
    return true;
  }
};

std::optional<std::int64_t> parse_date(std::string_view d) {
  if (d.size() != 8) return std::nullopt;
  const std::string iso = std::string(d.substr(0, 4)) + "-" + std::string(d.substr(4, 2)) + "-" + std::string(d.substr(6, 2));
  return parse_utc(iso);
}

std::optional<std::int64_t> parse_time(std::string_view t) {
  if (t.size() != 4 && t.size() != 6) return std::nullopt;
  for (const char c : t)
    if (!text::is_digit(c)) return std::nullopt;
  const int h = (t[0] - '0') * 10 + (t[1] - '0'), m = (t[2] - '0') * 10 + (t[3] - '0');
  const int s = t.size() == 6 ? (t[4] - '0') * 10 + (t[5] - '0') : 0;
  if (h > 23 || m > 59 || s > 59) return std::nullopt;
  return h * 3600 + m * 60 + s;
}

bool printable(std::string_view s) {
  for (const char c : s)
    if (c < 0x20 || c > 0x7e) return false;
  return true;
}

// Why a record is not a satellite QSO, or nothing when it is one.
std::optional<std::string> not_satellite(const std::map<std::string, std::string_view>& f) {
  const auto prop = f.find("PROP_MODE");
  const std::string mode = prop == f.end() ? std::string{} : text::upper(prop->second);
  if (!mode.empty() && mode != "SAT") return "PROP_MODE " + mode + ", not SAT";
  if (mode.empty() && !f.count("SAT_NAME")) return "neither PROP_MODE SAT nor SAT_NAME";
  return std::nullopt;
}

// A record's fields into a QSO; the refusal names the field.
std::string to_qso(const std::map<std::string, std::string_view>& f, Qso& q) {
  const auto get = [&](const char* name) -> std::string_view {
    const auto it = f.find(name);
    return it == f.end() ? std::string_view{} : it->second;
  };
  for (const auto& [name, value] : f)
    if (!printable(value)) return name + ": printable ASCII only (an .adi file's text fields)";
  q = Qso{};
  q.source = Source::import;
  q.call = text::upper(get("CALL"));
  if (auto e = check_callsign("CALL", q.call)) return *e;
  const auto date = parse_date(get("QSO_DATE"));
  if (!date) return "QSO_DATE: '" + std::string(get("QSO_DATE")) + "' is not a date (YYYYMMDD)";
  const auto time = parse_time(get("TIME_ON"));
  if (!time) return "TIME_ON: '" + std::string(get("TIME_ON")) + "' is not a time (HHMM or HHMMSS)";
  q.time_on = *date + *time;
  q.lotw_name = std::string(get("SAT_NAME"));
  q.sat_name = f.count("APP_TRAKBOX_SAT") ? std::string(get("APP_TRAKBOX_SAT")) : q.lotw_name;
  q.mode = text::upper(get("MODE"));
  if (q.mode == "SAT") return "MODE: the emission (FM, SSB, CW), not SAT";
  q.submode = text::upper(get("SUBMODE"));
  for (const auto& [name, hz] : {std::pair<const char*, std::int64_t*>{"FREQ", &q.uplink_hz}, {"FREQ_RX", &q.downlink_hz}}) {
    if (get(name).empty()) continue;
    const auto v = parse_mhz_hz(get(name));
    if (!v) return std::string(name) + ": '" + std::string(get(name)) + "' is not a frequency in MHz (at most 6 decimals)";
    *hz = *v;
  }
  for (const auto& [name, hz] : {std::pair<const char*, std::int64_t*>{"APP_TRAKBOX_FREQ_TUNED", &q.uplink_tuned_hz},
                                 {"APP_TRAKBOX_FREQ_RX_TUNED", &q.downlink_tuned_hz}}) {
    if (get(name).empty()) continue;
    const auto v = text::parse_integer<std::int64_t>(get(name));
    if (!v || *v < 0) return std::string(name) + ": '" + std::string(get(name)) + "' is not a frequency in Hz";
    *hz = *v;
  }
  for (const auto& [name, band, hz] : {std::tuple<const char*, std::string*, std::int64_t>{"BAND", &q.band, q.uplink_hz},
                                       {"BAND_RX", &q.band_rx, q.downlink_hz}}) {
    *band = text::lower(get(name));
    if (band->empty()) continue;
    const auto edges = band_edges(*band);
    if (!edges) return std::string(name) + ": '" + *band + "' is not an ADIF band";
    if (hz > 0 && (hz < edges->first || hz > edges->second))
      return std::string(name) + ": " + *band + " does not hold " + mhz_text(hz) + " MHz";
  }
  q.grid = std::string(get("GRIDSQUARE"));
  q.my_grid = std::string(get("MY_GRIDSQUARE"));
  if (!q.grid.empty())
    if (auto e = check_grid("GRIDSQUARE", q.grid)) return *e;
  if (!q.my_grid.empty())
    if (auto e = check_grid("MY_GRIDSQUARE", q.my_grid)) return *e;
  q.station_call = text::upper(f.count("STATION_CALLSIGN") ? get("STATION_CALLSIGN") : get("OPERATOR"));
  if (!q.station_call.empty())
    if (auto e = check_callsign(f.count("STATION_CALLSIGN") ? "STATION_CALLSIGN" : "OPERATOR", q.station_call)) return *e;
  q.rst_sent = std::string(get("RST_SENT"));
  q.rst_rcvd = std::string(get("RST_RCVD"));
  if (!q.rst_sent.empty())
    if (auto e = check_rst("RST_SENT", q.rst_sent)) return *e;
  if (!q.rst_rcvd.empty())
    if (auto e = check_rst("RST_RCVD", q.rst_rcvd)) return *e;
  if (!get("TX_PWR").empty()) {
    const auto p = text::parse_double(get("TX_PWR"));
    if (!p || *p < 0 || *p > 100000) return "TX_PWR: '" + std::string(get("TX_PWR")) + "' is not a power in W (0 to 100000)";
    q.power_w = *p;
  }
  q.note = std::string(get("COMMENT"));
  if (!get("APP_TRAKBOX_NORAD").empty()) {
    const auto n = text::parse_integer<int>(get("APP_TRAKBOX_NORAD"));
    if (!n || *n < 0 || *n > 999999) return "APP_TRAKBOX_NORAD: '" + std::string(get("APP_TRAKBOX_NORAD")) + "' is not a catalog number";
    q.norad = *n;
  }
  if (!get("APP_TRAKBOX_SOURCE").empty()) {
    const auto s = source_from_name(get("APP_TRAKBOX_SOURCE"));
    if (!s) return "APP_TRAKBOX_SOURCE: '" + std::string(get("APP_TRAKBOX_SOURCE")) + "' is not web, menus, host, cli or import";
    q.source = *s;
  }
  q = normalized(std::move(q));
  if (auto e = check_qso(q)) return *e;
  return {};
}

}  // namespace

std::string mhz_text(std::int64_t hz) {
  std::string frac = std::to_string(hz % 1'000'000);
  return std::to_string(hz / 1'000'000) + "." + std::string(6 - frac.size(), '0') + frac;
}

std::optional<std::int64_t> parse_mhz_hz(std::string_view s) {
  s = text::trim(s, text::kWhitespace);
  const auto dot = s.find('.');
  const std::string_view whole = s.substr(0, dot);
  std::string_view frac = dot == std::string_view::npos ? std::string_view{} : s.substr(dot + 1);
  while (frac.size() > 6 && frac.back() == '0') frac.remove_suffix(1);  // 145.9650000
  if (whole.empty() || whole.size() > 6 || frac.size() > 6) return std::nullopt;
  for (const char c : whole)
    if (!text::is_digit(c)) return std::nullopt;
  for (const char c : frac)
    if (!text::is_digit(c)) return std::nullopt;
  std::int64_t hz = *text::parse_integer<std::int64_t>(whole) * 1'000'000;
  std::int64_t scale = 100'000;
  for (const char c : frac) {
    hz += (c - '0') * scale;
    scale /= 10;
  }
  return hz;
}

AdifExport write_adif(const std::vector<Qso>& qsos, std::string_view program_version, std::int64_t created) {
  AdifExport r;
  r.text = "trakbox satellite log, ADIF 3.1.4\n";
  field(r.text, "ADIF_VER", "3.1.4");
  field(r.text, "PROGRAMID", "trakbox");
  field(r.text, "PROGRAMVERSION", program_version);
  field(r.text, "CREATED_TIMESTAMP", date_text(created) + " " + time_text(created));
  r.text += "<EOH>\n";
  for (const Qso& q : qsos) {
    if (q.deleted) continue;
    if (q.lotw_name.empty())
      r.warnings.push_back("QSO " + std::to_string(q.id) + " (" + q.call + ", " +
                           (q.sat_name.empty() ? std::string("no satellite") : q.sat_name) + "): no LoTW name" +
                           (q.norad > 0 ? " for NORAD " + std::to_string(q.norad) : std::string()) +
                           "; SAT_NAME left out, LoTW will not match it as a satellite QSO");
    if (q.station_call.empty())
      r.warnings.push_back("QSO " + std::to_string(q.id) + " (" + q.call + "): no STATION_CALLSIGN (logged before the "
                           "station's callsign was set); TQSL asks which callsign it was made with");
    write_record(r.text, q);
  }
  return r;
}

AdifRead read_adif(std::string_view text_in) {
  AdifRead r;
  Scan scan{text_in, 0, {}};
  Field f;
  const auto fail = [&](const std::string& where, const std::string& why) {
    AdifRead bad;
    bad.error = where + ": " + why;
    return bad;
  };
  if (text_in.empty() || text_in.front() != '<') {  // a header: up to <EOH>
    for (;;) {
      if (!scan.next(f)) return fail("header", scan.error);
      if (f.name.empty()) return fail("header", "no <EOH> (a file that does not begin with '<' has a header)");
      if (f.name == "EOH") break;
      if (f.name == "EOR") return fail("header", "<EOR> before <EOH>");
    }
  }
  std::map<std::string, std::string_view> fields;
  std::size_t record = 1;
  for (;;) {
    if (!scan.next(f)) return fail("record " + std::to_string(record), scan.error);
    if (f.name.empty()) break;
    if (f.name == "EOH") return fail("record " + std::to_string(record), "<EOH> after the header");
    if (f.name == "EOR") {
      if (auto why = not_satellite(fields)) {
        const auto call = fields.find("CALL");
        std::string shown = call == fields.end() || !printable(call->second) ? std::string{} : text::upper(call->second);
        r.skipped.push_back({record, std::move(shown), std::move(*why)});
        fields.clear();
        ++record;
        continue;
      }
      Qso q;
      if (std::string e = to_qso(fields, q); !e.empty()) return fail("record " + std::to_string(record), e);
      r.qsos.push_back(std::move(q));
      fields.clear();
      ++record;
      continue;
    }
    if (!fields.emplace(f.name, f.data).second)
      return fail("record " + std::to_string(record), f.name + ": the field appears twice");
  }
  if (!fields.empty()) return fail("record " + std::to_string(record), "no <EOR> after its fields");
  return r;
}

}  // namespace tb::logbook
