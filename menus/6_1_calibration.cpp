// 6-1: Calibration of antenna span value. The antenna is brought fully CCW at the horizon, then fully
// CW and straight up; the raw ADC counts at the two points become the new span. trakbox may be the
// rotator's only control box, so while it waits the operator can drive the antenna with the keys of
// 6-6-1 (4/6/8/2/5) and watch the live monitor line.
//
// While calibrating, the controller runs on a calibration configuration: no rotation limits, no skew,
// both spans the whole ADC (0..1023), so keyboard drive reaches the mechanical ends whatever the old
// span was (an elevation pot reading above the old 90-degree count could not be reached otherwise).
// An axis driven into its end stop stalls and is stopped by the controller: that is the reading
// wanted. Elevation must be stopped (5) straight up if the rotator goes on past 90 degrees; in the
// later firmware's flip mode (STATION.DAT's F, rotator.el_flip_allowed) the second point is the
// 180-degree one instead ("you must calibrate the EL rotor at 0 and 180 degree point"). The
// degrees on the monitor line are the old calibration's; the model is put back on leaving.
#include <cctype>

#include "menus/6_configuration.h"
#include "rotator/calibration.h"
#include "rotator/controller.h"
#include "store/model.h"
#include "tracker/operations.h"
#include "tracker/station_loop.h"

namespace tb::menus {

namespace {

// The controller on the calibration configuration for as long as this lives; then the model's again.
class CalibrationDrive {
 public:
  explicit CalibrationDrive(Services& s) : s_(s) {
    rotator::RotatorConfig c = s.model.rotator;
    c.limits_enabled = false;
    c.az_skew = c.el_skew = 0;
    c.az_span = {0, rotator::kAdcMaxCount};
    c.el_span = {0, rotator::kAdcMaxCount};
    c.el_flip_allowed = false;
    s.station.rotator().set_config(c, s.model.station.rotor_start);
  }
  ~CalibrationDrive() {
    s_.station.stop_antenna();
    s_.station.reconfigure();
  }
  CalibrationDrive(const CalibrationDrive&) = delete;
  CalibrationDrive& operator=(const CalibrationDrive&) = delete;

 private:
  Services& s_;
};

}  // namespace

void menu_6_1_calibration(term::Terminal& t, Services& s) {
  t.line(span_line(s.model.rotator));
  s.station.stop_antenna();  // direct control: tracking stops
  const rotator::AdcModel old(s.model.rotator, s.model.station.rotor_start);
  // The monitor line: raw counts, and degrees as the old calibration reads them.
  auto monitor = [&s, &old] {
    const auto& st = s.station.rotator().status();
    if (!st.has_position) return rotator::format_monitor_line(st);
    return rotator::format_monitor_line(st.az.counts, old.az_deg_from_raw(st.az.counts), st.el.counts,
                                        old.el_deg_from_raw(st.el.counts));
  };
  // Rotor control is taken by the first key that moves the antenna, not by opening 6-1: a stray
  // '1' (a key misrouted after a resize) must not switch on a real antenna (issue 39).
  t.line("Left(4),Right(6),Up(8),Dwn(2),Stop(5) move the antenna (or its own control box); Y when it is there.");
  struct Point {
    const char* where;
    const char* prompt;
  };
  const bool flip = s.model.rotator.el_flip_allowed;
  const Point points[2] = {{"Rotate the antenna to fully CCW and", "Elevation minimum position [Y/N] ? "},
                           {"Rotate the antenna to fully CW and",
                            flip ? "Elevation 180 degree (flip) position [Y/N] ? " : "Elevation maximum position [Y/N] ? "}};
  rotator::SpanCalibration cal;
  std::optional<CalibrationDrive> drive(std::in_place, s);
  for (int i = 0; i < 2; ++i) {
    t.line(points[i].where);
    cfg::LiveMonitor m(t, s, {points[i].prompt}, monitor);
    for (;;) {
      const int k = m.key();
      if (k == term::kTimeout || k < 0) continue;
      const char c = static_cast<char>(std::toupper(k));
      if (c == '4' || c == '6' || c == '8' || c == '2' || c == '5') {
        if (!s.station.rotor_control() && c != '5') {
          tracker::StationOps(s.station).rotor_control(true);  // the operator's key to move it: explicit
          m.note("Rotor control switched ON (E key in the realtime display switches it OFF).");
          if (const auto& failed = s.station.save_failure()) m.note("State not saved: " + *failed);
        }
        if (s.station.rotor_control()) s.station.rotator().manual_key(c);
        continue;
      }
      if (c == 'Y') {
        const auto raw = s.station.rotator().raw_counts();
        if (!raw || !s.station.rotator().status().has_position) {
          m.note("No ADC reading from the rotator: nothing to record.");
          continue;
        }
        m.set_below({std::string(points[i].prompt) + "Y"});
        m.end();
        s.station.stop_antenna();
        if (i == 0)
          cal.record_min(*raw);
        else
          cal.record_max(*raw);
        break;
      }
      if (c == 'N' || c == 'Q' || k == term::kEscape) {  // Esc leaves unchanged, as N does (issue 39)
        m.set_below({std::string(points[i].prompt) + (k == term::kEscape ? 'N' : c)});
        m.end();
        s.station.stop_antenna();
        t.line("Not changed.");
        return;
      }
    }
  }
  drive.reset();  // the model's configuration again
  const auto result = cal.result();
  if (!result.ok()) {
    t.bell();
    t.line("  " + result.error);
    t.line("Not changed.");
    return;
  }
  if (cfg::commit_rotator(t, s, cal.apply(s.model.rotator))) t.line(span_line(s.model.rotator));
}

}  // namespace tb::menus
