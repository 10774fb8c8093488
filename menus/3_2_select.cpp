// Menu 3-2: Select. After "Are you sure ?" a new tracking list is built: the whole database is
// listed with numbers, each number entered appends that satellite ("Satellite (AO-10) selected as
// #1") and the list is shown again with '*' on the one just selected, up to 15. Q, or Enter on an
// empty line once something is selected, ends. The list is built on a copy and replaces the old one only when at least one
// satellite was selected (Q at once keeps the old list).
#include <algorithm>
#include <cctype>

#include "menus/menus.h"
#include "store/model.h"
#include "tracker/station_loop.h"

namespace tb::menus {

namespace {
std::vector<std::string> database_names(const store::Database& db) {
  std::vector<std::string> names;
  for (const auto& sat : db.satellites) names.push_back(sat.name());
  return names;
}
}  // namespace

void menu_3_2_select(term::Terminal& t, Services& s) {
  if (!ask_yes_no(t, "Are you sure ? [Y/N] ? ")) return;
  const store::Database& old = s.model.db;
  if (old.satellites.empty()) {
    t.line("The database is empty: load element data with menu 3-3 first.");
    return;
  }
  store::Database db = old;  // committed at the end
  db.selected.clear();
  const auto names = database_names(db);
  int last = -1;  // database index selected last: it carries the '*'
  for (const auto& r : format_satellite_list(names, -1)) t.line(r);
  for (;;) {
    t.write("     Select :");
    t.flush();
    std::string a = read_line(t);
    while (!a.empty() && std::isspace(static_cast<unsigned char>(a.back()))) a.pop_back();
    while (!a.empty() && std::isspace(static_cast<unsigned char>(a.front()))) a.erase(0, 1);
    // An empty line before anything was chosen is the Enter typed after "Y": ask again.
    if (a.empty() && db.selected.empty()) continue;
    if (a.empty() || a == "Q" || a == "q") break;
    const auto n = parse_integer(a);
    if (!n || *n < 1 || *n > static_cast<long>(names.size())) {
      t.line("  Enter 1 to " + std::to_string(names.size()) + ", or Q (or Enter) to finish");
      continue;
    }
    const int i = static_cast<int>(*n - 1);
    const std::string& name = names[static_cast<std::size_t>(i)];
    if (const int already = db.list_number(i)) {
      t.line("Satellite (" + name + ") is already selected as #" + std::to_string(already));
      continue;
    }
    const int number = db.select(i);
    t.line("Satellite (" + name + ") selected as #" + std::to_string(number));
    last = i;
    if (static_cast<int>(db.selected.size()) >= store::kMaxSelected) {
      t.line("The tracking list is full (" + std::to_string(store::kMaxSelected) + " satellites).");
      break;
    }
    for (const auto& r : format_satellite_list(names, last)) t.line(r);
  }

  if (db.selected.empty()) {
    t.line("No satellite selected: the tracking list is unchanged.");
    return;
  }
  // The '*' of menus 1, 2 and M is where 3-2 showed it: on the satellite selected last (the
  // manual's "the asterisk (*) mark indicates the satellite last selected").
  db.marked = db.list_number(last) - 1;
  db.normalise();
  // A satellite followed alone that left the list: stop rather than follow something unlisted.
  const auto followed = s.tracker.last_decision().followed;
  const bool stop = s.tracker.mode() == tracker::Mode::single && followed && !tracker::body_target(*followed) &&
                    !db.list_number(*followed);
  if (!commit(t, s, store::bit(store::Area::tracking_list), "menu 3-2", [&](store::Model& m) { m.db = db; })) return;
  t.line("Tracking list: " + std::to_string(s.model.db.selected.size()) + " satellite(s) selected.");
  if (stop) {
    s.tracker.stop();
    t.line("Tracking stopped: the satellite followed is no longer listed.");
  }
  s.station.reconfigure();
  save_or_report(t, s);
}

}  // namespace tb::menus
