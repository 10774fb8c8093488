// The realtime tracking display of the manual's Figure 1, shared by menus 1, S and M:
//
//   ============ Realtime Tracking [1993/07/17] ============
//   'E' Toggle rotor control  'Y' RTC zero adjust  'Q' Return to main menu
//   '+/-/0' Doppler compensation
//   [Satellite: A-13S]
//     UTC      Azim.   Elev.    Range     Alt.   Lat.   Long.  Phase  Doppler
//   HH:MM:SS    deg     deg       Km       Km     deg    deg   <256>     Hz
//   04:06:58  28.54  -33.61  22101.6  12938.7   33.1   36.3    9.0    +2226  AOS
#pragma once
#include <string>

#include "menus/menus.h"
#include "tracker/tracker.h"

namespace tb::menus {

// One data row of the display (without the AOS indicator).
std::string format_realtime_row(const tracker::SatNow& n);
// The AOS indicator: "AOS" steady when rotor control is on, blinking (every other second)
// when off; blank when the satellite is below -2.0 deg.
std::string aos_indicator(bool in_range, bool rotor_control, orbit::UtcTime now);

// What ends a realtime display.
enum class RealtimeExit { quit, followed_changed };

// Shows the tracker's followed satellite live until Q (or, with exit_on_change, until the tracker
// follows another satellite). Handles E, Y, + / - / 0. `marker` is shown before the name
// ('*' single, '!' multiple normal, '&' multiple priority).
RealtimeExit run_realtime_display(term::Terminal& t, Services& s, char marker, bool exit_on_change = false);

// The satellite names of the tracking list, for the selection screens.
std::vector<std::string> tracking_list_names(const Services& s);

}  // namespace tb::menus
