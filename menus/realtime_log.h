#pragma once
// The realtime display's L key: a QSO of the pass being tracked into the logbook (docs/logbook.md).
#include "menus/menus.h"
#include "menus/term/terminal.h"

namespace tb::menus {

void realtime_log_qso(term::Terminal& t, Services& s);

}  // namespace tb::menus
