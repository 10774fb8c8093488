#include "store/station_file.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iterator>

#include "radio/freqmode.h"
#include "rotator/adc_model.h"
#include "store/model.h"
#include "store/settings.h"
#include "util/text.h"

namespace tb::store {

namespace {

// Items of each line after its number (index 0 is item 2). The 1994 file has five lines; the later
// firmware's (v3.20d-3.50b) seven, the optional items last.
const char* const kNames1[] = {"callsign", "latitude", "longitude", "height", "rotor start", "COM baud"};
const char* const kNames2[] = {"azimuth minimum", "azimuth maximum", "elevation minimum", "elevation maximum",
                               "flip mode"};
const char* const kNames3[] = {"azimuth dead band", "elevation dead band", "azimuth skew", "elevation skew"};
const char* const kNames4[] = {"CAT rig", "F/A", "Icom RX address", "Icom TX address", "CAT baud"};
const char* const kNames5[] = {"antenna parking ON/OFF", "parking azimuth", "parking elevation", "limit ON/OFF",
                               "azimuth minimum",        "azimuth maximum", "elevation minimum", "elevation maximum"};
const char* const kNames5Later[] = {"antenna parking ON/OFF", "parking azimuth", "parking elevation",
                                    "rotor start elevation",  "P16 on elevation", "P16 off elevation"};
const char* const kNames6[] = {"radio parking/rotator error flags", "RX park frequency", "TX park frequency",
                               "RX park mode", "TX park mode", "rotator error timeout"};
const char* const kNames7[] = {"limit ON/OFF", "azimuth minimum", "azimuth maximum", "elevation minimum",
                               "elevation maximum"};

struct LineShape {
  const char* const* names;
  int items;     // after the line number
  int optional;  // of those, how many at the end may be left out
  const char* summary;
};
const LineShape kShapes1994[5] = {
    {kNames1, 5, 0, "callsign, latitude, longitude, height, rotor start"},
    {kNames2, 4, 0, "ADC span az min, az max, el min, el max"},
    {kNames3, 4, 0, "dead band az, el, skew az, el"},
    {kNames4, 4, 0, "CAT rig, F/A, Icom RX and TX addresses"},
    {kNames5, 8, 0, "parking on/off, az, el, limit on/off, az min, az max, el min, el max"}};
const LineShape kShapesLater[7] = {
    {kNames1, 6, 1, "callsign, latitude, longitude, height, rotor start, COM baud"},
    {kNames2, 5, 1, "ADC span az min, az max, el min, el max, F"},
    {kNames3, 4, 0, "dead band az, el, skew az, el"},
    {kNames4, 5, 1, "CAT rig, FULL/AOS, Icom RX and TX addresses, CAT baud"},
    {kNames5Later, 6, 0, "parking, park az, park el, rotor start el, P16 on el, P16 off el"},
    {kNames6, 6, 0, "parking/error flags, RX and TX park MHz, RX and TX park modes, timeout"},
    {kNames7, 5, 0, "limit on/off, az min, az max, el min, el max"}};

const LineShape& shape_of(bool later, int number) {
  return later ? kShapesLater[number - 1] : kShapes1994[number - 1];
}

constexpr int kStationFileBauds[] = {1200, 2400, 4800, 9600, 19200};

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

  explicit Parser(bool later) : later_(later) { f.later_firmware = later; }

  // A problem with item `field` of the line numbered current_number_ (the line's own number).
  void problem(int line, int field, std::string found, std::string expected) {
    problems.push_back({line, field,
                        name_override_ ? name_override_ : station_file_item_name(current_number_, field, later_),
                        std::move(found), std::move(expected)});
  }
  void set_number(int n) { current_number_ = n; }

