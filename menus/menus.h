// The menus of the TrakBox manual, one function each, one file each (named by number and words).
// Every menu runs against a Terminal and the Services; it returns when the operator presses Q (or
// finishes), and throws InputClosed when the input ends.
#pragma once
#include <functional>
#include <string>

#include "menus/common.h"
#include "menus/term/terminal.h"

#include "store/owner.h"

namespace tb::station { class RealTimeClock; }
namespace tb::tracker { class Tracker; class StationLoop; }

namespace tb::menus {

struct Services {
  // What is stored, read only: a menu changes it through commit() (the model's one door).
  const store::Model& model;
  station::RealTimeClock& clock;
  tracker::Tracker& tracker;
  tracker::StationLoop& station;  // the rotator, the radio, rotor control
  // Persists the model now; on failure returns the reason (the menus show it).
  std::function<std::optional<std::string>()> save;
  // Program version for the banner.
  std::string version;
  // The main menu's Q (issue 30): asks and returns true when the menus should end. Empty: the
  // local terminal's way, leave_trakbox(). A serial line (and an attach client) sets its own,
  // which detaches the operator and leaves trakbox running.
  std::function<bool(term::Terminal&)> leave;
};

// The stored model changed through its one door (store/owner.h): `change` applied to a copy,
// checked whole as the state reader will check it, kept, announced (the station reconfigures what
// depends on it) and saved. A refusal is said on the terminal with the reader's sentence and
// nothing changes: false.
bool commit(term::Terminal& t, Services& s, store::Areas areas, std::string what,
            const std::function<void(store::Model&)>& change);

// Asks "leave trakbox? [Y/N]"; true for Y (trakbox then saves and exits).
bool leave_trakbox(term::Terminal& t);
// An attached client's Q (trakbox attach): "detach from trakbox? [Y/N]"; Y ends the menus for this
// operator (the service detaches the keyboard and keeps tracking; the menus start again for the next).
bool detach_attached(term::Terminal& t);
// A serial line's Q: "detach from trakbox? [Y/N]"; Y says trakbox keeps running and waits for a
// key to bring the menu back. Never ends the menus (the line is the box's own terminal).
bool detach_serial_line(term::Terminal& t);

// The sign-on banner and the main menu loop (returns when input closes).
void main_menu(term::Terminal& t, Services& s);
void sign_on(term::Terminal& t, Services& s);

void menu_1_realtime_tracking(term::Terminal& t, Services& s);
void menu_2_display_schedule(term::Terminal& t, Services& s);
void menu_3_update_elements(term::Terminal& t, Services& s);
void menu_3_1_edit(term::Terminal& t, Services& s);
void menu_3_2_select(term::Terminal& t, Services& s);
void menu_3_3_upload(term::Terminal& t, Services& s);
void menu_3_4_multi_track(term::Terminal& t, Services& s);
void menu_3_5_refresh(term::Terminal& t, Services& s);
void menu_4_station_elements(term::Terminal& t, Services& s);
void menu_5_realtime_clock(term::Terminal& t, Services& s);
void menu_6_configuration(term::Terminal& t, Services& s);
void menu_7_host_mode(term::Terminal& t, Services& s);
void menu_8_direct_antenna(term::Terminal& t, Services& s);
void menu_s_single_tracking(term::Terminal& t, Services& s);
void menu_m_multiple_tracking(term::Terminal& t, Services& s);

// Saves and reports a failure on the terminal (a failed save never loses the edit in memory).
// Says so when the last save of the model failed (each change is saved as it is made).
void save_or_report(term::Terminal& t, Services& s);

}  // namespace tb::menus
