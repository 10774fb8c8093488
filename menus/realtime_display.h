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
#include <vector>

#include "menus/menus.h"
#include "radio/driver.h"
#include "rotator/driver.h"
#include "tracker/tracker.h"

namespace tb::menus {

// One data row of the display (without the AOS indicator).
std::string format_realtime_row(const tracker::SatNow& n);
// The AOS indicator: "AOS" steady when rotor control is on, blinking (every other second)
// when off; blank when the satellite is below -2.0 deg.
std::string aos_indicator(bool in_range, bool rotor_control, orbit::UtcTime now);

// A serial terminal has no status line: the realtime display prints a line when the rotator's or
// the radio's link fails and when it works again, once per change (not for every retry):
//   Rotator FAULT: lost rotctld 127.0.0.1:4533: IO error; motion stopped, reconnecting
//   Rotator link restored
//   Radio FAULT: /dev/ttyUSB0 went away (the port hung up)
//   Radio working again
class LinkNotices {
 public:
  std::vector<std::string> update(const rotator::Health& rotator, const radio::RadioStatus& radio);

 private:
  bool rotator_fault_ = false;
  bool radio_fault_ = false;
};

// The pictures of a satellite's pass for the full-screen front end (the sky plot of n.pass with the
// satellite at n's time and the antenna now, the ground track of the next orbit), titled
// "NAME  pass HH:MM:SS-HH:MM:SS". The realtime display shows them live; menu 2's P, for the pass
// of the schedule.
term::Graphics pass_graphics(Services& s, const tracker::SatNow& n);
// "ISS: pass 2026/05/21 AOS 12:09:09 az 215.3, max el 45.2 at 12:12:21 az 138.0, LOS 12:15:35 az 62.1"
std::string describe_pass(const std::string& name, const orbit::Pass& p);

// What ends a realtime display.
enum class RealtimeExit { quit, followed_changed };

// Shows the tracker's followed satellite live until Q (or, with exit_on_change, until the tracker
// follows another satellite or none, or the one shown goes LOS: multiple tracking's realtime display
// lasts while its satellite is AOS). Handles E, Y, + / - / 0, U, D, L, S, R, T. `marker` is shown before the name
// ('*' single, '!' multiple normal, '&' multiple priority).
RealtimeExit run_realtime_display(term::Terminal& t, Services& s, char marker, bool exit_on_change = false);

// Multiple tracking (menu M): one row of the table of the N multi-tracked satellites,
//    No. Satellite    Azim.   Elev.    Range  In   Next AOS
//                       deg     deg       Km  rng  UTC
//     2.!AO-27       133.20   -1.52   3012.4  AOS  AOS now
// list number, marker (or a space), name (10 characters), azimuth, elevation, range, "AOS" while
// in range (elevation >= -2.0 deg), then "AOS now" ("AOS now (12:09:09, max 45.2)" when n's pass is
// the whole pass in progress, from its real AOS), the next AOS time (HH:MM:SS; the tracker looks
// a day ahead; with its date, 2026/05/22 03:04:05, when that is not the UTC day of n's time),
// "none in 24h", or "no position" when the elements cannot be propagated.
std::string format_multi_row(const tracker::SatNow& n, char marker);
// An AOS time as the menus' lists show it (UTC): "15:02:07" on the day of `now`, else with its date,
// "2026/05/22 03:04:05".
std::string aos_text(orbit::UtcTime aos, orbit::UtcTime now);
inline constexpr const char* kMultiHeader1 = " No. Satellite    Azim.   Elev.    Range  In   Next AOS";
inline constexpr const char* kMultiHeader2 = "                    deg     deg       Km  rng  UTC";

// The satellite names of the tracking list, for the selection screens.
std::vector<std::string> tracking_list_names(const Services& s);

}  // namespace tb::menus
