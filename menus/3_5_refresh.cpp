// Menu 3-5: Refresh (trakbox's own; the 1994 TrakBox had no network). The element sources the
// database is refreshed from on a schedule, the interval, the last refresh, and "refresh now".
// Sources and interval are stored in the state (store::RefreshSettings); the downloads run in the
// background (tracker::ElementsRefresh), so nothing here waits for the network.
#include <cstdio>

#include "menus/menus.h"
#include "store/model.h"
#include "store/refresh.h"
#include "tracker/elements_refresh.h"
#include "tracker/station_loop.h"

namespace tb::menus {

namespace {

void show_refresh(term::Terminal& t, const store::RefreshSettings& r, const tracker::ElementsRefresh* live) {
  t.line("======= ELEMENT REFRESH =======");
  if (r.sources.empty()) t.line(" No element source: the database is refreshed only by hand (3-3).");
  for (std::size_t i = 0; i < r.sources.size(); ++i) t.line(" " + std::to_string(i + 1) + ". " + r.sources[i].url);
  char every[64];
  std::snprintf(every, sizeof every, " Every %.1f hours (at least 2).", r.interval_hours);
  t.line(every);
  if (live) {
    if (live->running()) t.line(" Last refresh: running now");
    else if (!live->last_result().empty())
      t.line(std::string(" Last refresh: ") + (live->last_failed() ? "FAILED " : "ok ") + live->last_result());
    else t.line(" Last refresh: none since start");
  }
  t.line("A. Add a source (URL or file)   D. Delete a source   I. Interval   R. Refresh now   Q. Quit");
}

void add_source(term::Terminal& t, Services& s) {
  t.write("URL or file: ");
  t.flush();
  const std::string url = trim(read_line(t, store::kRefreshMaxUrl + 10));
  if (url.empty()) return;
  if (const auto why = store::add_refresh_source(s.model.refresh, url)) {
    t.line("  Not added: " + *why);
    return;
  }
  t.line("  Added. Sets of the database's satellites (by catalog number) will be taken from it.");
  save_or_report(t, s);
}

void delete_source(term::Terminal& t, Services& s) {
  auto& sources = s.model.refresh.sources;
  if (sources.empty()) return;
  t.write("Delete which (1-" + std::to_string(sources.size()) + ")? ");
  t.flush();
  const std::string a = trim(read_line(t));
  const auto n = parse_integer(a);
  if (!n || *n < 1 || *n > static_cast<long>(sources.size())) {
    if (!a.empty()) t.line("  '" + a + "': enter a number from 1 to " + std::to_string(sources.size()));
    return;
  }
  sources.erase(sources.begin() + (*n - 1));
  save_or_report(t, s);
}

void set_interval(term::Terminal& t, Services& s) {
  char shown[32];
  std::snprintf(shown, sizeof shown, "%.1f", s.model.refresh.interval_hours);
  s.model.refresh.interval_hours = edit_number(t, "Hours between refreshes (2-720)", s.model.refresh.interval_hours,
                                               shown, store::kRefreshMinHours, store::kRefreshMaxHours);
  save_or_report(t, s);
}

void refresh_now(term::Terminal& t, Services& s) {
  tracker::ElementsRefresh* live = s.station.refresh();
  if (!live) {
    t.line("  No refresh here.");
    return;
  }
  if (const auto why = live->refresh_now(tracker::ElementsRefresh::wall_now())) t.line("  Not started: " + *why);
  else t.line("  Refresh started: the result shows here, in the status line and in the log.");
}

}  // namespace

void menu_3_5_refresh(term::Terminal& t, Services& s) {
  run_menu(t, [&] { show_refresh(t, s.model.refresh, s.station.refresh()); }, " Select: ", [&](char key) {
    switch (key) {
      case 'A': add_source(t, s); break;
      case 'D': delete_source(t, s); break;
      case 'I': set_interval(t, s); break;
      case 'R': refresh_now(t, s); break;
      case 'Q': return MenuStep::back;
      default: return MenuStep::unknown;
    }
    return MenuStep::again;
  });
}

}  // namespace tb::menus
