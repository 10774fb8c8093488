// 6-2 Set ADC span value, 6-3 Set Dead Band and Skew value, 6-4 Set Antenna Parking and Limit
// position. Each edits a copy of the rotator configuration (Enter keeps a value, Q leaves with
// nothing changed) and commits it only when rotator::validate accepts the whole.
#include <cstdio>

#include "menus/6_configuration.h"
#include "rotator/parking_mask.h"
#include "rotator/split_travel.h"
#include "store/model.h"

namespace tb::menus {

namespace {
std::string span_of(const char* axis, const rotator::AxisSpan& a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "ADC span value %s: %04d - %04d", axis, a.min, a.max);
  return buf;
}
int whole(double v) { return static_cast<int>(v); }
}  // namespace

void menu_6_2_adc_span(term::Terminal& t, Services& s) {
  rotator::RotatorConfig c = s.model.rotator;
  const double lo = rotator::limits::kSpan.lo, top = rotator::limits::kSpan.hi;
  t.line(span_of("AZ", c.az_span));
  c.az_span.min = whole(cfg::ask_number(t, "AZ minimum value ? : ", c.az_span.min, lo, top, true));
  c.az_span.max = whole(cfg::ask_number(t, "AZ maximum value ? : ", c.az_span.max, lo, top, true));
  t.line(span_of("EL", c.el_span));
  c.el_span.min = whole(cfg::ask_number(t, "EL minimum value ? : ", c.el_span.min, lo, top, true));
  // Flip mode (the later firmware) calibrates the elevation at 0 and 180 degrees: the maximum is
  // the 180-degree count.
  const char* el_max = c.el_flip_allowed ? "EL maximum (180 deg) value ? : " : "EL maximum value ? : ";
  c.el_span.max = whole(cfg::ask_number(t, el_max, c.el_span.max, lo, top, true));
  // Limits that leave two pieces of travel (the rotor stop inside them) are said so, with what is
  // reachable. Whether they may be crossed is not asked here, so the manual's dialogue (whose own
  // example splits the travel on the factory South start) keeps its keystrokes: --cross-limit-sector.
  if (cfg::commit_rotator(t, s, c)) t.line(span_line(c));
}

void menu_6_3_dead_band_skew(term::Terminal& t, Services& s) {
  rotator::RotatorConfig c = s.model.rotator;
  auto ask = [&t](const char* label, int& value, rotator::limits::Counts range) {
    value = whole(cfg::ask_number(t, std::string(label) + " : " + cfg::fmt1(value) + "  ", value, range.lo, range.hi, true));
  };
  ask("Azimuth Dead Band", c.az_dead_band, rotator::limits::kDeadBand);
  ask("Elevation Dead Band", c.el_dead_band, rotator::limits::kDeadBand);
  ask("Azimuth Skew value", c.az_skew, rotator::limits::kSkew);
  ask("Elevation Skew value", c.el_skew, rotator::limits::kSkew);
  cfg::commit_rotator(t, s, c);
}

void menu_6_4_parking_limits(term::Terminal& t, Services& s) {
  rotator::RotatorConfig c = s.model.rotator;
  const double el_top = c.el_top_deg();
  auto prompt = [](const char* label, double current) { return std::string(label) + " : " + cfg::fmt1(current) + "  "; };
  c.parking_enabled = cfg::ask_choice(t, "Set Antenna Parking position ? [Y/N] ", "YN") == 'Y';
  if (c.parking_enabled) {
    c.parking.az = cfg::ask_number(t, prompt("Azimuth Parking value", c.parking.az), c.parking.az, 0, 360);
    c.parking.el = cfg::ask_number(t, prompt("Elevation Parking value", c.parking.el), c.parking.el, 0, el_top);
  }
  c.limits_enabled = cfg::ask_choice(t, "Set Antenna rotation limit ? [Y/N] ", "YN") == 'Y';
  if (c.limits_enabled) {
    // "minmum": the manual's spelling of these two prompts.
    c.az_limit_min = cfg::ask_number(t, prompt("Azimuth minmum value", c.az_limit_min), c.az_limit_min, 0, 360);
    c.az_limit_max = cfg::ask_number(t, prompt("Azimuth maximum value", c.az_limit_max), c.az_limit_max, 0, 360);
    c.el_limit_min = cfg::ask_number(t, prompt("Elevation minmum value", c.el_limit_min), c.el_limit_min, 0, el_top);
    c.el_limit_max = cfg::ask_number(t, prompt("Elevation maximum value", c.el_limit_max), c.el_limit_max, 0, el_top);
  }
  if (cfg::commit_rotator(t, s, c)) {
    if (const auto w = rotator::split_travel_warning(c, s.model.station.rotor_start))
      for (const auto& line : cfg::wrap_words(*w)) t.line(line);
    // The parking position is the operator's stow: kept as typed, said when below the horizon
    // mask (issue 57; menu 4 sets the mask).
    if (const auto w = rotator::parking_mask_warning(c, s.model.station.mask().get())) {
      t.bell();
      for (const auto& line : cfg::wrap_words("WARNING: " + *w + " (menu 4 sets the mask)")) t.line(line);
    }
  }
}

}  // namespace tb::menus
