// Menu 5: Update Realtime Clock. Y zeroes the seconds, Q leaves, Enter sets the clock.
// The clock is system time plus an offset: setting it changes the stored offset only.
#include <chrono>
#include <cmath>

#include "gps/monitor.h"
#include "menus/menus.h"
#include "station/clock.h"
#include "store/model.h"
#include "tracker/station_loop.h"

namespace tb::menus {

void menu_5_realtime_clock(term::Terminal& t, Services& s) {
  t.line("Enter 'Y' for zero sec. adjustment");
  t.line("Enter 'Q' for exit");
  t.line("Enter 'Ret' for Real Time Clock set");
  const gps::Monitor* g = s.station.gps();
  if (g) t.line("Enter 'G' for the clock from GPS time (" + g->describe() + ")");
  for (;;) {
    const auto now = s.clock.now();
    t.live({"Present Time:UTC " + format_date(now) + " " + format_time(now)});
    const int k = t.read_key(std::chrono::seconds(1));
    if (k == term::kTimeout) continue;
    t.end_live();
    if (k == term::kEndOfInput) throw InputClosed{};
    if (k == 'y' || k == 'Y') {
      s.clock.zero_seconds();
      (void)commit(t, s, store::bit(store::Area::other), "clock offset", [&](store::Model& m) { m.clock_offset = s.clock.offset(); });
      t.line("Present Time:UTC " + format_date(s.clock.now()) + " " + format_time(s.clock.now()));
      return;
    }
    if (g && (k == 'g' || k == 'G')) {
      // GPS time minus the clock at the receiver's last report becomes part of the offset.
      if (!g->filter().fixed() || g->link() != gps::Link::receiving || !g->clock_error_s()) {
        t.line("  no GPS fix: the clock is left alone");
        continue;
      }
      s.clock.set_offset(s.clock.offset() +
                         std::chrono::microseconds(std::llround(*g->clock_error_s() * 1e6)));
      (void)commit(t, s, store::bit(store::Area::other), "clock offset", [&](store::Model& m) { m.clock_offset = s.clock.offset(); });
      t.line("Present Time:UTC " + format_date(s.clock.now()) + " " + format_time(s.clock.now()) + " (from GPS)");
      return;
    }
    if (k == 'q' || k == 'Q') return;
    if (k == term::kEnter) break;
  }
  t.line("Set realtime Clock.");
  t.line("Present Time: UTC " + format_date(s.clock.now()) + " " + format_time(s.clock.now()));
  t.line("Enter with format [YY/MM/DD HH:MM:SS]");
  orbit::UtcTime target;
  for (;;) {
    t.write("Set time: ");
    t.flush();
    const std::string a = read_line(t);
    if (a.empty()) return;  // nothing entered: the clock is left alone
    if (const auto v = parse_yymmdd_hhmmss(a)) {
      target = *v;
      break;
    }
    t.line("  '" + a + "' is not a time: expected YY/MM/DD HH:MM:SS, e.g. 93/07/17 03:03:15");
  }
  t.write("ENTER when ready. ");
  t.flush();
  for (;;) {
    const int k = t.read_key();
    if (k == term::kEndOfInput) throw InputClosed{};
    if (k == term::kEnter) break;
  }
  s.clock.set(target);  // the moment Enter was pressed
  (void)commit(t, s, store::bit(store::Area::other), "clock offset",
               [&](store::Model& m) { m.clock_offset = s.clock.offset(); });
  t.line();
  t.line("Present Time:UTC " + format_date(s.clock.now()) + " " + format_time(s.clock.now()));
}

}  // namespace tb::menus
