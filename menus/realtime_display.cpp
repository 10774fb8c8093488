#include "menus/realtime_display.h"
#include "menus/realtime_log.h"
#include "menus/realtime_tuning.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "orbit/element_age.h"
#include "station/clock.h"
#include "store/model.h"
#include "tracker/operations.h"
#include "tracker/station_loop.h"

namespace tb::menus {

std::vector<std::string> tracking_list_names(const Services& s) {
  std::vector<std::string> names;
  for (int i : s.model.db.selected) names.push_back(s.model.db.satellites[static_cast<std::size_t>(i)].name());
  return names;
}

std::string format_realtime_row(const tracker::SatNow& n) {
  char buf[160];
  const std::string hms = format_time(n.obs.time);
  if (!n.obs.ok()) {
    std::snprintf(buf, sizeof buf, "%s  no position: %s (SGP4 error %d)", hms.c_str(), orbit::describe(n.obs.error),
                  static_cast<int>(n.obs.error));
    return buf;
  }
  // Doppler on the downlink F1 (0 when the satellite has no downlink frequency).
  std::snprintf(buf, sizeof buf, "%s%8.2f%8.2f%9.1f%9.1f%7.1f%7.1f%7.1f%+9ld", hms.c_str(), n.obs.look.az_deg,
                n.obs.look.el_deg, n.obs.look.range_km, n.obs.sub_point.alt_km, n.obs.sub_point.lat_deg,
                n.obs.sub_point.lon_deg, std::floor(n.obs.phase256), std::lround(n.downlink_doppler_hz));
  return buf;
}

std::string aos_text(orbit::UtcTime aos, orbit::UtcTime now) {
  const std::string date = format_date(aos);
  return (date == format_date(now) ? "" : date + " ") + format_time(aos);
}

std::string format_multi_row(const tracker::SatNow& n, char marker) {
  char buf[160];
  if (!n.obs.ok()) {
    std::snprintf(buf, sizeof buf, "%3d.%c%-10.10s  no position: %s", n.list_number, marker, n.name.c_str(),
                  orbit::describe(n.obs.error));
    return buf;
  }
  std::string next;
  // In range with its whole pass (menu M looks it up): when it rose and the whole pass's maximum.
  char whole[48];
  if (n.in_range && n.pass && !n.pass->up_at_start && n.pass->aos <= n.obs.time) {
    std::snprintf(whole, sizeof whole, "AOS now (%s, max %.1f)", aos_text(n.pass->aos, n.obs.time).c_str(),
                  n.pass->max_el_deg);
    next = whole;
  } else if (n.in_range) next = "AOS now";
  else if (n.pass) next = aos_text(n.pass->aos, n.obs.time);
  else next = "none in 24h";
  std::snprintf(buf, sizeof buf, "%3d.%c%-10.10s%8.2f%8.2f%9.1f  %-3s  %s", n.list_number, marker, n.name.c_str(),
                n.obs.look.az_deg, n.obs.look.el_deg, n.obs.look.range_km, n.in_range ? "AOS" : "", next.c_str());
  return buf;
}

std::string aos_indicator(bool in_range, bool rotor_control, orbit::UtcTime now) {
  if (!in_range) return "   ";
  if (rotor_control) return "AOS";
  const auto s = std::chrono::duration_cast<std::chrono::seconds>(now.time_since_epoch()).count();
  return (s % 2 == 0) ? "AOS" : "   ";
}

namespace {

const char* kHeader1 = "  UTC      Azim.   Elev.    Range     Alt.   Lat.  Long.  Phase  Doppler";
const char* kHeader2 = "HH:MM:SS     deg     deg       Km       Km    deg    deg  <256>       Hz";

}  // namespace

term::Graphics pass_graphics(Services& s, const tracker::SatNow& n) {
  term::Graphics g;
  // A satellite that stays up (geostationary) has no AOS or LOS to show.
  const bool always_up = n.pass && n.pass->up_at_start && n.pass->up_at_end;
  // A pass already up when the tracker searched it begins, for the tracker, at that search: the
  // title and the track show it whole, from when it rose (issue 47).
  std::optional<orbit::Pass> pass = n.pass;
  if (pass && pass->up_at_start && !always_up)
    if (const auto whole = s.tracker.pass_at(n.db_index, n.obs.time);
        whole && !whole->up_at_start && whole->aos <= n.obs.time && n.obs.time <= whole->los)
      pass = whole;
  g.title = n.name + (always_up ? "  always up"
                      : pass    ? "  pass " + aos_text(pass->aos, n.obs.time) + "-" +
                                     (pass->up_at_end ? std::string("...") : format_time(pass->los))
                                : "");
  if (pass) {
    const double minutes = orbit::minutes_between(pass->aos, pass->los);
    for (const auto& o : s.tracker.pass_track(n.db_index, *pass, std::clamp(static_cast<int>(minutes * 2), 2, 240)))
      g.pass_track.push_back({o.look.az_deg, o.look.el_deg});
  }
  if (n.obs.ok()) {
    g.satellite = term::SkyPoint{n.obs.look.az_deg, n.obs.look.el_deg};
    g.sub_point = std::pair{n.obs.sub_point.lat_deg, n.obs.sub_point.lon_deg};
    for (const auto& o : s.tracker.orbit_track(n.db_index, n.obs.time, 120))
      g.ground_track.emplace_back(o.sub_point.lat_deg, o.sub_point.lon_deg);
  }
  if (const auto a = s.station.antenna()) g.antenna = term::SkyPoint{a->az, a->el};
  g.station = std::pair{s.model.station.lat_deg, s.model.station.lon_deg};
  return g;
}

std::string describe_pass(const std::string& name, const orbit::Pass& p) {
  char buf[200];
  if (p.up_at_start && p.up_at_end) {
    std::snprintf(buf, sizeof buf, "%s: always up, az %.1f el %.1f: no AOS or LOS", name.c_str(), p.aos_az_deg,
                  p.max_el_deg);
    return buf;
  }
  std::snprintf(buf, sizeof buf, "%s: pass %s AOS %s az %.1f, max el %.1f at %s az %.1f, LOS %s az %.1f", name.c_str(),
                format_date(p.aos).c_str(), format_time(p.aos).c_str(), p.aos_az_deg, p.max_el_deg,
                format_time(p.tca).c_str(), p.tca_az_deg, format_time(p.los).c_str(), p.los_az_deg);
  return buf;
}

namespace {

std::string control_line(Services& s) {
  char buf[240];
  char antenna[32] = "---.-/--.-";
  if (const auto ant = s.station.antenna()) std::snprintf(antenna, sizeof antenna, "%.1f/%.1f", ant->az, ant->el);
  const auto& rs = s.station.rotator().status();
  std::string motion;
  if (!rs.link.ok()) motion = " FAULT: " + rs.link.message;
  else if (rs.az.motion != rotator::Drive::stop || rs.el.motion != rotator::Drive::stop) motion = " moving";
  const radio::RadioStatus rad = s.station.radio().status();
  auto mhz = [](std::optional<radio::Hz> hz) {
    char b[24] = "---";
    if (hz) std::snprintf(b, sizeof b, "%.5f", static_cast<double>(*hz) / 1e6);
    return std::string(b);
  };
  // The frequencies are the last ones the radio took: while it fails, the fault is shown instead.
  const std::string rig = rad.fault ? "RADIO FAULT: " + rad.message
                                    : "RX " + mhz(rad.downlink_hz) + " TX " + mhz(rad.uplink_hz) + " MHz";
  std::snprintf(buf, sizeof buf, "Rotor control %s  antenna %s%s | RIT %+ld Hz | %s",
                s.model.rotor_control ? "ON " : "OFF", antenna, motion.c_str(),
                static_cast<long>(s.station.tuner().rit_hz()), rig.c_str());
  return buf;
}

// The radio's links: the spot in the satellite's frame and the frequency sent, per link; dial
// follow's state; a warning when the spot is outside the transponder's passband.
std::string radio_line(Services& s) {
  const radio::Tuner& tu = s.station.tuner();
  const radio::SatelliteRadio& sat = tu.satellite();
  if (!sat.has_downlink() && !sat.has_uplink()) return "";
  const radio::RadioStatus rad = s.station.radio().status();
  auto mhz = [](std::optional<radio::Hz> hz) {
    char b[24] = "---";
    if (hz) std::snprintf(b, sizeof b, "%.6f", static_cast<double>(*hz) / 1e6);
    return std::string(b);
  };
  std::string line = "Spot D " + mhz(tu.downlink_spot_hz()) + " U " + mhz(tu.uplink_spot_hz()) + " | sent D " +
                     mhz(tu.last_sent_downlink_hz()) + " U " + mhz(tu.last_sent_uplink_hz());
  if (tu.dial_follow_active()) {
    line += " | dial follow";
    if (!rad.reads_downlink || !rad.reads_uplink)
      line += std::string(" (") + (rad.reads_downlink || rad.reads_uplink ? "one" : "no") + " dial readable)";
    const radio::LinearTransponder tp = *radio::transponder_of(sat);
    if (!tp.downlink_inside(tu.downlink_spot_hz()) || !tp.uplink_inside(tu.uplink_spot_hz()))
      line += " | SPOT OUTSIDE PASSBAND";
  } else if (sat.has_passbands()) {
    line += " | dial follow OFF";
  }
  // The operator's correction for this satellite and mode, kept for its next pass ('0' forgets it).
  if (tu.correction_remembered()) {
    const radio::Hz c = tu.config().corrections.at(tu.correction_key());
    line += " | correction " + std::string(c > 0 ? "+" : "") + std::to_string(c) + " Hz kept for " + tu.correction_key();
  }
  // The TX offset set from the page or host mode (OT), kept the same way.
  if (tu.xit_hz() != 0)
    line += " | TX " + std::string(tu.xit_hz() > 0 ? "+" : "") + std::to_string(tu.xit_hz()) + " Hz";
  return line;
}

// The shown satellite's elements: epoch and age now, and a warning past its orbit's limit
// (trakbox's line; the manual's display has none).
std::string elements_age_line(Services& s, int db_index) {
  if (tracker::body_target(db_index)) return "Geometric position of the centre (no refraction); no radio tuning";
  const orbit::Elements& e = s.model.db.satellites[static_cast<std::size_t>(db_index)].elements;
  const orbit::ElementAge age = orbit::element_age(e, s.clock.now());
  std::string line = "Elements: epoch " + format_date(e.epoch()) + " " + format_time(e.epoch()) + " UTC, age " + age.text();
  // The warning on a line of its own, short enough for 80 columns: appended, it wrapped
  // mid-sentence (issue 30).
  if (age.stale()) {
    char w[96];
    std::snprintf(w, sizeof w, "WARNING: elements too old (limit %.0f days): positions unreliable, see 3-5", age.limit_days);
    line += "\n" + std::string(w);
  }
  return line;
}

// A key typed under the live display, other than Q and the end of the input: E, Y, U, D, L, +, -, 0,
// and the typed tuning S, R, T, M (menus/realtime_tuning.h).
// `said`: what the typed tuning keys said (the full screen keeps it in the live block).
void realtime_key(term::Terminal& t, Services& s, int k, std::string& said) {
  switch (k) {
    case term::kTimeout: break;
    case 'e':
    case 'E':
      tracker::StationOps(s.station).rotor_control(!s.model.rotor_control);
      save_or_report(t, s);
      // Full screen shows it in the status line; a serial terminal gets a line (issue 18, item 6).
      if (!t.full_screen()) t.line(s.model.rotor_control ? "Rotor control ON" : "Rotor control OFF");
      break;
    case 'y':
    case 'Y':
      s.clock.zero_seconds();
      (void)commit(t, s, store::bit(store::Area::other), "clock offset", [&](store::Model& m) { m.clock_offset = s.clock.offset(); });
      break;
    case 'u':
    case 'U':
      // The later firmware's alternative uplinks (FREQ.DAT): the next channel, kept.
      if (const auto up = s.station.next_uplink()) {
        save_or_report(t, s);
        t.line("Uplink " + radio::format_mhz(*up) + " MHz");
      } else {
        t.line("No other uplink for this satellite (FREQ.DAT lists up to four)");
      }
      break;
    case 'd':
    case 'D':
      // Dial follow on linear transponders: the spot reached so far stays.
      if (commit(t, s, store::bit(store::Area::radio), std::string(tracker::kDialFollowEdit),
                 [&](store::Model& m) { m.radio.dial_follow = !m.radio.dial_follow; }))
        s.station.tuner().set_config(s.model.radio);
      if (!t.full_screen()) t.line(s.model.radio.dial_follow ? "Dial follow ON" : "Dial follow OFF");
      break;
    case 'l':
    case 'L':
      said = realtime_log_qso(t, s);  // a QSO of this pass into the logbook (menus/realtime_log.cpp)
      break;
    case '+':
    case '-':
    case '0':
      // The correction is remembered for this satellite and mode (StationOps::tune_offsets).
      said = realtime_step_offset(t, s, k == '+' ? 1 : k == '-' ? -1 : 0);
      break;
    case 's':
    case 'S':
      said = realtime_type_spot(t, s);
      break;
    case 'r':
    case 'R':
    case 't':
    case 'T':
      said = realtime_type_offset(t, s, k == 't' || k == 'T');
      break;
    case 'm':
    case 'M':
      said = realtime_type_mode(t, s);  // the satellite's mode (issue 59)
      break;
    default: break;
  }
}

}  // namespace

std::vector<std::string> LinkNotices::update(const rotator::Health& rotator, const radio::RadioStatus& radio) {
  std::vector<std::string> out;
  const bool rot_fault = rotator.state == rotator::LinkState::fault;
  if (rot_fault != rotator_fault_) out.push_back(rot_fault ? "Rotator FAULT: " + rotator.message : "Rotator link restored");
  if (radio.fault != radio_fault_) out.push_back(radio.fault ? "Radio FAULT: " + radio.message : "Radio working again");
  rotator_fault_ = rot_fault;
  radio_fault_ = radio.fault;
  return out;
}

RealtimeExit run_realtime_display(term::Terminal& t, Services& s, char marker, bool exit_on_change) {
  const orbit::UtcTime start = s.clock.now();
  t.clear();
  t.line("============ Realtime Tracking [" + format_date(start) + "] ============");
  t.line("'E' Toggle rotor control  'Y' RTC zero adjust  'Q' Return to main menu");
  t.line("'+/-/0' Doppler compensation  'U' next uplink channel  'D' dial follow on/off");
  t.line("'S' type the spot  'R'/'T' type the RX/TX offset  'L' log a QSO  'M' mode");
  std::optional<int> shown;
  bool was_in_range = false;       // the shown satellite was AOS on the last update
  LinkNotices notices;             // full screen has the status line instead
  std::string coverage_said;       // serial terminal: the coverage note last printed
  std::string radio_shown;         // serial terminal: the radio line last printed, without "sent"
  std::string said;                // full screen: what the last tuning key said, under the radio line
  for (;;) {
    s.station.tick();  // fresh numbers at once, not a second late
    if (!t.full_screen())
      for (const auto& n : notices.update(s.station.rotator().status().link, s.station.radio().status())) t.line(n);
    const tracker::SatNow* followed = s.tracker.followed();
    const tracker::SatNow* f = followed;
    if (!f && !s.tracker.candidates().empty()) f = &s.tracker.candidates().front();
    // Multiple tracking shows a satellite only while it is AOS: leave when the tracker follows
    // another one, none (the fallback above must not hide that), or this one has gone LOS.
    if (exit_on_change && shown &&
        (!followed || followed->db_index != *shown || (was_in_range && !followed->in_range))) {
      t.end_live();
      return RealtimeExit::followed_changed;
    }
    if (f && (!shown || *shown != f->db_index)) {
      t.end_live();
      t.line(std::string("[Satellite:") + marker + f->name + "]");
      {
        const std::string age = elements_age_line(s, f->db_index);
        for (std::size_t a = 0, b; a <= age.size(); a = b + 1) {
          b = std::min(age.find('\n', a), age.size());
          t.line(std::string_view(age).substr(a, b - a));
        }
      }
      t.line(kHeader1);
      t.line(kHeader2);
      shown = f->db_index;
    }
    was_in_range = f && f->in_range;
    if (f) {
      std::string row = format_realtime_row(*f) + "  " + aos_indicator(f->in_range, s.model.rotor_control, f->obs.time);
      while (row.back() == ' ') row.pop_back();
      // A pass the antenna cannot follow whole (limits, a split travel): how much it follows.
      const std::optional<std::string> coverage = s.station.coverage_note(f->db_index);
      if (t.full_screen()) {
        // Five lines always: the last, what a tuning key said (or blank), does not move the pictures.
        t.live({row, coverage.value_or(""), control_line(s), radio_line(s), said});
        // The pictures on every update, as the table: the satellite's @ and the antenna's X are the
        // numbers of the row above. (Drawn only on clock seconds divisible by 5, they stood still
        // under --clock-rate 10, whose updates step 10 s at a time: issue 30 item 8.)
        t.graphics(pass_graphics(s, *f));
      } else {
        if (coverage && *coverage != coverage_said) {
          t.end_live();
          t.line(*coverage);
        }
        t.live({row});
        // A serial terminal gets the radio line when the spot or dial follow's state changes.
        std::string radio = radio_line(s);
        std::string key = radio;
        if (const auto a = key.find(" | sent "), b = key.find(" | ", a + 1); a != std::string::npos)
          key.erase(a, b == std::string::npos ? std::string::npos : b - a);
        if (key != radio_shown) {
          t.end_live();
          if (!radio.empty()) t.line(radio);
          radio_shown = key;
        }
      }
      coverage_said = coverage.value_or("");
    }
    // Wait for a key until the next whole second of the (possibly accelerated) clock.
    // Sooner when a link waits for the operator's knob to rest, so it moves as soon as it has.
    const int k = t.read_key(std::min(std::chrono::milliseconds(1000),
                                      s.station.radio_due_in().value_or(std::chrono::milliseconds(1000))));
    if (k == term::kEndOfInput) throw InputClosed{};
    if (k == 'q' || k == 'Q') {
      t.end_live();
      // The sky plot and map stay on a full screen until cleared: the menu after them printed
      // over their remains (issue 30).
      if (t.full_screen()) t.clear();
      return RealtimeExit::quit;
    }
    if (k != term::kTimeout) said.clear();   // said until the next key
    realtime_key(t, s, k, said);
  }
}

}  // namespace tb::menus
