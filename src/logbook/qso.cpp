#include "logbook/qso.h"

#include <array>
#include <cmath>

#include "util/civil_date.h"
#include "util/text.h"

namespace tb::logbook {
namespace {

constexpr bool is_upper(char c) { return c >= 'A' && c <= 'Z'; }
constexpr bool is_alnum_upper(char c) { return is_upper(c) || text::is_digit(c); }

struct Band {
  std::string_view name;
  std::int64_t lo, hi;
  std::string_view letter;  // the satellite mode letter ("" none)
};
// ADIF 3.1.4's band enumeration (the amateur bands a satellite uses and those around them).
constexpr std::array<Band, 23> kBands{{
    {"160m", 1'800'000, 2'000'000, ""},          {"80m", 3'500'000, 4'000'000, ""},
    {"60m", 5'060'000, 5'450'000, ""},           {"40m", 7'000'000, 7'300'000, ""},
    {"30m", 10'100'000, 10'150'000, ""},         {"20m", 14'000'000, 14'350'000, ""},
    {"17m", 18'068'000, 18'168'000, ""},         {"15m", 21'000'000, 21'450'000, "H"},
    {"12m", 24'890'000, 24'990'000, ""},         {"10m", 28'000'000, 29'700'000, "A"},
    {"6m", 50'000'000, 54'000'000, ""},          {"4m", 70'000'000, 71'000'000, ""},
    {"2m", 144'000'000, 148'000'000, "V"},       {"1.25m", 222'000'000, 225'000'000, ""},
    {"70cm", 420'000'000, 450'000'000, "U"},     {"33cm", 902'000'000, 928'000'000, ""},
    {"23cm", 1'240'000'000, 1'300'000'000, "L"}, {"13cm", 2'300'000'000, 2'450'000'000, "S"},
    {"9cm", 3'300'000'000, 3'500'000'000, "S2"}, {"6cm", 5'650'000'000, 5'925'000'000, "C"},
    {"3cm", 10'000'000'000, 10'500'000'000, "X"}, {"1.25cm", 24'000'000'000, 24'250'000'000, "K"},
    {"6mm", 47'000'000'000, 47'200'000'000, "R"},
}};

const Band* band_at(std::int64_t hz) {
  for (const Band& b : kBands)
    if (hz >= b.lo && hz <= b.hi) return &b;
  return nullptr;
}

// ADIF 3.1.4's Mode enumeration (the MODE field; SUBMODEs such as USB, FT4 or C4FM belong to one).
constexpr std::array<std::string_view, 46> kModes{
    "AM",     "ARDOP",  "ATV",   "CHIP",  "CLO",    "CONTESTI", "CW",     "DIGITALVOICE", "DOMINO", "DYNAMIC",
    "FAX",    "FM",     "FSK441", "FT8",  "HELL",   "ISCAT",    "JT4",    "JT6M",         "JT9",    "JT44",
    "JT65",   "MFSK",   "MSK144", "MT63", "OLIVIA", "OPERA",    "PAC",    "PAX",          "PKT",    "PSK",
    "PSK2K",  "Q15",    "QRA64",  "ROS",  "RTTY",   "RTTYM",    "SSB",    "SSTV",         "T10",    "THOR",
    "THRB",   "TOR",    "V4",     "VOI",  "WINMOR", "WSPR"};

// The mode a well-known SUBMODE belongs to ("" for none), for the refusal's hint.
std::string_view mode_of_submode(std::string_view m) {
  for (const std::string_view s : {"FT4", "FST4", "JS8", "Q65", "FSQCALL", "JTMS"})
    if (m == s) return "MFSK";
  for (const std::string_view s : {"C4FM", "DMR", "DSTAR", "FREEDV", "M17"})
    if (m == s) return "DIGITALVOICE";
  for (const std::string_view s : {"PSK31", "PSK63", "PSK125", "BPSK31", "QPSK31"})
    if (m == s) return "PSK";
  return {};
}

bool printable_ascii(std::string_view s) {
  for (const char c : s)
    if (c < 0x20 || c > 0x7e) return false;
  return true;
}

}  // namespace

std::string_view source_name(Source s) {
  switch (s) {
    case Source::web: return "web";
    case Source::menus: return "menus";
    case Source::host: return "host";
    case Source::cli: return "cli";
    case Source::import: return "import";
  }
  return "cli";
}

std::optional<Source> source_from_name(std::string_view name) {
  for (const Source s : {Source::web, Source::menus, Source::host, Source::cli, Source::import})
    if (text::iequals(name, source_name(s))) return s;
  return std::nullopt;
}

std::optional<std::string> check_callsign(std::string_view field, std::string_view call) {
  const std::string f(field);
  if (call.empty()) return f + ": a callsign is needed";
  if (call.size() < 3 || call.size() > 20)
    return f + ": '" + std::string(call) + "' is not a callsign (3 to 20 characters)";
  bool digit = false, letter = false;
  for (std::size_t i = 0; i < call.size(); ++i) {
    const char c = text::to_upper(call[i]);
    if (c == '/') {
      if (i == 0 || i + 1 == call.size() || call[i - 1] == '/')
        return f + ": '" + std::string(call) + "' is not a callsign (a '/' only between parts)";
      continue;
    }
    if (!is_alnum_upper(c))
      return f + ": '" + std::string(call) + "' is not a callsign (letters, digits and '/' only)";
    (text::is_digit(c) ? digit : letter) = true;
  }
  if (!digit || !letter) return f + ": '" + std::string(call) + "' is not a callsign (it needs a letter and a digit)";
  return std::nullopt;
}

std::optional<std::string> check_grid(std::string_view field, std::string_view grid) {
  const auto bad = [&] {
    return std::string(field) + ": '" + std::string(grid) +
           "' is not a Maidenhead locator (like FN31 or FN31pr: two letters A-R, two digits, two letters A-X, two digits)";
  };
  if (grid.size() != 2 && grid.size() != 4 && grid.size() != 6 && grid.size() != 8) return bad();
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const char c = text::to_upper(grid[i]);
    const bool ok = (i < 2) ? (c >= 'A' && c <= 'R') : (i < 4 || i >= 6) ? text::is_digit(c) : (c >= 'A' && c <= 'X');
    if (!ok) return bad();
  }
  return std::nullopt;
}

