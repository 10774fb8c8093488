// Menu 3-4: Multi Track. How many of the tracking list (the first N, 2 to 5) menu M follows.
#include <cctype>

#include "menus/menus.h"
#include "store/model.h"

namespace tb::menus {

void menu_3_4_multi_track(term::Terminal& t, Services& s) {
  const auto& db = s.model.db;
  for (;;) {
    t.write("How many satellites configure for multi tracking mode ? (2-5) ");
    t.flush();
    std::string a = read_line(t);
    while (!a.empty() && std::isspace(static_cast<unsigned char>(a.back()))) a.pop_back();
    while (!a.empty() && std::isspace(static_cast<unsigned char>(a.front()))) a.erase(0, 1);
    if (a.empty()) {
      t.line("Multi tracking: " + std::to_string(db.multi_count) + " satellites (unchanged)");
      return;
    }
    const auto n = parse_integer(a);
    if (!n || *n < store::kMinMultiTrack || *n > store::kMaxMultiTrack) {
      t.line("  '" + a + "': enter a number from 2 to 5");
      continue;
    }
    if (!commit(t, s, store::bit(store::Area::tracking_list), "menu 3-4",
                [&](store::Model& m) { m.db.multi_count = static_cast<int>(*n); }))
      return;
    t.line("The first " + std::to_string(db.multi_count) + " satellites of the tracking list will be multi-tracked.");
    if (static_cast<int>(db.selected.size()) < db.multi_count)
      t.line("Note: the tracking list holds " + std::to_string(db.selected.size()) +
             " satellite(s); select more with menu 3-2.");
    return;
  }
}

}  // namespace tb::menus
