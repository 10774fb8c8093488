// Standalone mode (the manual's STANDALONE MODE and STARTUP): the front-panel selector, the
// two-line LCD and the AOS LED, with the keyboard standing in for the selector and the track switch.
#include "menus/standalone.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "station/clock.h"
#include "store/model.h"
#include "tracker/operations.h"
#include "tracker/station_loop.h"

namespace tb::menus {

// ---- the LCD and the LED ----

std::string lcd_top(orbit::UtcTime t, std::string_view name, char separator) {
  std::string s = format_time(t);
  s.push_back(separator);
  s.append(name.substr(0, kLcdNameColumns));
  return s;
}

namespace {
// Rounded to tenths, without "-0.0".
double tenths(double v) {
  const double r = std::round(v * 10.0) / 10.0;
  return r == 0.0 ? 0.0 : r;
}
}  // namespace

std::string lcd_azel(double az_deg, double el_deg) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "Az%6.1fEl%6.1f", tenths(az_deg), tenths(el_deg));
  return std::string(buf).substr(0, kLcdColumns);
}

std::string lcd_ma(double az_deg, double el_deg, double phase256) {
  long az = std::lround(az_deg);
  az = ((az % 360) + 360) % 360;  // 359.6 shows as 0, as a compass does
  long el = std::lround(el_deg);
  if (el == 0) el = 0;  // no "-0"
  // Tenths cut down, so that 255.97 stays 255.9 (phase is 0 to 255).
  const double p = std::clamp(std::floor(phase256 * 10.0) / 10.0, 0.0, 255.9);
  char buf[48];
  std::snprintf(buf, sizeof buf, "A%ld E%ld P%.1f", az, el, p);
  return std::string(buf).substr(0, kLcdColumns);
}

Lcd lcd_for(const tracker::SatNow& n, bool ma_display, char separator) {
  Lcd l;
  l.top = lcd_top(n.obs.time, n.name, separator);
  if (!n.obs.ok()) l.bottom = "No position";
  else if (ma_display) l.bottom = lcd_ma(n.obs.look.az_deg, n.obs.look.el_deg, n.obs.phase256);
  else l.bottom = lcd_azel(n.obs.look.az_deg, n.obs.look.el_deg);
  return l;
}

Lcd lcd_no_satellite(orbit::UtcTime t, int position) {
  return Lcd{format_time(t), ("No satellite #" + std::to_string(position)).substr(0, kLcdColumns)};
}

Led aos_led(bool in_range, bool track_switch) {
  if (!in_range) return Led::off;
  return track_switch ? Led::on : Led::blinking;
}

bool led_lit(Led led, orbit::UtcTime t) {
  switch (led) {
    case Led::off: return false;
    case Led::on: return true;
    case Led::blinking: break;
  }
  const auto s = std::chrono::floor<std::chrono::seconds>(t.time_since_epoch()).count();
  return s % 2 == 0;
}

const char* led_word(Led led) {
  switch (led) {
    case Led::on: return "on";
    case Led::blinking: return "blink";
    case Led::off: break;
  }
  return "off";
}

namespace {
std::string pad(std::string s, std::size_t width) {
  if (s.size() < width) s.append(width - s.size(), ' ');
  return s;
}
}  // namespace

std::string lcd_line(const Lcd& lcd, Led led) {
  return "|" + pad(lcd.top, kLcdColumns) + "|" + pad(lcd.bottom, kLcdColumns) + "| LED " + led_word(led);
}

std::vector<std::string> lcd_panel(const Lcd& lcd, Led led, orbit::UtcTime t, bool track_switch) {
  const std::string frame = "+" + std::string(kLcdColumns, '-') + "+";
  const char* lamp = led_lit(led, t) ? "(*)" : "( )";
  return {frame,
          "|" + pad(lcd.top, kLcdColumns) + "|   AOS " + lamp + " " + led_word(led),
          "|" + pad(lcd.bottom, kLcdColumns) + "|   Track switch " + (track_switch ? "ON" : "OFF"),
          frame};
}

// ---- the selector ----

std::optional<int> selector_key(int key, int current) {
  if (key >= '0' && key <= '9') return key - '0';
  if (key == '+' || key == '=') return std::min(current + 1, kSelectorPositions - 1);
  if (key == '-') return std::max(current - 1, 0);
  return std::nullopt;
}

// ---- the mode ----

namespace {

class Panel {
 public:
  Panel(term::Terminal& t, Services& s) : t_(t), s_(s) {}

  // The satellite at a selector position, if the tracking list has one there.
  std::optional<int> db_at(int position) const {
    const auto& sel = s_.model.db.selected;
    if (position < 1 || position > static_cast<int>(sel.size())) return std::nullopt;
    return sel[static_cast<std::size_t>(position - 1)];
  }
  bool multi_possible() const {
    return static_cast<int>(s_.model.db.selected.size()) >= store::kMinMultiTrack;
  }
  char separator() const {
    if (!multi_) return ' ';
    return s_.model.priority_mode ? '&' : '!';
  }

