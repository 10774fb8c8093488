// Menu 1: Realtime Tracking. Choose from the tracking list (Enter: the one marked '*'; SUN or MOON
// for the Sun or the Moon), then the live display. Rotor control stays as it was (E toggles it); tracking goes on after Q.
#include "menus/realtime_display.h"
#include "menus/take_back.h"
#include "store/model.h"
#include "tracker/operations.h"
#include "tracker/station_loop.h"

namespace tb::menus {

namespace {
std::optional<int> choose_and_track(term::Terminal& t, Services& s) {
  std::optional<orbit::Body> body;  // SUN or MOON typed at "Select :" (issue 58)
  const auto pick =
      choose_satellite(t, "     *** Tracking object satellite ***", tracking_list_names(s), s.model.db.marked, '*', &body);
  if (!pick) return std::nullopt;
  const int db_index = body ? tracker::target_index(*body) : s.model.db.selected[static_cast<std::size_t>(*pick)];
  // Marks it '*' in the list; asks first when an outside client or a SatNOGS window holds the antenna.
  if (!with_confirmation(t, s.station, [db_index](tracker::StationOps& o) { return o.track(db_index); }).ok())
    return std::nullopt;
  save_or_report(t, s);
  return db_index;
}
}  // namespace

void menu_1_realtime_tracking(term::Terminal& t, Services& s) {
  if (!choose_and_track(t, s)) return;
  run_realtime_display(t, s, '*');
}

// S: Single Tracking Mode — the same choice, with rotor control switched on: the antenna follows.
void menu_s_single_tracking(term::Terminal& t, Services& s) {
  if (!choose_and_track(t, s)) return;
  tracker::StationOps(s.station).rotor_control(true);
  save_or_report(t, s);
  run_realtime_display(t, s, '*');
}

}  // namespace tb::menus