std::optional<std::string> check_rst(std::string_view field, std::string_view rst) {
  const bool ok = (rst.size() == 2 || rst.size() == 3) && rst[0] >= '1' && rst[0] <= '5' && rst[1] >= '1' &&
                  rst[1] <= '9' && (rst.size() == 2 || (rst[2] >= '1' && rst[2] <= '9'));
  if (ok) return std::nullopt;
  return std::string(field) + ": '" + std::string(rst) + "' is not a report (RS like 59 or RST like 599)";
}

Qso normalized(Qso q) {
  q.call = text::upper(text::trim(q.call, text::kWhitespace));
  q.station_call = text::upper(text::trim(q.station_call, text::kWhitespace));
  for (std::string* g : {&q.grid, &q.my_grid}) {
    std::string s(text::trim(*g, text::kWhitespace));
    for (std::size_t i = 0; i < s.size(); ++i) s[i] = (i >= 4 && i < 6) ? text::to_lower(s[i]) : text::to_upper(s[i]);
    *g = s;
  }
  q.mode = adif_mode(q.mode);
  q.submode = text::upper(text::trim(q.submode, text::kWhitespace));
  if (q.band.empty()) q.band = band_of(q.uplink_hz);
  if (q.band_rx.empty()) q.band_rx = band_of(q.downlink_hz);
  return q;
}

