// The sign-on banner and the MAIN MENU: Select [1-8,S,M], and Q to leave (trakbox's addition).
#include "menus/menus.h"

namespace tb::menus {

void sign_on(term::Terminal& t, Services& s) {
  t.clear();
  t.line("*******************************************");
  t.line("*  TrakBox 8052 v3.10a menus              *");
  t.line("*  trakbox " + s.version + std::string(31 > s.version.size() ? 31 - s.version.size() : 0, ' ') + "*");
  t.line("*  (C) JAMSAT/JA6FTL Jan.10 1994          *");
  t.line("*******************************************");
}

namespace {
void show_main_menu(term::Terminal& t) {
  t.line("----- MAIN MENU -----");
  t.line("     1. Realtime Tracking.");
  t.line("     2. Display Schedule.");
  t.line("     3. Update Satellite Elements.");
  t.line("     4. Update Station Elements.");
  t.line("     5. Update Realtime Clock.");
  t.line("     6. Configuration.");
  t.line("     7. Host mode.");
  t.line("     8. Direct Antenna control.");
  t.line("     Q. Leave trakbox.");  // trakbox's line (issue 30; docs/menus/README.md)
}
}  // namespace

bool leave_trakbox(term::Terminal& t) { return ask_yes_no(t, "     leave trakbox? [Y/N]"); }

bool detach_attached(term::Terminal& t) { return ask_yes_no(t, "     detach from trakbox? [Y/N]"); }

bool detach_serial_line(term::Terminal& t) {
  if (!ask_yes_no(t, "     detach from trakbox? [Y/N]")) return false;
  t.line("     Detached: trakbox keeps tracking. Any key brings the menu back.");
  t.flush();
  if (!t.read_choice({}, true)) throw InputClosed{};
  return false;
}

void main_menu(term::Terminal& t, Services& s) {
  run_menu(t, [&] { show_main_menu(t); }, "     Select [1-8,S,M]:", [&](char key) {
    switch (key) {
      case '1': menu_1_realtime_tracking(t, s); break;
      case '2': menu_2_display_schedule(t, s); break;
      case '3': menu_3_update_elements(t, s); break;
      case '4': menu_4_station_elements(t, s); break;
      case '5': menu_5_realtime_clock(t, s); break;
      case '6': menu_6_configuration(t, s); break;
      case '7': menu_7_host_mode(t, s); break;
      case '8': menu_8_direct_antenna(t, s); break;
      case 'S': menu_s_single_tracking(t, s); break;
      case 'M': menu_m_multiple_tracking(t, s); break;
      case 'Q': return (s.leave ? s.leave(t) : leave_trakbox(t)) ? MenuStep::back : MenuStep::again;
      default: return MenuStep::unknown;
    }
    return MenuStep::again;
  });
}

}  // namespace tb::menus
