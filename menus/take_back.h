// The operator at the menus acting on the antenna or the radio while an outside client (rotctld,
// rigctld, Satrak) or a SatNOGS window holds it (tracker/control.h, issue 44): one Y/N question
// naming the holder, then the operation again, confirmed. A refusal is shown in its sentence
// (unless show_refusal is false: the caller shows it, as the realtime display does in its live block).
#pragma once
#include <functional>

#include "menus/term/terminal.h"
#include "tracker/operations.h"

namespace tb::menus {

tracker::OpResult with_confirmation(term::Terminal& t, tracker::StationLoop& station,
                                    const std::function<tracker::OpResult(tracker::StationOps&)>& op,
                                    bool show_refusal = true);

}  // namespace tb::menus
