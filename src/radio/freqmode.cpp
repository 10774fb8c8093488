#include "radio/freqmode.h"
#include "util/text.h"

#include <cstdlib>
#include <map>

namespace tb::radio {

namespace {

constexpr int kFields = 7;

bool is_space(char c) { return c == ' ' || c == '\t'; }

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    if (i >= line.size()) break;
    std::size_t j = i;
    while (j < line.size() && !is_space(line[j])) ++j;
    out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

using text::lower;

constexpr const char* kExpectFrequency =
    "a frequency in MHz such as 435.120, optionally with a converter offset as in "
    "2400.730/-2256.000";

constexpr const char* kExpectUplink =
    "a frequency in MHz such as 145.900, up to 4 separated by commas (no spaces), optionally with a "
    "converter offset after the last as in 1268.100,1268.200/-1124.000";

constexpr const char* kExpectBand = "LOW-HIGH in MHz, low first, such as 435.610-435.670";

std::optional<std::pair<Hz, Hz>> parse_band(std::string_view t) {
  const std::size_t dash = t.find('-', 1);
  if (dash == std::string_view::npos) return std::nullopt;
  const auto lo = parse_frequency_field(t.substr(0, dash));
  const auto hi = parse_frequency_field(t.substr(dash + 1));
  if (!lo || !hi || lo->offset_hz || hi->offset_hz || lo->rf_hz <= 0 || lo->rf_hz > hi->rf_hz) return std::nullopt;
  return std::pair{lo->rf_hz, hi->rf_hz};
}

// A CTCSS tone in Hz with at most one decimal, 60.0 to 300.0: tenths of Hz.
std::optional<int> parse_tone(std::string_view t) {
  const auto hz = parse_mhz(t);   // MHz digits read as Hz: 67.0 -> 67,000,000
  if (!hz || *hz % 100000 != 0 || *hz < 60'000'000 || *hz > 300'000'000) return std::nullopt;
  return static_cast<int>(*hz / 100000);
}

// options[k] is field first_field + k of the line.
template <class Problem>
void parse_options(const std::vector<std::string_view>& options, int first_field, FreqModeRecord& rec,
                   Problem& problem_at) {
  SatelliteRadio& r = rec.radio;
  int field = first_field - 1;
  bool bad_band = false;
  auto problem = [&](int, std::string_view found, std::string expected) { problem_at(field, found, std::move(expected)); };
  for (std::string_view o : options) {
    ++field;
    const std::size_t eq = o.find('=');
    const std::string key = lower(o.substr(0, eq));
    const std::string_view value = o.substr(eq + 1);
    if (key == "down" || key == "up") {
      const auto band = parse_band(value);
      if (!band) {
        bad_band = true;
        problem(0, o, std::string(key) + "=" + kExpectBand);
        continue;
      }
      (key == "down" ? r.downlink_low_hz : r.uplink_low_hz) = band->first;
      (key == "down" ? r.downlink_high_hz : r.uplink_high_hz) = band->second;
    } else if (key == "inv") {
      const std::string v = lower(value);
      if (v == "y" || v == "n") r.inverting = v == "y";
      else problem(0, o, "inv=y (inverting transponder) or inv=n");
    } else if (key == "tone") {
      const auto tone = parse_tone(value);
      if (tone) r.ctcss_tenths_hz = *tone;
      else problem(0, o, "tone=HZ, a CTCSS tone from 60.0 to 300.0 Hz such as tone=67.0");
    } else if (key == "arm") {
      const auto tone = parse_tone(value);
      if (tone) rec.arm_tone_tenths_hz = *tone;
      else problem(0, o, "arm=HZ, the arming tone from 60.0 to 300.0 Hz such as arm=74.4");
    } else if (key == "mode") {
      if (const std::string why = mode_name_problem(value); why.empty()) rec.mode = std::string(value);
      else problem(0, o, "mode=NAME: " + why);
    } else {
      problem(0, o, "an option down=LOW-HIGH, up=LOW-HIGH, inv=y|n, tone=HZ, arm=HZ or mode=NAME");
    }
  }
  const bool any_band = r.downlink_low_hz || r.uplink_low_hz;
  field = first_field;
  if (any_band && !bad_band && !r.has_passbands())
    problem(0, r.downlink_low_hz ? "down=" : "up=", "both down=LOW-HIGH and up=LOW-HIGH for a transponder");
}

// A satellite once per mode: its name with the mode's, case aside ("" for the line without one).
// What was expected when the record's name and mode were given on an earlier line; else it is noted.
std::optional<std::string> given_before(std::map<std::string, int, std::less<>>& seen, const FreqModeRecord& rec) {
  const std::string key = rec.name + "\n" + lower(rec.mode);
  const auto it = seen.find(key);
  if (it == seen.end()) {
    seen.emplace(key, rec.line);
    return std::nullopt;
  }
  const std::string where = " (it is on line " + std::to_string(it->second) + ")";
  return rec.mode.empty() ? "a satellite name not already given" + where
                          : "a mode not already given for " + rec.name + where;
}

}  // namespace

const char* freqmode_field_name(int field) {
  switch (field) {
    case 1: return "satellite name";
    case 2: return "downlink frequency";
    case 3: return "uplink frequency";
    case 4: return "downlink mode";
    case 5: return "uplink mode";
    case 6: return "Doppler mode";
    case 7: return "phase display";
    case 8: return "reverse flag";
    default: return "line";
  }
}

std::string FreqModeProblem::message() const {
  std::string m = "line " + std::to_string(line);
  if (field > 0)
    m += ", field " + std::to_string(field) + " (" + (option ? "option" : freqmode_field_name(field)) + ")";
  m += ": found \"" + found + "\", expected " + expected;
  return m;
}

std::optional<Hz> parse_mhz(std::string_view t) {
  if (t.empty()) return std::nullopt;
  bool negative = false;
  if (t.front() == '+' || t.front() == '-') {
    negative = t.front() == '-';
    t.remove_prefix(1);
  }
  const std::size_t dot = t.find('.');
  std::string_view whole = t.substr(0, dot);
  std::string_view frac = dot == std::string_view::npos ? std::string_view{} : t.substr(dot + 1);
  if (whole.empty() && frac.empty()) return std::nullopt;
  if (whole.size() > 7) return std::nullopt;  // 10 THz is no radio frequency; keeps int64 safe
  Hz mhz = 0;
  for (char c : whole) {
    if (c < '0' || c > '9') return std::nullopt;
    mhz = mhz * 10 + (c - '0');
  }
  Hz hz = 0;
  Hz scale = 100000;  // first decimal is 100 kHz
  for (std::size_t i = 0; i < frac.size(); ++i) {
    const char c = frac[i];
    if (c < '0' || c > '9') return std::nullopt;
    if (i < 6) {
      hz += (c - '0') * scale;
      scale /= 10;
    } else if (c != '0') {
      return std::nullopt;  // finer than 1 Hz
    }
  }
  const Hz total = mhz * 1000000 + hz;
  return negative ? -total : total;
}

std::optional<FrequencyField> parse_frequency_field(std::string_view t) {
  const std::size_t slash = t.find('/');
  FrequencyField f;
  std::string_view rf = t.substr(0, slash);
  if (rf.empty() || rf.front() == '-') return std::nullopt;
  auto v = parse_mhz(rf);
  if (!v) return std::nullopt;
  f.rf_hz = *v;
  if (slash != std::string_view::npos) {
    auto o = parse_mhz(t.substr(slash + 1));
    if (!o) return std::nullopt;
    f.offset_hz = *o;
  }
  return f;
}

std::optional<UplinkField> parse_uplink_field(std::string_view t) {
  const std::size_t slash = t.find('/');
  UplinkField u;
  if (slash != std::string_view::npos) {
    const auto o = parse_mhz(t.substr(slash + 1));
    if (!o) return std::nullopt;
    u.offset_hz = *o;
  }
  for (std::string_view channel : text::split(t.substr(0, slash), ',')) {
    if (channel.empty() || channel.front() == '-' || u.rf_hz.size() == kMaxUplinkChannels) return std::nullopt;
    const auto v = parse_mhz(channel);
    if (!v) return std::nullopt;
    u.rf_hz.push_back(*v);
  }
  if (u.rf_hz.empty()) return std::nullopt;
  return u;
}

std::string format_mhz(Hz hz) {
  const bool negative = hz < 0;
  const Hz a = negative ? -hz : hz;
  std::string frac = std::to_string(a % 1000000);
  frac.insert(0, 6 - frac.size(), '0');
  while (frac.size() > 3 && frac.back() == '0') frac.pop_back();
  return (negative ? "-" : "") + std::to_string(a / 1000000) + "." + frac;
}

std::string format_frequency_field(Hz rf_hz, Hz offset_hz) {
  std::string s = format_mhz(rf_hz);
  if (offset_hz != 0) s += "/" + format_mhz(offset_hz);
  return s;
}

std::string format_freqmode_line(const FreqModeRecord& r) {
  const SatelliteRadio& s = r.radio;
  std::string line = r.name;
  line += " " + format_frequency_field(s.downlink_hz, s.downlink_offset_hz);
  std::string up = format_mhz(s.uplink_hz);
  for (Hz alt : s.alternate_uplinks_hz) up += "," + format_mhz(alt);
  if (s.uplink_offset_hz != 0) up += "/" + format_mhz(s.uplink_offset_hz);
  line += " " + up;
  line += " " + lower(to_string(s.downlink_mode));
  line += " " + lower(to_string(s.uplink_mode));
  line += s.doppler == DopplerControl::mic_click ? " mic" : " cat";
  line += s.lcd_ma_display ? " ma" : " no";
  if (s.reverse != ReverseAssignment::none) line += std::string(" ") + to_string(s.reverse);
  if (s.has_passbands()) {
    line += " down=" + format_mhz(s.downlink_low_hz) + "-" + format_mhz(s.downlink_high_hz);
    line += " up=" + format_mhz(s.uplink_low_hz) + "-" + format_mhz(s.uplink_high_hz);
  }
  if (s.has_passbands() || s.inverting) line += s.inverting ? " inv=y" : " inv=n";
  if (s.ctcss_tenths_hz > 0)
    line += " tone=" + std::to_string(s.ctcss_tenths_hz / 10) + "." + std::to_string(s.ctcss_tenths_hz % 10);
  if (r.arm_tone_tenths_hz > 0)
    line += " arm=" + std::to_string(r.arm_tone_tenths_hz / 10) + "." + std::to_string(r.arm_tone_tenths_hz % 10);
  if (!r.mode.empty()) line += " mode=" + r.mode;
  return line;
}

std::string write_freqmode(const std::vector<FreqModeRecord>& records) {
  std::string out;
  for (const auto& r : records) out += format_freqmode_line(r) + "\n";
  return out;
}

FreqModeParse parse_freqmode(std::string_view text) {
  FreqModeParse result;
  const std::size_t eof = text.find('\x1a');
  if (eof != std::string_view::npos) text = text.substr(0, eof);

  std::map<std::string, int, std::less<>> seen;  // name -> line
  int line_no = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find_first_of("\r\n", pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    // CR LF is one line end; CR or LF alone is one too.
    pos = end;
    if (pos < text.size() && text[pos] == '\r') {
      if (++pos < text.size() && text[pos] == '\n') ++pos;
    } else if (pos < text.size()) {
      ++pos;  // '\n'
    }
    ++line_no;

    auto fields = split_fields(line);
    if (fields.empty() || fields.front().front() == ';') continue;  // blank, or a comment
    auto problem = [&](int field, std::string_view found, std::string expected) {
      result.problems.push_back({line_no, field, std::string(found), std::move(expected)});
    };
    // trakbox's options after the record (down=LO-HI up=LO-HI inv=y|n tone=HZ): taken off the end.
    std::vector<std::string_view> options;
    while (fields.size() > kFields && fields.back().find('=') != std::string_view::npos) {
      options.insert(options.begin(), fields.back());
      fields.pop_back();
    }
    if (fields.size() != kFields && fields.size() != kFields + 1) {
      std::string expected = "7 fields (name, downlink MHz, uplink MHz, downlink mode, uplink mode, "
                             "cat/mic, ma/no) and an optional 8th, ir or kr";
      if (fields.size() > kFields + 1 && fields.size() % kFields == 0)
        expected += "; this line looks like " + std::to_string(fields.size() / kFields) +
                    " records: put each on its own line";
      problem(0, std::to_string(fields.size()) + " fields", expected);
      continue;
    }

    FreqModeRecord rec;
    rec.line = line_no;
    rec.name = std::string(fields[0]);
    const std::size_t before = result.problems.size();

    if (auto f = parse_frequency_field(fields[1])) {
      rec.radio.downlink_hz = f->rf_hz;
      rec.radio.downlink_offset_hz = f->offset_hz;
    } else {
      problem(2, fields[1], kExpectFrequency);
    }
    if (auto f = parse_uplink_field(fields[2])) {
      rec.radio.uplink_hz = f->rf_hz.front();
      rec.radio.alternate_uplinks_hz.assign(f->rf_hz.begin() + 1, f->rf_hz.end());
      rec.radio.uplink_offset_hz = f->offset_hz;
    } else {
      problem(3, fields[2], kExpectUplink);
    }
    for (int k : {3, 4}) {
      auto m = parse_mode(fields[k]);
      if (!m) {  // the 1994 manual's four modes, and cw of the later firmware
        problem(k + 1, fields[k], "usb, lsb, fm, cw or none");
        continue;
      }
      (k == 3 ? rec.radio.downlink_mode : rec.radio.uplink_mode) = *m;
    }
    const std::string doppler = lower(fields[5]);
    if (doppler == "cat") rec.radio.doppler = DopplerControl::cat;
    else if (doppler == "mic") rec.radio.doppler = DopplerControl::mic_click;
    else problem(6, fields[5], "cat or mic");
    const std::string phase = lower(fields[6]);
    if (phase == "ma") rec.radio.lcd_ma_display = true;
    else if (phase == "no") rec.radio.lcd_ma_display = false;
    else problem(7, fields[6], "ma or no");
    if (fields.size() > kFields) {
      const std::string flag = lower(fields[7]);
      if (flag == "ir") rec.radio.reverse = ReverseAssignment::icom_main_sub;
      else if (flag == "kr") rec.radio.reverse = ReverseAssignment::kenwood_vfo;
      else problem(8, fields[7], "ir (Icom main/sub reversed), kr (Kenwood VFOs reversed) or nothing");
    }

    auto option_problem = [&](int field, std::string_view found, std::string expected) {
      result.problems.push_back({line_no, field, std::string(found), std::move(expected), true});
    };
    parse_options(options, static_cast<int>(fields.size()) + 1, rec, option_problem);
    if (const auto again = given_before(seen, rec)) problem(1, fields[0], *again);

    if (result.problems.size() == before) result.records.push_back(std::move(rec));
  }
  return result;
}

}  // namespace tb::radio