  // One record: `number` is the line number it claims, `phys` its line in the upload.
  void record(int number, int phys, const std::vector<std::string_view>& items) {
    set_number(number);
    const LineShape& shape = shape_of(later_, number);
    const int given = static_cast<int>(items.size()) - 1;
    int wanted = shape.items;
    if (given >= shape.items - shape.optional && given <= shape.items) wanted = given;
    if (number == 4 && (given == 2 || (later_ && given == 3))) {
      // CAT rig and F/A only (the later firmware: and the CAT baud): for the rigs that have no addresses.
      wanted = given;
      no_addresses_ = true;
    }
    for (int i = 0; i < std::min(given, wanted); ++i) {
      const std::string_view s = items[static_cast<std::size_t>(i + 1)];
      if (no_addresses_ && number == 4 && i == 2) {  // the CAT baud right after F/A
        name_override_ = "CAT baud";
        baud(phys, i + 2, s, f.radio.cat_baud, f.cat_baud_given);
        name_override_ = nullptr;
      } else {
        item(number, phys, i + 2, s);
      }
    }
    if (given < wanted) {
      problem(phys, given + 2, "", std::string("a value for ") + shape.names[given] + " (line " +
                                       std::to_string(number) + " has " + std::to_string(shape.items + 1) + " items)");
    } else if (given > wanted) {
      problem(phys, wanted + 2, std::string(items[static_cast<std::size_t>(wanted + 1)]),
              "the end of line " + std::to_string(number) + " (" + std::to_string(shape.items + 1) + " items)");
    }
    if (number == 4 && no_addresses_ && f.radio.rig == radio::Rig::icom && rig_ok_)
      problem(phys, 4, "", "the Icom RX and TX addresses (hex, e.g. 10 14) after the F/A item for ICOM");
    cross_checks(number, phys);
  }

 private:
  bool later_ = false;
  int current_number_ = 0;  // the line being read
  bool rig_ok_ = false;
  bool no_addresses_ = false;
  const char* name_override_ = nullptr;
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
                  (v && *v > hi && hi < 1023 ? " (line " + std::to_string(current_number_) +
                                                   " is in degrees, not ADC counts)"
                                             : ""));
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

  void baud(int phys, int field, std::string_view s, int& out, bool& given) {
    const auto v = to_int(s);
    if (v && std::find(std::begin(kStationFileBauds), std::end(kStationFileBauds), *v) != std::end(kStationFileBauds)) {
      out = *v;
      given = true;
    } else {
      problem(phys, field, std::string(s), "a speed in baud: 1200, 2400, 4800, 9600 or 19200");
    }
  }

  void mhz(int phys, int field, std::string_view s, radio::Hz& out) {
    const auto v = radio::parse_mhz(s);
    if (v && *v >= 0)
      out = *v;
    else
      problem(phys, field, std::string(s), "a frequency in MHz such as 145.800 (0 for none)");
  }

  void mode(int phys, int field, std::string_view s, radio::Mode& out) {
    if (const auto m = radio::parse_mode(s))
      out = *m;
    else
      problem(phys, field, std::string(s), "usb, lsb, fm, cw or none");
  }

  void item(int number, int phys, int field, std::string_view s) {
    switch (number) {
      case 1: item_line1(phys, field, s); break;
      case 2:
        if (field == 6) {
          if (upper(s) == "F")
            f.rotator.el_flip_allowed = true;
          else
            problem(phys, field, std::string(s), "F (flip mode) or nothing");
          break;
        }
        {
          int* dst[] = {&f.rotator.az_span.min, &f.rotator.az_span.max, &f.rotator.el_span.min, &f.rotator.el_span.max};
          counts(phys, field, s, rotator::limits::kSpan, *dst[field - 2], "ADC counts", span_ok_[field - 2]);
        }
        break;
      case 3: {
        bool ok = false;
        if (field <= 3)
          counts(phys, field, s, rotator::limits::kDeadBand, field == 2 ? f.rotator.az_dead_band : f.rotator.el_dead_band, "ADC counts", ok);
        else
          counts(phys, field, s, rotator::limits::kSkew, field == 4 ? f.rotator.az_skew : f.rotator.el_skew, "ADC counts", ok);
        break;
      }
      case 4: item_line4(phys, field, s); break;
      case 5:
        if (later_)
          item_line5_later(phys, field, s);
        else if (field <= 4)
          item_parking(phys, field, s);
        else
          item_limits(phys, field, field - 3, s);
        break;
      case 6: item_line6(phys, field, s); break;
      case 7: item_limits(phys, field, field, s); break;
    }
  }

