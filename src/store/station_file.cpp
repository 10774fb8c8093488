#include "store/station_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "rotator/adc_model.h"
#include "store/model.h"
#include "util/text.h"

namespace tb::store {

namespace {

// Items of each line after its number (index 0 is item 2).
const char* const kNames1[] = {"callsign", "latitude", "longitude", "height", "rotor start"};
const char* const kNames2[] = {"azimuth minimum", "azimuth maximum", "elevation minimum", "elevation maximum"};
const char* const kNames3[] = {"azimuth dead band", "elevation dead band", "azimuth skew", "elevation skew"};
const char* const kNames4[] = {"CAT rig", "F/A", "Icom RX address", "Icom TX address"};
const char* const kNames5[] = {"antenna parking ON/OFF", "parking azimuth", "parking elevation", "limit ON/OFF",
                               "azimuth minimum",        "azimuth maximum", "elevation minimum", "elevation maximum"};

struct LineShape {
  const char* const* names;
  int items;  // after the line number
};
const LineShape kShapes[5] = {{kNames1, 5}, {kNames2, 4}, {kNames3, 4}, {kNames4, 4}, {kNames5, 8}};

using text::upper;
std::optional<double> to_double(std::string_view s) { return text::parse_double(s); }
std::optional<int> to_int(std::string_view s) { return text::parse_integer<int>(s); }

// "10", "2E", "2eH": one or two hex digits, an optional trailing H. Digits only: from_chars takes a
// '-', and "-4" would wrap to FC (the CI-V jam code) in the address byte.
std::optional<int> to_hex_address(std::string_view s) {
  if (!s.empty() && (s.back() == 'H' || s.back() == 'h')) s.remove_suffix(1);
  if (s.empty() || s.size() > 2) return std::nullopt;
  for (const char c : s)
    if (!std::isxdigit(static_cast<unsigned char>(c))) return std::nullopt;
  int v = 0;
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v, 16);
  if (ec != std::errc() || p != s.data() + s.size()) return std::nullopt;
  return v;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

class Parser {
 public:
  std::vector<StationFileProblem> problems;
  StationFile f;

  // A problem with item `field` of the line numbered current_number_ (the line's own number).
  void problem(int line, int field, std::string found, std::string expected) {
    problems.push_back({line, field, station_file_item_name(current_number_, field), std::move(found), std::move(expected)});
  }
  void set_number(int n) { current_number_ = n; }

  // One record: `number` is the line number it claims (1..5), `phys` its line in the upload.
  void record(int number, int phys, const std::vector<std::string_view>& items) {
    set_number(number);
    const LineShape& shape = kShapes[number - 1];
    const int given = static_cast<int>(items.size()) - 1;
    int wanted = shape.items;
    if (number == 4 && given == 2) {
      // CAT rig and F/A only: allowed for the rigs that have no addresses.
      wanted = 2;
    }
    for (int i = 0; i < std::min(given, wanted); ++i) item(number, phys, i + 2, items[static_cast<std::size_t>(i + 1)]);
    if (given < wanted) {
      problem(phys, given + 2, "", std::string("a value for ") + shape.names[given] + " (line " +
                                       std::to_string(number) + " has " + std::to_string(shape.items + 1) + " items)");
    } else if (given > wanted) {
      problem(phys, wanted + 2, std::string(items[static_cast<std::size_t>(wanted + 1)]),
              "the end of line " + std::to_string(number) + " (" + std::to_string(shape.items + 1) + " items)");
    }
    if (number == 4 && given == 2 && f.radio.rig == radio::Rig::icom && rig_ok_)
      problem(phys, 4, "", "the Icom RX and TX addresses (hex, e.g. 10 14) after the F/A item for ICOM");
    cross_checks(number, phys);
  }

 private:
  int current_number_ = 0;  // the line being read
  bool rig_ok_ = false;
  bool span_ok_[4] = {false, false, false, false};
  bool limit_ok_[4] = {false, false, false, false};

  void counts(int phys, int field, std::string_view s, rotator::limits::Counts range, int& out, const char* unit,
              bool& ok) {
    const int lo = range.lo, hi = range.hi;
    const auto v = to_int(s);
    ok = v && range.contains(*v);
    if (ok)
      out = *v;
    else
      problem(phys, field, std::string(s),
              std::string(unit) + " " + std::to_string(lo) + " to " + std::to_string(hi) + (v ? "" : " (a whole number)"));
  }

