// Host mode's LOG (trakbox's own; the manual's set has no logbook): LOG CALL [GRID] [RST] logs a
// QSO with the pass being tracked (tracker::LogOps), answered "LOGGED n CALL SAT TIME" once it is
// on disk, or "ERROR LOG: <the field and what was wrong>".
#pragma once
#include <string_view>

#include "host/host_mode.h"

namespace tb::host {

Reply log_command(tracker::StationLoop& station, std::string_view args);

}  // namespace tb::host