  void item_line1(int phys, int field, std::string_view s) {
    bool ok = false;
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
      // The ranges of the settings table (store/settings.h), as every reader of them takes them.
      case 3: {
        const Bounds b = bounds("station.lat_deg");
        degrees(phys, field, s, b.lo, b.hi, f.station.lat_deg, ok);
        break;
      }
      case 4: {
        const Bounds b = bounds("station.lon_deg");
        degrees(phys, field, s, b.lo, b.hi, f.station.lon_deg, ok);
        break;
      }
      case 5: {
        const auto v = to_double(s);
        const store::Setting& h = *find_setting("station.height_m");
        if (v && !refusal(h, nlohmann::json(*v)))
          f.station.height_m = *v;
        else
          problem(phys, field, std::string(s), "metres above sea level, " + range_text(h));
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
      case 7: baud(phys, field, s, f.station.com_baud, f.com_baud_given); break;
    }
  }

  // The rig names of both firmwares: the family, and the model the later firmware names.
  void rig(int phys, std::string_view s) {
    struct Name {
      const char* text;
      radio::Rig rig;
      radio::RigModel model;
      int wide;  // -1: not said, 0: standard FM filter, 1: wide
    };
    static const Name kRigs[] = {
        {"ICOM", radio::Rig::icom, radio::RigModel::generic, -1},
        {"I", radio::Rig::icom, radio::RigModel::generic, -1},
        {"KENWOOD", radio::Rig::kenwood, radio::RigModel::generic, -1},
        {"K", radio::Rig::kenwood, radio::RigModel::generic, -1},
        {"KENWOOD711", radio::Rig::kenwood, radio::RigModel::kenwood_711, -1},
        {"YAESU", radio::Rig::yaesu, radio::RigModel::generic, -1},
        {"Y", radio::Rig::yaesu, radio::RigModel::generic, -1},
        {"YAESU_O", radio::Rig::yaesu, radio::RigModel::yaesu_other, 0},
        {"YAESU_847", radio::Rig::yaesu, radio::RigModel::yaesu_847, 0},
        {"YAESU_736", radio::Rig::yaesu, radio::RigModel::yaesu_736, 0},
        {"YAESUW847", radio::Rig::yaesu, radio::RigModel::yaesu_847, 1},
        {"YAESUW736", radio::Rig::yaesu, radio::RigModel::yaesu_736, 1},
        {"NONE", radio::Rig::none, radio::RigModel::generic, -1},
        {"N", radio::Rig::none, radio::RigModel::generic, -1}};
    const std::string u = upper(s);
    for (const Name& n : kRigs)
      if (u == n.text) {
        rig_ok_ = true;
        f.radio.rig = n.rig;
        f.radio.rig_model = n.model;
        f.wide_fm_given = n.wide >= 0;
        f.radio.ft736_wide_fm = n.wide == 1;
        return;
      }
    rig_ok_ = false;
    problem(phys, 2, std::string(s),
            later_ ? "ICOM, KENWOOD, KENWOOD711, YAESU_o, YAESU_847, YAESU_736, YAESUw736, YAESUw847 or NONE"
                   : "ICOM, KENWOOD, YAESU or NONE");
  }

  void item_line4(int phys, int field, std::string_view s) {
    if (field == 2) {
      rig(phys, s);
    } else if (field == 3) {
      const std::string u = upper(s);
      if (u == "F" || u == "FULL")
        f.radio.cat_policy = radio::CatPolicy::full_orbit;
      else if (u == "A" || u == "AOS")
        f.radio.cat_policy = radio::CatPolicy::aos_only;
      else
        problem(phys, field, std::string(s), "F (full orbit) or A (AOS only)");
    } else if (field == 6) {
      baud(phys, field, s, f.radio.cat_baud, f.cat_baud_given);
    } else {
      const auto v = to_hex_address(s);
      if (v && *v < 0xE0)
        (field == 4 ? f.radio.icom_rx_address : f.radio.icom_tx_address) = static_cast<std::uint8_t>(*v);
      else
        problem(phys, field, std::string(s),
                "a CI-V address in hex, 00 to DF (e.g. 10 for an IC-275, 14 for an IC-475; E0 is TrakBox's own)");
    }
  }

