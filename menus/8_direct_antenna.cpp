// Menu 8: Direct Antenna control. The manual lists it in the main menu as well as under 6-6; both
// lead to the same sub-menu (menus/6_6_direct_control.cpp).
#include "menus/6_configuration.h"

namespace tb::menus {

void menu_8_direct_antenna(term::Terminal& t, Services& s) { menu_6_6_direct_control(t, s); }

}  // namespace tb::menus
