// 6-1: Calibration of antenna span value. The antenna is brought fully CCW at the horizon, then fully
// CW and straight up; the raw ADC counts at the two points become the new span. trakbox may be the
// rotator's only control box, so while it waits the operator can drive the antenna with the keys of
// 6-6-1 (4/6/8/2/5) and watch the live monitor line; an axis driven into its end stop stalls and
// stops there, which is the reading wanted.
#include <cctype>

#include "menus/6_configuration.h"
#include "rotator/controller.h"
#include "store/model.h"
#include "tracker/station_loop.h"

namespace tb::menus {

void menu_6_1_calibration(term::Terminal& t, Services& s) {
  t.line(span_line(s.model.rotator));
  s.station.stop_antenna();  // direct control: tracking stops
  const bool keys = cfg::offer_rotor_control(t, s, "keys 4/6/8/2/5 will not move the antenna.");
  t.line(keys ? "Left(4),Right(6),Up(8),Dwn(2),Stop(5) move the antenna; Y when it is there."
              : "Move the antenna with its own control box; Y when it is there.");
  struct Point {
    const char* where;
    const char* prompt;
  };
  const Point points[2] = {{"Rotate the antenna to fully CCW and", "Elevation minimum position [Y/N] ? "},
                           {"Rotate the antenna to fully CW and", "Elevation maximum position [Y/N] ? "}};
  rotator::SpanCalibration cal;
  for (int i = 0; i < 2; ++i) {
    t.line(points[i].where);
    cfg::LiveMonitor m(t, s, {points[i].prompt});
    bool said_off = false;
    for (;;) {
      const int k = m.key();
      if (k == term::kTimeout || k < 0) continue;
      const char c = static_cast<char>(std::toupper(k));
      if (c == '4' || c == '6' || c == '8' || c == '2' || c == '5') {
        if (s.station.rotor_control()) {
          s.station.rotator().manual_key(c);
        } else if (!said_off) {
          m.note("Rotor control is OFF: the keys do not move the antenna.");
          said_off = true;
        }
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
      if (c == 'N' || c == 'Q') {
        m.set_below({std::string(points[i].prompt) + c});
        m.end();
        s.station.stop_antenna();
        t.line("Not changed.");
        return;
      }
    }
  }
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
