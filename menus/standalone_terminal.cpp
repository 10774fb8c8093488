// Standalone mode with the real terminal mode behind selector position 0 + Enter: the sign-on and
// the main menu. Kept apart from standalone.cpp so that tests of standalone mode (which pass their
// own terminal mode) do not pull the main menu, and with it every menu, into the link.
#include "menus/standalone.h"

namespace tb::menus {

void standalone(term::Terminal& t, Services& s, int selector) {
  standalone(t, s, selector, [&] {
    sign_on(t, s);
    main_menu(t, s);
  });
}

}  // namespace tb::menus
