// 6-5: Monitor ADC value & Antenna position: the live monitor line until Q (or Enter).
#include "menus/6_configuration.h"

namespace tb::menus {

void menu_6_5_monitor(term::Terminal& t, Services& s) {
  t.line("=== ADC value & Antenna position ===");
  cfg::LiveMonitor m(t, s);
  for (;;) {
    const int k = m.key();
    if (k == 'q' || k == 'Q' || k == term::kEnter || k == '\n' || k == term::kEscape) break;
  }
}

}  // namespace tb::menus
