// M: Multiple Tracking Mode. The first N satellites of the tracking list (N from menu 3-4) are
// computed together; a table shows them live until one is AOS, then the realtime display follows it
// (the lowest list number wins a tie). Normal mode stays with that satellite until its LOS; priority
// mode re-evaluates every second and slews to a higher-priority (lower-numbered) satellite that
// comes into view. After LOS the table is back. The rules live in tracker::choose_multi.
#include <algorithm>

#include "menus/realtime_display.h"
#include "menus/standalone.h"
#include "menus/take_back.h"
#include "store/model.h"
#include "tracker/operations.h"
#include "tracker/station_loop.h"

namespace tb::menus {

namespace {

char marker_for(bool priority) { return priority ? '&' : '!'; }

// The sub-mode: N or P; Enter keeps the last choice; Q leaves.
std::optional<bool> ask_priority(term::Terminal& t, const Services& s) {
  const std::string prompt =
      std::string("Normal or Priority mode ? [N/P] (Enter = ") + (s.model.priority_mode ? "P" : "N") + ") ";
  const char c = ask_key(t, prompt, "NPQ", true);
  if (c == 'Q') return std::nullopt;
  if (c == '\r') return s.model.priority_mode;
  return c == 'P';
}

void table_header(term::Terminal& t, Services& s, bool priority) {
  t.clear();
  t.line("=========== Multiple Tracking [" + format_date(s.clock.now()) + "] " +
         (priority ? "Priority" : "Normal") + " mode ===========");
  t.line("'E' Toggle rotor control  'Q' Return to main menu");
  t.line(priority ? "The AOS satellite with the lowest number is tracked ('&'); a higher one preempts."
                  : "The first satellite to come AOS is tracked ('!') until its LOS.");
  t.line(kMultiHeader1);
  t.line(kMultiHeader2);
}

// The table's live lines: one row per satellite, then rotor control and the LCD.
std::vector<std::string> table_lines(Services& s, int lcd_db_index, char marker) {
  const auto& cands = s.tracker.candidates();
  const tracker::SatNow* f = s.tracker.followed();
  // The active satellite: the one tracked (AOS, or waited for at its AOS); else the LCD's.
  const int active = f ? f->db_index : lcd_db_index;
  std::vector<std::string> lines;
  const tracker::SatNow* lcd_sat = nullptr;
  for (const auto& c : cands) {
    // A pass up when the tracker searched it begins there for the tracker: the row shows it whole.
    tracker::SatNow row = c;
    if (row.in_range && row.pass && row.pass->up_at_start && !row.pass->up_at_end)
      if (const auto whole = s.tracker.pass_at(row.db_index, row.obs.time);
          whole && !whole->up_at_start && whole->aos <= row.obs.time && row.obs.time <= whole->los)
        row.pass = whole;
    lines.push_back(format_multi_row(row, c.db_index == active ? marker : ' '));
    if (c.db_index == lcd_db_index) lcd_sat = &c;
  }
  std::string lcd = "(none)";
  if (lcd_sat) {
    const bool ma = s.model.db.satellites[static_cast<std::size_t>(lcd_sat->db_index)].radio.lcd_ma_display;
    lcd = lcd_line(lcd_for(*lcd_sat, ma, marker), aos_led(lcd_sat->in_range, s.model.rotor_control));
  }
  lines.push_back(std::string("Rotor control ") + (s.model.rotor_control ? "ON " : "OFF") + "  LCD " + lcd);
  return lines;
}

}  // namespace

void menu_m_multiple_tracking(term::Terminal& t, Services& s) {
  const std::vector<std::string> names = tracking_list_names(s);
  if (names.empty()) {
    t.line("No satellite selected: load elements with menu 3-3 and select with 3-2.");
    return;
  }
  if (static_cast<int>(names.size()) < store::kMinMultiTrack) {
    t.line("Multiple tracking needs two or more satellites in the tracking list (menu 3-2).");
    return;
  }
  const int n = std::clamp(s.model.db.multi_count, store::kMinMultiTrack,
                           std::min<int>(store::kMaxMultiTrack, static_cast<int>(names.size())));
  const auto priority = ask_priority(t, s);
  if (!priority) return;
  const char marker = marker_for(*priority);

  // Which satellite the LCD shows: one of the N, marked with the sub-mode's marker.
  const std::vector<std::string> multi_names(names.begin(), names.begin() + n);
  const int marked = (s.model.db.marked >= 0 && s.model.db.marked < n) ? s.model.db.marked : 0;
  const auto pick = choose_satellite(t, "     *** LCD display satellite ***", multi_names, marked, marker);
  if (!pick) return;

  if (!commit(t, s, store::bit(store::Area::tracking_list), "LCD satellite",
              [&](store::Model& m) { m.db.marked = *pick; }))
    return;
  const int lcd_db_index = s.model.db.selected[static_cast<std::size_t>(*pick)];
  const bool prio = *priority;
  if (!with_confirmation(t, s.station, [prio](tracker::StationOps& o) { return o.track_multi(prio); }).ok())
    return;  // stores the sub-mode; asks first when an outside client holds the antenna
  tracker::StationOps ops(s.station);
  ops.rotor_control(true);     // as S: the antenna follows (E turns it off)
  save_or_report(t, s);

  bool header = true;
  for (;;) {
    s.station.tick();
    if (const tracker::SatNow* f = s.tracker.followed(); f && f->in_range) {
      // One is AOS: the realtime display for it, until it goes LOS or another preempts it (then
      // straight to the realtime display of that one).
      t.end_live();
      if (run_realtime_display(t, s, marker, true) == RealtimeExit::quit) return;
      header = true;
      continue;
    }
    if (header) table_header(t, s, *priority);
    header = false;
    t.live(table_lines(s, lcd_db_index, marker));
    switch (t.read_key(std::chrono::milliseconds(1000))) {
      case term::kTimeout: break;
      case term::kEndOfInput: throw InputClosed{};
      case 'q':
      case 'Q':
        t.end_live();
        return;
      case 'e':
      case 'E':
        tracker::StationOps(s.station).rotor_control(!s.model.rotor_control);
        save_or_report(t, s);
        break;
      default: break;
    }
  }
}

}  // namespace tb::menus
