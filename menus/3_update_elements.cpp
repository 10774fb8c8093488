// Menu 3: Update Satellite Elements. The UPDATE MENU of the manual; each choice is its own file
// (3_1_edit.cpp, 3_2_select.cpp, 3_3_upload.cpp, 3_4_multi_track.cpp; 3_5_refresh.cpp is trakbox's
// own, the scheduled refresh from the network). Q returns to the main menu.
#include "menus/menus.h"

namespace tb::menus {

namespace {
void show_update_menu(term::Terminal& t) {
  t.line("======= UPDATE MENU =======");
  t.line("1. EDIT: View/Edit satellite Element by hand");
  t.line("2. SELECT: Select Satellite for list.");
  t.line("3. UPDATE: Clear database & read new Element");
  t.line("4. MULTI TRACK: Configure multi tracking sat");
  t.line("5. REFRESH: Element sources and schedule");
}
}  // namespace

void menu_3_update_elements(term::Terminal& t, Services& s) {
  run_menu(t, [&] { show_update_menu(t); }, " Select: ", [&](char key) {
    switch (key) {
      case '1': menu_3_1_edit(t, s); break;
      case '2': menu_3_2_select(t, s); break;
      case '3': menu_3_3_upload(t, s); break;
      case '4': menu_3_4_multi_track(t, s); break;
      case '5': menu_3_5_refresh(t, s); break;
      case 'Q': return MenuStep::back;
      default: return MenuStep::unknown;
    }
    return MenuStep::again;
  });
}

}  // namespace tb::menus