  void degrees(int phys, int field, std::string_view s, double lo, double hi, double& out, bool& ok) {
    const auto v = to_double(s);
    ok = v && *v >= lo && *v <= hi;
    if (ok)
      out = *v;
    else
      problem(phys, field, std::string(s),
              "degrees " + num(lo) + " to " + num(hi) +
                  (v && *v > hi && hi < 1023 ? " (line 5 is in degrees, not ADC counts)" : ""));
  }

  void flag(int phys, int field, std::string_view s, bool& out) {
    const std::string u = upper(s);
    if (u == "1" || u == "ON")
      out = true;
    else if (u == "0" || u == "OFF")
      out = false;
    else
      problem(phys, field, std::string(s), "1 (on) or 0 (off)");
  }

  void item(int number, int phys, int field, std::string_view s) {
    bool ok = false;
    switch (number) {
      case 1:
        switch (field) {
          case 2: {
            bool good = !s.empty() && s.size() <= 10;
            for (char c : s)
              if (!std::isalnum(static_cast<unsigned char>(c)) && c != '/' && c != '-') good = false;
            if (good)
              f.station.callsign = upper(s);
            else
              problem(phys, field, std::string(s), "a callsign of 1 to 10 letters, digits, / or -");
            break;
          }
          case 3: degrees(phys, field, s, -90.0, 90.0, f.station.lat_deg, ok); break;
          case 4: degrees(phys, field, s, -180.0, 180.0, f.station.lon_deg, ok); break;
          case 5: {
            const auto v = to_double(s);
            if (v && *v >= -500.0 && *v <= 9000.0)
              f.station.height_m = *v;
            else
              problem(phys, field, std::string(s), "metres above sea level, -500 to 9000");
            break;
          }
          case 6: {
            const std::string u = upper(s);
            if (u == "S" || u == "SOUTH")
              f.station.rotor_start = station::RotorStart::south;
            else if (u == "N" || u == "NORTH")
              f.station.rotor_start = station::RotorStart::north;
            else
              problem(phys, field, std::string(s), "S (South) or N (North)");
            break;
          }
        }
        break;
      case 2: {
        int* dst[] = {&f.rotator.az_span.min, &f.rotator.az_span.max, &f.rotator.el_span.min, &f.rotator.el_span.max};
        counts(phys, field, s, rotator::limits::kSpan, *dst[field - 2], "ADC counts", span_ok_[field - 2]);
        break;
      }
      case 3: {
        if (field <= 3)
          counts(phys, field, s, rotator::limits::kDeadBand, field == 2 ? f.rotator.az_dead_band : f.rotator.el_dead_band, "ADC counts", ok);
        else
          counts(phys, field, s, rotator::limits::kSkew, field == 4 ? f.rotator.az_skew : f.rotator.el_skew, "ADC counts", ok);
        break;
      }
      case 4:
        if (field == 2) {
          const std::string u = upper(s);
          rig_ok_ = true;
          if (u == "ICOM" || u == "I")
            f.radio.rig = radio::Rig::icom;
          else if (u == "KENWOOD" || u == "K")
            f.radio.rig = radio::Rig::kenwood;
          else if (u == "YAESU" || u == "Y")
            f.radio.rig = radio::Rig::yaesu;
          else if (u == "NONE" || u == "N")
            f.radio.rig = radio::Rig::none;
          else {
            rig_ok_ = false;
            problem(phys, field, std::string(s), "ICOM, KENWOOD, YAESU or NONE");
          }
        } else if (field == 3) {
          const std::string u = upper(s);
          if (u == "F" || u == "FULL")
            f.radio.cat_policy = radio::CatPolicy::full_orbit;
          else if (u == "A" || u == "AOS")
            f.radio.cat_policy = radio::CatPolicy::aos_only;
          else
            problem(phys, field, std::string(s), "F (full orbit) or A (AOS only)");
        } else {
          const auto v = to_hex_address(s);
          if (v && *v < 0xE0)
            (field == 4 ? f.radio.icom_rx_address : f.radio.icom_tx_address) = static_cast<std::uint8_t>(*v);
          else
            problem(phys, field, std::string(s),
                    "a CI-V address in hex, 00 to DF (e.g. 10 for an IC-275, 14 for an IC-475; E0 is TrakBox's own)");
        }
        break;
      case 5:
        switch (field) {
          case 2: flag(phys, field, s, f.rotator.parking_enabled); break;
          case 3: degrees(phys, field, s, 0.0, 360.0, f.rotator.parking.az, ok); break;
          case 4: degrees(phys, field, s, 0.0, 90.0, f.rotator.parking.el, ok); break;
          case 5: flag(phys, field, s, f.rotator.limits_enabled); break;
          case 6: degrees(phys, field, s, 0.0, 360.0, f.rotator.az_limit_min, limit_ok_[0]); break;
          case 7: degrees(phys, field, s, 0.0, 360.0, f.rotator.az_limit_max, limit_ok_[1]); break;
          case 8: degrees(phys, field, s, 0.0, 90.0, f.rotator.el_limit_min, limit_ok_[2]); break;
          case 9: degrees(phys, field, s, 0.0, 90.0, f.rotator.el_limit_max, limit_ok_[3]); break;
        }
        break;
    }
  }