  void item_parking(int phys, int field, std::string_view s) {
    bool ok = false;
    switch (field) {
      case 2: flag(phys, field, s, f.rotator.parking_enabled); break;
      case 3: degrees(phys, field, s, 0.0, 360.0, f.rotator.parking.az, ok); break;
      case 4: degrees(phys, field, s, 0.0, 90.0, f.rotator.parking.el, ok); break;
    }
  }

  // The limit switch and its ranges: items 5..9 of the 1994 line 5 (`k` = field - 3) or 2..6 of line 7.
  void item_limits(int phys, int field, int k, std::string_view s) {
    switch (k) {
      case 2: flag(phys, field, s, f.rotator.limits_enabled); break;
      case 3: degrees(phys, field, s, 0.0, 360.0, f.rotator.az_limit_min, limit_ok_[0]); break;
      case 4: degrees(phys, field, s, 0.0, 360.0, f.rotator.az_limit_max, limit_ok_[1]); break;
      case 5: degrees(phys, field, s, 0.0, 90.0, f.rotator.el_limit_min, limit_ok_[2]); break;
      case 6: degrees(phys, field, s, 0.0, 90.0, f.rotator.el_limit_max, limit_ok_[3]); break;
    }
  }

  // "1", "0", or "1" followed by the mic-click pulse width and interval digits: "125".
  void park_with_digits(int phys, std::string_view s) {
    const bool good = !s.empty() && s.size() <= 3 && (s[0] == '0' || s[0] == '1') &&
                      std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!good) {
      problem(phys, 2, std::string(s), "1 (on) or 0 (off), optionally followed by the mic-click pulse width and "
                                       "interval digits (e.g. 125)");
      return;
    }
    f.rotator.parking_enabled = s[0] == '1';
    f.radio.mic_click.park_pulse_width_digit = s.size() > 1 ? s[1] - '0' : -1;
    f.radio.mic_click.park_pulse_interval_digit = s.size() > 2 ? s[2] - '0' : -1;
  }

  void item_line5_later(int phys, int field, std::string_view s) {
    bool ok = false;
    switch (field) {
      case 2: park_with_digits(phys, s); break;
      case 3: case 4: item_parking(phys, field, s); break;
      case 5: degrees(phys, field, s, -90.0, 90.0, f.pass_events.rotor_start_el_deg, ok); break;
      case 6: degrees(phys, field, s, -90.0, 90.0, f.pass_events.output_on_el_deg, ok); break;
      case 7: degrees(phys, field, s, -90.0, 90.0, f.pass_events.output_off_el_deg, ok); break;
    }
  }

  void item_line6(int phys, int field, std::string_view s) {
    switch (field) {
      case 2:
        if (s.size() == 2 && (s[0] == '0' || s[0] == '1') && (s[1] == '0' || s[1] == '1')) {
          f.radio.parking.enabled = s[0] == '1';
          f.rotator_error_detection = s[1] == '1';
        } else {
          problem(phys, field, std::string(s),
                  "two digits 0 or 1: radio parking, then rotator-error detection (e.g. 11)");
        }
        break;
      case 3: mhz(phys, field, s, f.radio.parking.rx_hz); break;
      case 4: mhz(phys, field, s, f.radio.parking.tx_hz); break;
      case 5: mode(phys, field, s, f.radio.parking.rx_mode); break;
      case 6: mode(phys, field, s, f.radio.parking.tx_mode); break;
      case 7: {
        const auto v = to_double(s);
        if (v && *v >= 1.0 && *v <= 600.0)
          f.rotator.stall_s = *v;
        else
          problem(phys, field, std::string(s), "seconds 1 to 600");
        break;
      }
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
    if (number == (later_ ? 7 : 5)) {
      const int first = later_ ? 2 : 5;  // the item of the limit ON/OFF
      if (limit_ok_[0] && limit_ok_[1] && f.rotator.az_limit_max - f.rotator.az_limit_min < 360.0 &&
          rotator::wrap360(f.rotator.az_limit_max - f.rotator.az_limit_min) == 0.0)
        problem(phys, first + 2, num(f.rotator.az_limit_max),
                "an azimuth other than the minimum (" + num(f.rotator.az_limit_min) +
                    "): the sector runs clockwise from minimum to maximum; 0 and 360 mean no limit");
      if (limit_ok_[2] && limit_ok_[3] && f.rotator.el_limit_max < f.rotator.el_limit_min)
        problem(phys, first + 4, num(f.rotator.el_limit_max),
                "at least the elevation minimum (" + num(f.rotator.el_limit_min) + ")");
    }
  }
};

}  // namespace

