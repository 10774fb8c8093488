#include "menus/menus.h"
#include "tracker/station_loop.h"

namespace tb::menus {

// A change of the model is saved as the model's owner announces it (store/owner.h; the station
// saves on each notice): what is left to say here is whether that save failed.
void save_or_report(term::Terminal& t, Services& s) {
  if (const auto& failed = s.station.save_failure()) {
    t.bell();
    t.line("State not saved: " + *failed);
  }
}

}  // namespace tb::menus