  // What one item cannot say alone.
  void cross_checks(int number, int phys) {
    if (number == 2) {
      constexpr int kMinWidth = 10;  // as rotator::validate
      if (span_ok_[0] && span_ok_[1] && f.rotator.az_span.max - f.rotator.az_span.min < kMinWidth)
        problem(phys, 3, std::to_string(f.rotator.az_span.max),
                "at least " + std::to_string(f.rotator.az_span.min + kMinWidth) + ": the maximum must exceed the minimum (" +
                    std::to_string(f.rotator.az_span.min) + ") by " + std::to_string(kMinWidth) + " counts or more");
      if (span_ok_[2] && span_ok_[3] && f.rotator.el_span.max - f.rotator.el_span.min < kMinWidth)
        problem(phys, 5, std::to_string(f.rotator.el_span.max),
                "at least " + std::to_string(f.rotator.el_span.min + kMinWidth) + ": the maximum must exceed the minimum (" +
                    std::to_string(f.rotator.el_span.min) + ") by " + std::to_string(kMinWidth) + " counts or more");
    }
    if (number == 5) {
      if (limit_ok_[0] && limit_ok_[1] && f.rotator.az_limit_max - f.rotator.az_limit_min < 360.0 &&
          rotator::wrap360(f.rotator.az_limit_max - f.rotator.az_limit_min) == 0.0)
        problem(phys, 7, num(f.rotator.az_limit_max),
                "an azimuth other than the minimum (" + num(f.rotator.az_limit_min) +
                    "): the sector runs clockwise from minimum to maximum; 0 and 360 mean no limit");
      if (limit_ok_[2] && limit_ok_[3] && f.rotator.el_limit_max < f.rotator.el_limit_min)
        problem(phys, 9, num(f.rotator.el_limit_max), "at least the elevation minimum (" + num(f.rotator.el_limit_min) + ")");
    }
  }
};

}  // namespace

std::string station_file_item_name(int line, int field) {
  if (field == 1) return "line number";
  if (line < 1 || line > 5 || field < 2) return "line";
  const LineShape& s = kShapes[line - 1];
  if (field - 2 >= s.items) return "extra item";
  return s.names[field - 2];
}

std::string StationFileProblem::message() const {
  std::string m;
  if (line > 0) m = "line " + std::to_string(line);
  if (field > 0) m += (m.empty() ? "" : ", ") + std::string("item ") + std::to_string(field);
  if (!what.empty() && field > 0) m += " (" + what + ")";
  m += m.empty() ? "" : ": ";
  m += found.empty() ? std::string("found nothing") : "found \"" + found + "\"";
  m += ", expected " + expected;
  return m;
}

StationFileParse parse_station_file(std::string_view text) {
  if (const auto z = text.find('\x1a'); z != std::string_view::npos) text = text.substr(0, z);
  Parser p;
  bool seen[5] = {false, false, false, false, false};
  bool unnumbered[5] = {false, false, false, false, false};  // the record in this place had no line number
  int records = 0;
  int phys = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find_first_of("\r\n", pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(pos, end - pos);
    pos = end;
    if (pos < text.size()) {
      if (text[pos] == '\r' && pos + 1 < text.size() && text[pos + 1] == '\n') ++pos;
      ++pos;
    }
    ++phys;
    std::vector<std::string_view> items;
    for (std::size_t i = 0; i < line.size();) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
      std::size_t j = i;
      while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
      if (j > i) items.push_back(line.substr(i, j - i));
      i = j;
    }
    if (items.empty()) continue;  // a blank line
    ++records;
    p.set_number(0);
    if (records > 5) {
      p.problem(phys, 0, std::string(line), "nothing more: the station file has five lines");
      continue;
    }
    const auto n = to_int(items[0]);
    if (!n || *n < 1 || *n > 5 || items[0].size() != 1) {
      p.problem(phys, 1, std::string(items[0]),
                "the line number " + std::to_string(records) + " first (lines 1 to 5, in order)");
      unnumbered[records - 1] = true;
      continue;
    }
    if (*n != records)
      p.problem(phys, 1, std::string(items[0]),
                "line number " + std::to_string(records) + " here: the lines must come in order 1 to 5");
    if (seen[*n - 1]) {
      p.problem(phys, 1, std::string(items[0]), "each line once; line " + std::to_string(*n) + " was given before");
      continue;
    }
    seen[*n - 1] = true;
    p.record(*n, phys, items);
  }
  for (int n = 1; n <= 5; ++n)
    if (!seen[n - 1] && !unnumbered[n - 1])
      p.problems.push_back({0, 0, "", "", "line " + std::to_string(n) + " (" +
                                                  (n == 1   ? std::string("callsign, latitude, longitude, height, rotor start")
                                                   : n == 2 ? std::string("ADC span az min, az max, el min, el max")
                                                   : n == 3 ? std::string("dead band az, el, skew az, el")
                                                   : n == 4 ? std::string("CAT rig, F/A, Icom RX and TX addresses")
                                                            : std::string("parking on/off, az, el, limit on/off, az min, "
                                                                          "az max, el min, el max")) +
                                                  "): the file ended without it"});
  std::stable_sort(p.problems.begin(), p.problems.end(), [](const StationFileProblem& a, const StationFileProblem& b) {
    const int la = a.line == 0 ? 1 << 30 : a.line, lb = b.line == 0 ? 1 << 30 : b.line;
    return la != lb ? la < lb : a.field < b.field;
  });
  StationFileParse r;
  r.problems = std::move(p.problems);
  if (r.problems.empty()) r.file = p.f;
  return r;
}