  // Moves the selector. Going 0 -> satellite position toggles single/multiple tracking.
  void select(int position) {
    if (position == position_) return;
    if (position == 0) {
      at_zero_ = true;
      position_ = 0;
      say("Selector 0: terminal mode. Enter: the menus; a satellite position: tracking again" +
          std::string(multi_possible() ? " (single/multiple toggles)." : "."));
      return;
    }
    if (at_zero_ && tracking_started_) {
      if (multi_possible()) multi_ = !multi_;
      else say("Multiple tracking needs two or more satellites in the tracking list: single tracking.");
    }
    at_zero_ = false;
    track(position);
  }

  // The power-on position (0: terminal mode; the first satellite position then starts single
  // tracking, with no toggle).
  void start(int position) {
    position = std::clamp(position, 0, kSelectorPositions - 1);
    if (position == 0) {
      at_zero_ = true;
      say("Selector 0: terminal mode. Enter: the menus; a satellite position: tracking.");
      return;
    }
    track(position);
  }

  // One update of the LCD and the LED.
  void show() {
    const orbit::UtcTime now = s_.clock.now();
    std::optional<tracker::SatNow> sat;
    const tracker::SatNow* f = s_.tracker.followed();
    // Multiple tracking: the LCD shows the satellite being tracked while it is AOS, else the one
    // the selector points at (the panel's version of menu M's "satellite displayed on the LCD").
    if (multi_ && f && f->in_range) sat = *f;
    const auto db = db_at(last_satellite_position_);
    if (!sat && db) {
      if (!multi_ && f && f->db_index == *db) sat = *f;
      else sat = s_.tracker.observe(*db, now);
    }
    Lcd lcd;
    if (sat) {
      const bool ma = s_.model.db.satellites[static_cast<std::size_t>(sat->db_index)].radio.lcd_ma_display;
      lcd = lcd_for(*sat, ma, separator());
    } else if (last_satellite_position_ > 0) {
      lcd = lcd_no_satellite(now, last_satellite_position_);
    } else {
      lcd = Lcd{format_time(now), "Terminal mode"};
    }
    const Led led = aos_led(sat && sat->in_range, s_.model.rotor_control);
    if (t_.full_screen()) t_.live(lcd_panel(lcd, led, now, s_.model.rotor_control));
    else t_.live({lcd_line(lcd, led)});
  }

  void toggle_track_switch() {
    tracker::StationOps(s_.station).rotor_control(!s_.model.rotor_control);
    say(std::string("Track switch ") + (s_.model.rotor_control ? "ON" : "OFF"));
    save_or_report(t_, s_);
  }

  bool at_zero() const { return at_zero_; }
  int position() const { return position_; }

 private:
  void say(const std::string& text) {
    t_.end_live();
    t_.line(text);
  }

  void track(int position) {
    position_ = position;
    last_satellite_position_ = position;
    tracking_started_ = true;
    const auto db = db_at(position_);
    std::string what;
    if (multi_) {
      if (s_.tracker.mode() != tracker::Mode::multi) s_.tracker.track_multi(s_.model.priority_mode);
      const int n = std::min<int>(s_.model.db.multi_count, static_cast<int>(s_.model.db.selected.size()));
      what = std::string("multiple tracking (") + (s_.model.priority_mode ? "priority" : "normal") + ") of #1-#" +
             std::to_string(n);
    } else if (db) {
      s_.tracker.track_single(*db);
      what = "single tracking";
    } else {
      s_.station.stop_antenna();
      what = "tracking stopped";
    }
    const std::string name = db ? s_.model.db.satellites[static_cast<std::size_t>(*db)].name()
                                : "no satellite in the tracking list";
    say("Selector " + std::to_string(position_) + ": " + name + ", " + what);
  }

  term::Terminal& t_;
  Services& s_;
  int position_ = 0;
  int last_satellite_position_ = 0;
  bool at_zero_ = false;
  bool tracking_started_ = false;  // a satellite position has been selected
  bool multi_ = false;
};

}  // namespace

void standalone(term::Terminal& t, Services& s, int selector, const std::function<void()>& terminal_mode) {
  t.clear();
  t.line("TrakBox standalone mode.  Selector: 0-9, +/- one position (to 15); 0 = terminal mode.");
  t.line("E = track switch, Q = quit; Enter at position 0 starts the menus.");
  // The track switch starts off: the LED blinks in range and the antenna stays put until E.
  tracker::StationOps(s.station).rotor_control(false);
  Panel panel(t, s);
  panel.start(selector);
  for (;;) {
    s.station.tick();
    panel.show();
    const int k = t.read_key(std::chrono::milliseconds(1000));
    if (k == term::kTimeout) continue;
    if (k == term::kEndOfInput) throw InputClosed{};
    if (k == 'q' || k == 'Q') {
      t.end_live();
      return;
    }
    if (k == 'e' || k == 'E') {
      panel.toggle_track_switch();
      continue;
    }
    if ((k == '\r' || k == '\n') && panel.at_zero()) {
      t.end_live();
      terminal_mode();
      return;
    }
    if (const auto p = selector_key(k, panel.position())) panel.select(*p);
  }
}

}  // namespace tb::menus
