// Menu 3-1: Edit. Choose a satellite of the tracking list by its number (Enter: the one marked '*',
// Q: back; the whole database when the tracking list is empty), then
// its data line by line in the manual's order, each line showing the stored value; Enter keeps it:
//
//   ====== Satellite data ======
//   Satellite       : A-21
//   Epoch Year Y0   : 93           Y0:
//   Epoch Time T0   : 45.39066000  T0:
//   ...
//   Downlink Frq.F1 : 145.987      F1:
//   Offset for F1   : 0.000        F1OFFSET:
//   ...
//   LCD MA display  : No
//
// Every answer is checked (format and range); a wrong one says why and the line is asked again.
// The edit is made on a copy and stored only after the last line. Beyond the manual: the drag
// term B* (trakbox runs SGP4, which uses it; the 8051's own model did not) follows Decay N1.
#include <cmath>
#include <cstdio>

#include "menus/menus.h"
#include "orbit/sgp4.h"
#include "store/model.h"
#include "tracker/station_loop.h"
#include "util/text.h"

namespace tb::menus {

namespace {

using Accept = std::function<std::optional<std::string>(const std::string&)>;
using Keep = std::function<std::optional<std::string>()>;

std::string edit_fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// One line: "Label           : value        PROMPT" then the answer. Enter keeps the value (after
// `keep` agrees: a value can become wrong through an earlier line, e.g. day 366 after the year
// changed). accept() stores the value, or returns why it cannot.
void ask_field(term::Terminal& t, const char* label, const std::string& shown, const char* prompt,
               const Accept& accept, const Keep& keep = {}) {
  for (;;) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%-16s: %-13s%s", label, shown.c_str(), prompt);
    t.write(buf);
    t.flush();
    const std::string a = text::trimmed(read_line(t));
    const std::optional<std::string> error = a.empty() ? (keep ? keep() : std::nullopt) : accept(a);
    if (!error) return;
    t.line("  " + *error);
  }
}

std::optional<double> finite_number(const std::string& a) {
  const auto v = parse_number(a);
  if (!v || !std::isfinite(*v)) return std::nullopt;
  return v;
}

// A number in [lo, hi] (hi excluded when open).
void number_field(term::Terminal& t, const char* label, const char* prompt, double& value, const char* shown_format,
                  double lo, double hi, bool open_high, const char* unit) {
  ask_field(t, label, edit_fmt(shown_format, value), prompt, [&](const std::string& a) -> std::optional<std::string> {
    const auto v = finite_number(a);
    if (!v) return "'" + a + "' is not a number";
    if (*v < lo || *v > hi || (open_high && *v == hi)) {
      char range[128];
      std::snprintf(range, sizeof range, "%s is out of range: expected %.10g to %s%.10g%s%s", a.c_str(), lo,
                    open_high ? "less than " : "", hi, *unit ? " " : "", unit);
      return std::string(range);
    }
    value = *v;
    return std::nullopt;
  });
}

int edit_days_in_year(int year) {
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return leap ? 366 : 365;
}

constexpr radio::Hz kMaxHz = 1'000'000'000'000LL;  // 1 THz, the stored document's limit

void frequency_field(term::Terminal& t, const char* label, const char* prompt, radio::Hz& hz) {
  ask_field(t, label, radio::format_mhz(hz), prompt, [&](const std::string& a) -> std::optional<std::string> {
    const auto v = radio::parse_mhz(a);
    if (!v) return "'" + a + "' is not a frequency in MHz (such as 145.950; 0 = none)";
    if (*v < 0 || *v > kMaxHz) return a + " is out of range: expected 0 (none) to 1000000 MHz";
    hz = *v;
    return std::nullopt;
  });
}

// The converter offset: added to the frequency, it must leave something the radio can tune.
void offset_field(term::Terminal& t, const char* label, const char* prompt, radio::Hz rf, radio::Hz& offset) {
  auto check = [rf](radio::Hz off) -> std::optional<std::string> {
    if (rf > 0 && rf + off <= 0)
      return "the radio would be tuned to " + radio::format_mhz(rf + off) + " MHz: the offset must leave more than 0";
    return std::nullopt;
  };
  ask_field(
      t, label, radio::format_mhz(offset), prompt,
      [&](const std::string& a) -> std::optional<std::string> {
        const auto v = radio::parse_mhz(a);
        if (!v) return "'" + a + "' is not an offset in MHz (such as -2256.000; 0 = none)";
        if (*v < -kMaxHz || *v > kMaxHz) return a + " is out of range: expected -1000000 to 1000000 MHz";
        if (auto e = check(*v)) return e;
        offset = *v;
        return std::nullopt;
      },
      [&] { return check(offset); });
}

void mode_field(term::Terminal& t, const char* label, radio::Mode& mode) {
  ask_field(t, label, radio::to_string(mode), "", [&](const std::string& a) -> std::optional<std::string> {
    const auto m = radio::parse_mode(a);
    if (!m || *m == radio::Mode::cw) return "'" + a + "': expected FM, LSB, USB or None";
    mode = *m;
    return std::nullopt;
  });
}

// Name and epoch: the name must stay unique in the database; the day must exist in the year.
void edit_identity(term::Terminal& t, const store::Database& db, std::size_t index, orbit::Elements& e) {
  ask_field(t, "Satellite", e.name, "", [&](const std::string& a) -> std::optional<std::string> {
    if (a.size() > 24) return "a name has at most 24 characters";
    if (const auto other = db.find(a); other && static_cast<std::size_t>(*other) != index)
      return "satellite #" + std::to_string(*other + 1) + " is already called " + a + " (names must differ)";
    e.name = a;
    return std::nullopt;
  });

  ask_field(t, "Epoch Year Y0", edit_fmt("%02.0f", e.epoch_year % 100), "Y0:",
            [&](const std::string& a) -> std::optional<std::string> {
              const auto y = parse_integer(a);
              if (y && *y >= 0 && *y <= 99) e.epoch_year = orbit::expand_two_digit_year(static_cast<int>(*y));
              else if (y && *y >= 1957 && *y <= 2056) e.epoch_year = static_cast<int>(*y);
              else return "'" + a + "': expected YY (57-99 = 19YY, 00-56 = 20YY) or a year 1957 to 2056";
              return std::nullopt;
            });

  auto day_error = [&](double day) -> std::optional<std::string> {
    const int last = edit_days_in_year(e.epoch_year);
    if (day >= 1.0 && day < last + 1.0) return std::nullopt;
    return edit_fmt("%.8f", day) + " is not a day of " + std::to_string(e.epoch_year) + ": expected 1 to less than " +
           std::to_string(last + 1) + " (day of the year with fraction)";
  };
  ask_field(
      t, "Epoch Time T0", edit_fmt("%.8f", e.epoch_day), "T0:",
      [&](const std::string& a) -> std::optional<std::string> {
        const auto v = finite_number(a);
        if (!v) return "'" + a + "' is not a number (day of the year with fraction, such as 45.39066)";
        if (auto err = day_error(*v)) return err;
        e.epoch_day = *v;
        return std::nullopt;
      },
      [&] { return day_error(e.epoch_day); });

  ask_field(t, "Epoch Rev K0", std::to_string(e.revolution_number), "K0:",
            [&](const std::string& a) -> std::optional<std::string> {
              const auto v = parse_integer(a);
              if (!v) return "'" + a + "' is not a whole number";
              if (*v < 0 || *v > 9999999) return a + " is out of range: expected 0 to 9999999";
              e.revolution_number = *v;
              return std::nullopt;
            });

}

// The orbit's mean elements, each within its range.
void edit_orbit(term::Terminal& t, orbit::Elements& e) {
  number_field(t, "Mean Anomaly M0", "M0:", e.mean_anomaly_deg, "%.4f", 0.0, 360.0, true, "deg");
  ask_field(t, "Mean Motion N0", edit_fmt("%.8f", e.mean_motion_rev_per_day), "N0:",
            [&](const std::string& a) -> std::optional<std::string> {
              const auto v = finite_number(a);
              if (!v) return "'" + a + "' is not a number";
              if (!(*v > 0.0) || *v > 20.0) return a + " is out of range: expected more than 0 to 20 rev/day";
              e.mean_motion_rev_per_day = *v;
              return std::nullopt;
            });
  number_field(t, "Inclination I0", "I0:", e.inclination_deg, "%.4f", 0.0, 180.0, false, "deg");
  number_field(t, "Eccentricity E0", "E0:", e.eccentricity, "%.7f", 0.0, 0.9999999, false, "");
  number_field(t, "Arg perigee W0", "W0:", e.arg_perigee_deg, "%.4f", 0.0, 360.0, true, "deg");
  number_field(t, "R.A.A.N. O0", "O0:", e.raan_deg, "%.4f", 0.0, 360.0, true, "deg");
  number_field(t, "Decay N1", "N1:", e.ndot_over_2, "%.6e", -1.0, 1.0, false, "rev/day^2");
  number_field(t, "Drag term B*", "B*:", e.bstar, "%.6e", -1.0, 1.0, false, "per earth radius");

}

// Frequencies, converter offsets, modes, the Doppler method and the LCD display.
void edit_radio(term::Terminal& t, radio::SatelliteRadio& r) {
  frequency_field(t, "Downlink Frq.F1", "F1:", r.downlink_hz);
  offset_field(t, "Offset for F1", "F1OFFSET:", r.downlink_hz, r.downlink_offset_hz);
  frequency_field(t, "Uplink Frq.F2", "F2:", r.uplink_hz);
  offset_field(t, "Offset for F2", "F2OFFSET:", r.uplink_hz, r.uplink_offset_hz);
  mode_field(t, "Downlink mode", r.downlink_mode);
  mode_field(t, "Uplink mode", r.uplink_mode);
  ask_field(t, "Doppler correct.", radio::to_string(r.doppler), "",
            [&](const std::string& a) -> std::optional<std::string> {
              const std::string l = text::lower(a);
              if (l == "cat" || l == "c") r.doppler = radio::DopplerControl::cat;
              else if (l == "mic-click" || l == "mic" || l == "m" || l == "mic click" || l == "micclick")
                r.doppler = radio::DopplerControl::mic_click;
              else return "'" + a + "': expected CAT or Mic-click (C or M)";
              return std::nullopt;
            });
  ask_field(t, "LCD MA display", r.lcd_ma_display ? "Yes" : "No", "",
            [&](const std::string& a) -> std::optional<std::string> {
              const std::string l = text::lower(a);
              if (l == "yes" || l == "y") r.lcd_ma_display = true;
              else if (l == "no" || l == "n") r.lcd_ma_display = false;
              else return "'" + a + "': expected Yes or No";
              return std::nullopt;
            });

}

}  // namespace