std::optional<std::string> check_qso(const Qso& q) {
  if (auto e = check_callsign("call", q.call)) return e;
  if (!q.grid.empty())
    if (auto e = check_grid("grid", q.grid)) return e;
  if (!q.my_grid.empty())
    if (auto e = check_grid("my_grid", q.my_grid)) return e;
  if (!q.station_call.empty())
    if (auto e = check_callsign("station_call", q.station_call)) return e;
  if (!q.rst_sent.empty())
    if (auto e = check_rst("rst_sent", q.rst_sent)) return e;
  if (!q.rst_rcvd.empty())
    if (auto e = check_rst("rst_rcvd", q.rst_rcvd)) return e;
  if (q.time_on < 0 || q.time_on > days_from_civil(10000, 1, 1) * 86400)
    return std::string("time_on: not a time between 1970 and 9999");
  if (q.mode == "SAT") return std::string("mode: the emission (FM, SSB, CW), not SAT");
  if (auto e = check_mode(q.mode)) return e;
  if (q.submode.size() > 20) return std::string("submode: at most 20 characters");
  for (const auto& [name, value] : {std::pair<const char*, const std::string*>{"mode", &q.mode},
                                    {"submode", &q.submode}, {"sat_name", &q.sat_name}, {"lotw_name", &q.lotw_name},
                                    {"note", &q.note}}) {
    if (!printable_ascii(*value)) return std::string(name) + ": printable ASCII only (ADIF's text fields)";
    if (value->size() > 500) return std::string(name) + ": at most 500 characters";
  }
  if (q.norad < 0 || q.norad > 999999) return std::string("norad: a catalog number 0 to 999999");
  for (const auto& [name, hz] : {std::pair<const char*, std::int64_t>{"uplink_hz", q.uplink_hz},
                                 {"downlink_hz", q.downlink_hz}, {"uplink_tuned_hz", q.uplink_tuned_hz},
                                 {"downlink_tuned_hz", q.downlink_tuned_hz}})
    if (hz < 0 || hz > 300'000'000'000) return std::string(name) + ": a frequency 0 to 300 GHz in Hz";
  for (const auto& [name, b] : {std::pair<const char*, const std::string*>{"band", &q.band}, {"band_rx", &q.band_rx}})
    if (!b->empty() && !band_edges(*b)) return std::string(name) + ": '" + *b + "' is not an ADIF band";
  if (!(q.power_w >= 0 && q.power_w <= 100000)) return std::string("power: 0 to 100000 W");
  return std::nullopt;
}

std::optional<std::pair<std::string, std::string>> adif_of_mode_name(std::string_view name) {
  const std::string u = text::upper(name);
  if (is_adif_mode(u)) return std::pair{u, std::string()};
  if (const std::string_view parent = mode_of_submode(u); !parent.empty()) return std::pair{std::string(parent), u};
  if (u == "APRS") return std::pair{std::string("PKT"), std::string()};
  return std::nullopt;
}

bool is_adif_mode(std::string_view mode) {
  for (const std::string_view m : kModes)
    if (m == mode) return true;
  return false;
}

std::optional<std::string> check_mode(std::string_view mode) {
  if (mode.empty() || is_adif_mode(mode)) return std::nullopt;
  const std::string shown = printable_ascii(mode) && mode.size() <= 40 ? std::string(mode) : std::string("that text");
  const std::string_view parent = mode_of_submode(mode);
  if (!parent.empty())
    return "mode: '" + shown + "' is a submode in ADIF; log it as " + std::string(parent);
  return "mode: '" + shown + "' is not one of ADIF's modes (FM, SSB, CW, AM, FT8, MFSK, PSK, RTTY, SSTV, DIGITALVOICE, ...)";
}

std::string band_of(std::int64_t hz) {
  const Band* b = band_at(hz);
  return b ? std::string(b->name) : std::string();
}

std::optional<std::pair<std::int64_t, std::int64_t>> band_edges(std::string_view band) {
  for (const Band& b : kBands)
    if (text::iequals(b.name, band)) return std::pair{b.lo, b.hi};
  return std::nullopt;
}

std::string sat_mode(std::int64_t uplink_hz, std::int64_t downlink_hz) {
  const Band* up = band_at(uplink_hz);
  const Band* down = band_at(downlink_hz);
  if (!up || !down || up->letter.empty() || down->letter.empty()) return {};
  return std::string(up->letter) + "/" + std::string(down->letter);
}

std::string adif_mode(std::string_view radio_mode) {
  const std::string m = text::upper(text::trim(radio_mode, text::kWhitespace));
  if (m == "USB" || m == "LSB" || m == "SSB") return "SSB";
  if (m == "CW" || m == "CWR" || m == "CW-R" || m == "CW-U" || m == "CW-L") return "CW";
  if (m == "FM" || m == "NFM" || m == "FMN" || m == "WFM") return "FM";
  return m;
}

std::int64_t days_from_civil(int y, unsigned m, unsigned d) { return civil::days_from_civil(y, m, d); }

void civil_from_days(std::int64_t z, int& y, unsigned& m, unsigned& d) {
  const civil::Date c = civil::civil_from_days(z);
  y = static_cast<int>(c.y);
  m = c.m;
  d = c.d;
}

std::string utc_text(std::int64_t t) {
  const std::int64_t days = (t >= 0 ? t : t - 86399) / 86400;
  const std::int64_t s = t - days * 86400;
  int y;
  unsigned m, d;
  civil_from_days(days, y, m, d);
  char buf[40];
  std::snprintf(buf, sizeof buf, "%04d-%02u-%02u %02d:%02d:%02d", y, m, d, static_cast<int>(s / 3600),
                static_cast<int>(s / 60 % 60), static_cast<int>(s % 60));
  return buf;
}

std::optional<std::int64_t> parse_utc(std::string_view s) {
  s = text::trim(s, text::kWhitespace);
  if (!s.empty() && (s.back() == 'Z' || s.back() == 'z')) s.remove_suffix(1);
  const auto num = [&](std::size_t at, std::size_t n) -> std::optional<int> {
    if (at + n > s.size()) return std::nullopt;
    int v = 0;
    for (std::size_t i = at; i < at + n; ++i) {
      if (!text::is_digit(s[i])) return std::nullopt;
      v = v * 10 + (s[i] - '0');
    }
    return v;
  };
  if (s.size() != 10 && s.size() != 16 && s.size() != 19) return std::nullopt;
  const auto y = num(0, 4), mo = num(5, 2), d = num(8, 2);
  if (!y || !mo || !d || s[4] != '-' || s[7] != '-' || *mo < 1 || *mo > 12 || *d < 1) return std::nullopt;
  static constexpr int kDays[] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (*y % 4 == 0 && *y % 100 != 0) || *y % 400 == 0;
  if (*d > kDays[*mo - 1] || (*mo == 2 && *d == 29 && !leap)) return std::nullopt;
  std::int64_t t = days_from_civil(*y, static_cast<unsigned>(*mo), static_cast<unsigned>(*d)) * 86400;
  if (s.size() == 10) return t;
  const auto h = num(11, 2), mi = num(14, 2);
  if ((s[10] != 'T' && s[10] != 't' && s[10] != ' ') || s[13] != ':' || !h || !mi || *h > 23 || *mi > 59)
    return std::nullopt;
  t += *h * 3600 + *mi * 60;
  if (s.size() == 16) return t;
  const auto sec = num(17, 2);
  if (s[16] != ':' || !sec || *sec > 59) return std::nullopt;
  return t + *sec;
}

}  // namespace tb::logbook
