// 6-R: Rotor control, trakbox's own item beside the manual's 0-9: the E key's switch as a setting.
// It is stored (as E's is), so a restarted station, the unattended service above all, moves its
// antenna or leaves it where it is as set here; --rotor-control on|off sets the same.
#include "menus/6_configuration.h"
#include "store/model.h"
#include "tracker/operations.h"
#include "tracker/station_loop.h"

namespace tb::menus {

void menu_6_r_rotor_control(term::Terminal& t, Services& s) {
  t.line(std::string("Rotor control is ") + (s.model.rotor_control ? "ON: the antenna follows the satellite tracked"
                                                                    : "OFF: the antenna stays where it is"));
  const char k = cfg::ask_choice(t, "Rotor control ON or OFF (kept over a restart) ? [Y/N] ", "YN");
  const bool on = k == 'Y';
  if (on == s.model.rotor_control) {
    t.line("Rotor control unchanged.");
    return;
  }
  tracker::StationOps(s.station).rotor_control(on);  // saved by the station (StationLoop::on_settings_changed)
  t.line(on ? "Rotor control switched ON" : "Rotor control switched OFF");
  save_or_report(t, s);
}

}  // namespace tb::menus