void menu_3_1_edit(term::Terminal& t, Services& s) {
  const store::Database& db = s.model.db;
  if (db.satellites.empty()) {
    t.line("The database is empty: load element data with menu 3-3 first.");
    return;
  }
  // The manual lists the tracking list (up to 15, the '*' on the one last chosen) and takes its
  // number; with an empty tracking list, the whole database.
  std::vector<int> candidates = db.selected;
  int marked = db.marked;
  if (candidates.empty()) {
    for (std::size_t i = 0; i < db.satellites.size(); ++i) candidates.push_back(static_cast<int>(i));
    marked = db.marked_index().value_or(-1);
  }
  std::vector<std::string> names;
  for (const int i : candidates) names.push_back(db.satellites[static_cast<std::size_t>(i)].name());
  const auto pick = choose_satellite(t, "     *** Select object satellite ***", names, marked);
  if (!pick) return;
  const std::size_t index = static_cast<std::size_t>(candidates[static_cast<std::size_t>(*pick)]);

  store::Satellite sat = db.satellites[index];  // the copy being edited
  orbit::Elements& e = sat.elements;
  radio::SatelliteRadio& r = sat.radio;
  t.line("====== Satellite data ======");

  edit_identity(t, db, index, e);
  edit_orbit(t, e);
  edit_radio(t, r);

  // Every line was answered: store the satellite.
  const orbit::Sgp4Error at_epoch = orbit::error_at_epoch(e);
  if (!commit(t, s, store::bit(store::Area::elements) | store::bit(store::Area::radio_entries), "menu 3-1",
              [&](store::Model& m) { m.db.satellites[index] = sat; }))
    return;
  t.line("Satellite (" + s.model.db.satellites[index].name() + ") updated.");
  if (at_epoch != orbit::Sgp4Error::none)
    t.line(std::string("Warning: SGP4 finds no orbit in these elements: ") + orbit::describe(at_epoch));
  s.station.reconfigure();  // the radio is tuned again from the new frequencies
  save_or_report(t, s);
}

}  // namespace tb::menus
