#pragma once
// The realtime display's L key: a QSO of the pass being tracked into the logbook (docs/logbook.md).
#include <string>

#include "menus/menus.h"
#include "menus/term/terminal.h"

namespace tb::menus {

// What it said ("Logged #3 W1AW RS-44 USB 21:44:20 UTC", "Not logged: ..."), for the full screen.
std::string realtime_log_qso(term::Terminal& t, Services& s);

}  // namespace tb::menus
