// Menu 6: Configuration. The list of items 0-9, the 6-0 display, and what the items share.
#include "menus/6_configuration.h"
#include "store/drivers.h"

#include <cctype>
#include <cmath>
#include <cstdarg>
#include <cstdio>

#include "rotator/controller.h"
#include "store/model.h"
#include "tracker/operations.h"
#include "tracker/station_loop.h"
#include "tracker/web_url.h"

namespace tb::menus {

namespace {

std::string config_fmt(const char* f, ...) __attribute__((format(printf, 1, 2)));
std::string config_fmt(const char* f, ...) {
  char buf[256];
  va_list ap;
  va_start(ap, f);
  std::vsnprintf(buf, sizeof buf, f, ap);
  va_end(ap);
  return buf;
}

std::string label(const char* l) { return config_fmt("%-17s", l); }

const char* yn(bool b) { return b ? "Y" : "N"; }

void show_list(term::Terminal& t) {
  t.line("====== Configuration Menu ======");
  t.line(" 0. Display all configured value");
  t.line(" 1. Calibration of antenna span value");
  t.line(" 2. Set ADC span value");
  t.line(" 3. Set Dead Band and Skew value");
  t.line(" 4. Set Antenna Parking and Limit position");
  t.line(" 5. Monitor ADC value & Antenna position");
  t.line(" 6. Direct antenna control");
  t.line(" 7. Radio CAT port configuration");
  t.line(" 8. Mic click configuration");
  t.line(" 9. Set default parameter");
  t.line(" R. Rotor control (kept over a restart)");
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// The list.

void menu_6_configuration(term::Terminal& t, Services& s) {
  run_menu(t, [&] { show_list(t); }, " Select: ", [&](char key) {
    if (key == 'Q') return MenuStep::back;
    // Esc at any line prompt of an item leaves it with nothing changed, as Q does (issue 39): the
    // items edit copies and commit only at their end.
    EscapeLeaves esc(t);
    try {
      switch (key) {
        case '0': menu_6_0_display(t, s); break;
        case '1': menu_6_1_calibration(t, s); break;
        case '2': menu_6_2_adc_span(t, s); break;
        case '3': menu_6_3_dead_band_skew(t, s); break;
        case '4': menu_6_4_parking_limits(t, s); break;
        case '5': menu_6_5_monitor(t, s); break;
        case '6': menu_6_6_direct_control(t, s); break;
        case '7': menu_6_7_radio_cat(t, s); break;
        case '8': menu_6_8_mic_click(t, s); break;
        case '9': menu_6_9_default_parameter(t, s); break;
        case 'R': menu_6_r_rotor_control(t, s); break;
        default: return MenuStep::unknown;
      }
    } catch (const cfg::Quit&) {
      t.end_live();
    } catch (const Escaped&) {
      t.end_live();
      t.line("Not changed.");
    }
    return MenuStep::again;
  });
}

// ---------------------------------------------------------------------------------------------
// 6-0

std::string span_line(const rotator::RotatorConfig& c) {
  return config_fmt("ADC span value AZ:%04d-%04d EL:%04d-%04d", c.az_span.min, c.az_span.max, c.el_span.min, c.el_span.max);
}

std::vector<std::string> preset_lines(const rotator::RotatorConfig& c) {
  std::vector<std::string> items;
  for (std::size_t i = 0; i < c.presets.size(); ++i)
    items.push_back(std::to_string(i + 1) + ":" + cfg::fmt1(c.presets[i].az) + "/" + cfg::fmt1(c.presets[i].el));
  std::string all = " ";
  for (const auto& it : items) all += it + " ";
  all.pop_back();
  if (all.size() <= 55) return {all};
  std::string first = " ", second = "   ";
  for (std::size_t i = 0; i < items.size(); ++i) (i < 3 ? first : second) += items[i] + " ";
  first.pop_back();
  second.pop_back();
  return {first, second};
}

std::vector<std::string> configuration_lines(const store::Model& m) {
  const auto& st = m.station;
  const auto& r = m.rotator;
  const auto& rc = m.radio;
  std::vector<std::string> out;
  out.push_back(config_fmt("Callsign:%s  Lat:%s Long:%s Hgt:%s", st.callsign.c_str(), cfg::fmt1(st.lat_deg).c_str(),
                    cfg::fmt1(st.lon_deg).c_str(), cfg::fmt1(st.height_m).c_str()));
  // An overlap rotator's travel (--az-travel) is shown only when it is not the TrakBox's 360.
  out.push_back(label("ADC span value") + config_fmt("AZ:%4d - %4d  EL:%4d - %4d", r.az_span.min, r.az_span.max, r.el_span.min,
                                              r.el_span.max) +
                (r.az_travel_deg != 360.0 ? config_fmt("  travel %.0f deg", r.az_travel_deg) : ""));
  out.push_back(label("Dead band") + "AZ:" + cfg::fmt1(r.az_dead_band) + " EL:" + cfg::fmt1(r.el_dead_band) +
                "  Skew AZ:" + cfg::fmt1(r.az_skew) + " EL:" + cfg::fmt1(r.el_skew));
  out.push_back(label("Antenna parking") +
                (r.parking_enabled ? "On  AZ:" + cfg::fmt1(r.parking.az) + " EL:" + cfg::fmt1(r.parking.el) : "Off"));
  // "cross": limits that split the travel may be crossed between passes (shown only when on, so
  // the manual's screen is unchanged otherwise).
  out.push_back(label("Rotator limit") +
                (r.limits_enabled ? "On  AZ:" + cfg::fmt1(r.az_limit_min) + "-" + cfg::fmt1(r.az_limit_max) +
                                        " EL:" + cfg::fmt1(r.el_limit_min) + "-" + cfg::fmt1(r.el_limit_max) +
                                        (r.cross_limit_sector ? "  cross between passes" : "")
                                  : "Off"));
  out.push_back(label("Preset position") + text::trimmed(preset_lines(r).front()) +
                (preset_lines(r).size() > 1 ? " " + text::trimmed(preset_lines(r).back()) : ""));
  std::string cat = std::string(radio::to_string(rc.rig)) +
                    (rc.cat_policy == radio::CatPolicy::aos_only ? " AOS" : " Full");
  if (rc.rig == radio::Rig::icom) cat += config_fmt("  RX:%02XH TX:%02XH", rc.icom_rx_address, rc.icom_tx_address);
  if (rc.rig == radio::Rig::yaesu && rc.ft736_wide_fm) cat += "  FT-736 wide FM";
  // The later firmware's STATION.DAT items: shown only when set, so the manual's screen is unchanged.
  if (rc.rig_model != radio::RigModel::generic) cat += std::string("  ") + radio::to_string(rc.rig_model);
  if (rc.cat_baud > 0) cat += config_fmt("  %d Bd", rc.cat_baud);
  out.push_back(label("CAT Rig") + cat);
  const char* down = rc.downlink_correction == radio::DownlinkCorrection::on        ? "Y"
                     : rc.downlink_correction == radio::DownlinkCorrection::reverse ? "R"
                                                                                    : "N";
  out.push_back(label("Doppler correct.") + "Up:" + yn(rc.uplink_correction) + " Down:" + down);
  const auto& mc = rc.mic_click;
  out.push_back(config_fmt("Step control ADC value Center:%d Reff:%d", mc.centre_adc, mc.reference_adc));
  out.push_back(label("Frequency step") + config_fmt("%lld Hz", static_cast<long long>(mc.step_hz)));
  out.push_back(label("Mic click at AOS") + "CAT:" + yn(mc.cat_at_aos) + " Up pulse:" + yn(mc.auto_up_at_aos) +
                " Polarity:" + (mc.polarity == radio::PulsePolarity::normal ? "Normal" : "Reverse"));
  const store::PassEvents& pe = m.pass_events;
  const store::PassEvents factory;
  out.push_back(label("Rotor start") + station::to_string(st.rotor_start) +
                (pe.rotor_start_el_deg != factory.rotor_start_el_deg ? "  above EL:" + cfg::fmt1(pe.rotor_start_el_deg)
                                                                     : ""));
  out.push_back(label("COM port") + config_fmt("%d Baud 8-N-1", st.com_baud));
  if (rc.parking.enabled) {
    auto link = [](radio::Hz hz, radio::Mode mode) {
      return (hz > 0 ? config_fmt("%.3f", static_cast<double>(hz) / 1e6) : std::string("-")) + " " + radio::to_string(mode);
    };
    out.push_back(label("Radio parking") + "On  RX:" + link(rc.parking.rx_hz, rc.parking.rx_mode) +
                  " TX:" + link(rc.parking.tx_hz, rc.parking.tx_mode));
  }
  if (pe.output_on_el_deg != factory.output_on_el_deg || pe.output_off_el_deg != factory.output_off_el_deg)
    out.push_back(label("AOS/LOS line") + "On above EL:" + cfg::fmt1(pe.output_on_el_deg) +
                  "  Off below EL:" + cfg::fmt1(pe.output_off_el_deg));
  if (!m.rotator_error_detection) out.push_back(label("Rotator error") + "Detection off");
  // trakbox's line (issue 30): which drivers the antenna and the radio are on.
  auto driver = [](const std::string& spec) {
    const std::string name = store::driver_label(spec);
    return spec.empty() || spec == "simulated" ? name + " (simulated)" : name + " (" + spec + ")";
  };
  out.push_back(label("Drivers") + "Rotor " + driver(m.rotator_driver) + "  Radio " + driver(m.radio_driver) +
                (rc.uplink_radio.empty() ? "" : "  Uplink " + driver(rc.uplink_radio)));
  return out;
}

void menu_6_0_display(term::Terminal& t, Services& s) {
  for (const auto& l : configuration_lines(s.model)) t.line(l);
  if (!tracker::web_page_url().empty()) t.line(label("Web page") + tracker::web_page_url());
  t.write("Press any key to continue");
  t.flush();
  if (t.read_key() == term::kEndOfInput) throw InputClosed{};
  t.line();
}

// ---------------------------------------------------------------------------------------------
// Shared pieces.

namespace cfg {

std::string fmt1(double v) {
  double r = std::round(v * 10.0) / 10.0;
  if (r == 0.0) r = 0.0;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", r);
  return buf;
}

std::string answer(term::Terminal& t, std::string_view prompt) {
  t.write(prompt);
  t.flush();
  std::string a = text::trimmed(read_line(t));
  if (a == "Q" || a == "q") throw Quit{};
  return a;
}

double ask_number(term::Terminal& t, std::string_view prompt, std::optional<double> current, double lo, double hi,
                  bool whole) {
  for (;;) {
    const std::string a = answer(t, prompt);
    if (a.empty()) {
      if (current) return *current;
      t.line("  Enter a value (Q to leave)");
      continue;
    }
    const auto v = parse_number(a);
    if (!v) {
      t.line("  '" + a + "' is not a number");
      continue;
    }
    if (whole && *v != std::floor(*v)) {
      t.line("  " + a + " is not a whole number");
      continue;
    }
    if (*v < lo || *v > hi) {
      t.line(config_fmt("  %s is out of range: expected %g to %g", a.c_str(), lo, hi));
      continue;
    }
    return *v;
  }
}

char ask_choice(term::Terminal& t, std::string_view prompt, std::string_view keys) {
  for (;;) {
    t.write(prompt);
    t.flush();
    const auto c = t.read_choice();
    if (!c) throw InputClosed{};
    if (*c == 'Q') throw Quit{};
    if (*c != '\r' && keys.find(*c) != std::string_view::npos) return *c;
  }
}

std::vector<std::string> wrap_words(std::string_view text, std::size_t width, std::string_view indent) {
  std::vector<std::string> out;
  std::string line;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && text[i] == ' ') ++i;
    std::size_t j = text.find(' ', i);
    if (j == std::string_view::npos) j = text.size();
    if (j == i) break;
    const std::string_view word = text.substr(i, j - i);
    const std::string lead = out.empty() ? "" : std::string(indent);
    if (!line.empty() && lead.size() + line.size() + 1 + word.size() > width) {
      out.push_back(lead + line);
      line.clear();
    }
    line += (line.empty() ? "" : " ") + std::string(word);
    i = j;
  }
  if (!line.empty()) out.push_back((out.empty() ? "" : std::string(indent)) + line);
  return out;
}

bool commit_rotator(term::Terminal& t, Services& s, const rotator::RotatorConfig& next) {
  const auto problems = rotator::validate(next);
  if (!problems.empty()) {
    t.bell();
    for (const auto& p : problems) t.line("  " + p);
    t.line("Not changed.");
    return false;
  }
  // Through the one door: the whole model checked as the next start reads it, the rotator
  // reconfigured by the station, saved.
  return commit(t, s, store::bit(store::Area::rotator), "rotator settings", [&](store::Model& m) { m.rotator = next; });
}

void take_rotor_control(term::Terminal& t, Services& s) {
  if (s.station.rotor_control()) return;
  tracker::StationOps(s.station).rotor_control(true);
  t.line("Rotor control switched ON (E key in the realtime display switches it OFF).");
  save_or_report(t, s);
}

LiveMonitor::LiveMonitor(term::Terminal& t, Services& s, std::vector<std::string> below,
                         std::function<std::string()> line)
    : t_(t), s_(s), line_(std::move(line)), message_(s.station.rotator().status().message) {
  set_below(std::move(below));
  update(true);
}

LiveMonitor::~LiveMonitor() { end(); }

// Full screen: the lines below are part of the live block, redrawn in place. Line mode: they are
// printed once when they change (a prompt is not repeated with every reading).
void LiveMonitor::set_below(std::vector<std::string> below) {
  if (below == below_) return;
  below_ = std::move(below);
  if (t_.full_screen()) {
    update();
  } else {
    end();
    for (const auto& l : below_) t_.line(l);
  }
}

void LiveMonitor::update(bool force) {
  const auto& st = s_.station.rotator().status();
  if (st.message != message_) {
    message_ = st.message;
    if (!message_.empty()) {
      end();
      t_.line(message_);
      force = true;
    }
  }
  std::vector<std::string> lines{line_ ? line_() : rotator::format_monitor_line(st)};
  if (t_.full_screen()) lines.insert(lines.end(), below_.begin(), below_.end());
  if (!force && live_ && lines == shown_) return;
  t_.live(lines);
  shown_ = std::move(lines);
  live_ = true;
}

void LiveMonitor::note(std::string_view text) {
  end();
  t_.line(text);
  update(true);
}

int LiveMonitor::key() {
  const int k = t_.read_key(kLiveInterval);
  if (k == term::kEndOfInput) throw InputClosed{};
  update();
  return k;
}

void LiveMonitor::end() {
  if (live_) t_.end_live();
  live_ = false;
}

void watch_until_arrived(term::Terminal& t, Services& s) {
  // The controller's status describes a new target as soon as it is set (Controller::set_target),
  // so a resting antenna's previous arrival is never taken for this one.
  LiveMonitor m(t, s);
  for (;;) {
    const int k = m.key();
    if (k != term::kTimeout) {
      if (k == '5') s.station.stop_antenna();
      break;
    }
    const auto& st = s.station.rotator().status();
    if (st.on_target || st.mode != rotator::ControlMode::target) break;
    if ((st.az.stalled || st.el.stalled) && st.az.motion == rotator::Drive::stop &&
        st.el.motion == rotator::Drive::stop)
      break;
  }
  m.update();
  m.end();
}

}  // namespace cfg
}  // namespace tb::menus