std::vector<std::string> apply_station_file(const StationFile& f, Model& m) {
  // What the five lines carry, line by line; the rest of each configuration keeps its value.
  Model next = m;
  station::StationConfig& st = next.station;
  const station::StationConfig& fs = f.station;
  std::tie(st.callsign, st.lat_deg, st.lon_deg, st.height_m, st.rotor_start) =
      std::tie(fs.callsign, fs.lat_deg, fs.lon_deg, fs.height_m, fs.rotor_start);
  rotator::RotatorConfig& r = next.rotator;
  const rotator::RotatorConfig& fr = f.rotator;
  std::tie(r.az_span, r.el_span) = std::tie(fr.az_span, fr.el_span);
  std::tie(r.az_dead_band, r.el_dead_band, r.az_skew, r.el_skew) =
      std::tie(fr.az_dead_band, fr.el_dead_band, fr.az_skew, fr.el_skew);
  std::tie(r.parking_enabled, r.parking, r.limits_enabled, r.az_limit_min, r.az_limit_max, r.el_limit_min,
           r.el_limit_max) = std::tie(fr.parking_enabled, fr.parking, fr.limits_enabled, fr.az_limit_min,
                                      fr.az_limit_max, fr.el_limit_min, fr.el_limit_max);
  radio::RadioConfig& rc = next.radio;
  const radio::RadioConfig& frc = f.radio;
  std::tie(rc.rig, rc.cat_policy, rc.icom_rx_address, rc.icom_tx_address) =
      std::tie(frc.rig, frc.cat_policy, frc.icom_rx_address, frc.icom_tx_address);
  auto problems = rotator::validate(r);
  if (problems.empty()) m = std::move(next);
  return problems;
}

std::string write_station_file(const Model& m) {
  const auto& st = m.station;
  const auto& r = m.rotator;
  const auto& rc = m.radio;
  char buf[512];
  std::string out;
  std::snprintf(buf, sizeof buf, "1 %s %.3f %.3f %g %s\n", st.callsign.c_str(), st.lat_deg, st.lon_deg, st.height_m,
                st.rotor_start == station::RotorStart::north ? "N" : "S");
  out += buf;
  std::snprintf(buf, sizeof buf, "2 %d %d %d %d\n", r.az_span.min, r.az_span.max, r.el_span.min, r.el_span.max);
  out += buf;
  std::snprintf(buf, sizeof buf, "3 %d %d %d %d\n", r.az_dead_band, r.el_dead_band, r.az_skew, r.el_skew);
  out += buf;
  std::snprintf(buf, sizeof buf, "4 %s %s %02X %02X\n", radio::to_string(rc.rig),
                rc.cat_policy == radio::CatPolicy::full_orbit ? "F" : "A", rc.icom_rx_address, rc.icom_tx_address);
  out += buf;
  std::snprintf(buf, sizeof buf, "5 %d %g %g %d %g %g %g %g\n", r.parking_enabled ? 1 : 0, r.parking.az, r.parking.el,
                r.limits_enabled ? 1 : 0, r.az_limit_min, r.az_limit_max, r.el_limit_min, r.el_limit_max);
  out += buf;
  return out;
}

}  // namespace tb::store