std::string station_file_item_name(int line, int field, bool later_firmware) {
  if (field == 1) return "line number";
  if (line < 1 || line > (later_firmware ? 7 : 5) || field < 2) return "line";
  const LineShape& s = shape_of(later_firmware, line);
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

namespace {

struct Record {
  int phys;
  std::string_view line;
  std::vector<std::string_view> items;
};

// The lines that carry items: not blank, not a `;` comment (the later firmware's; harmless in a 1994
// file). Lines are numbered as in the upload.
std::vector<Record> records_of(std::string_view text) {
  std::vector<Record> out;
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
    if (items.empty() || items.front().front() == ';') continue;
    out.push_back({phys, line, std::move(items)});
  }
  return out;
}

// The later firmware's seven-line file rather than the 1994 five-line one: told by line 5 (7 items
// against 9), or else by a line numbered 6 or 7 or more than five lines.
bool is_later_form(const std::vector<Record>& records) {
  for (const Record& r : records)
    if (r.items[0] == "5") {
      if (r.items.size() == 7) return true;
      if (r.items.size() == 9) return false;
      break;
    }
  if (records.size() > 5) return true;
  for (const Record& r : records)
    if (r.items[0] == "6" || r.items[0] == "7") return true;
  return false;
}

}  // namespace

StationFileParse parse_station_file(std::string_view text) {
  if (const auto z = text.find('\x1a'); z != std::string_view::npos) text = text.substr(0, z);
  const std::vector<Record> all = records_of(text);
  const bool later = is_later_form(all);
  const int lines = later ? 7 : 5;
  Parser p(later);
  bool seen[7] = {false, false, false, false, false, false, false};
  bool unnumbered[7] = {false, false, false, false, false, false, false};  // this place's record had no number
  int records = 0;
  for (const Record& rec : all) {
    const int phys = rec.phys;
    const auto& items = rec.items;
    ++records;
    p.set_number(0);
    if (records > lines) {
      p.problem(phys, 0, std::string(rec.line),
                later ? "nothing more: the later firmware's station file has seven lines"
                      : "nothing more: the station file has five lines");
      continue;
    }
    const auto n = to_int(items[0]);
    if (!n || *n < 1 || *n > lines || items[0].size() != 1) {
      p.problem(phys, 1, std::string(items[0]),
                "the line number " + std::to_string(records) + " first (lines 1 to " + std::to_string(lines) +
                    ", in order)");
      unnumbered[records - 1] = true;
      continue;
    }
    if (*n != records)
      p.problem(phys, 1, std::string(items[0]),
                "line number " + std::to_string(records) + " here: the lines must come in order 1 to " +
                    std::to_string(lines));
    if (seen[*n - 1]) {
      p.problem(phys, 1, std::string(items[0]), "each line once; line " + std::to_string(*n) + " was given before");
      continue;
    }
    seen[*n - 1] = true;
    p.record(*n, phys, items);
  }
  for (int n = 1; n <= lines; ++n)
    if (!seen[n - 1] && !unnumbered[n - 1])
      p.problems.push_back({0, 0, "", "", "line " + std::to_string(n) + " (" + shape_of(later, n).summary +
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

}  // namespace tb::store
