#include "menus/menus.h"

namespace tb::menus {

void save_or_report(term::Terminal& t, Services& s) {
  if (auto err = s.save()) {
    t.bell();
    t.line("State not saved: " + *err);
  }
}

}  // namespace tb::menus
