// Who holds the antenna and the radio, as `trakbox status`, the API and the page show it (issue 44):
// the document's "control", "standby" and "reservations", the truth of antenna.target and of the
// radio's Doppler.
#pragma once
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace tb::tracker {
class StationLoop;
}

namespace tb::app {

// Adds "control": {"antenna": {kind, label, since, until}, "radio": {...}}, "standby" and
// "reservations" to the status document (antenna.action and antenna.target, whoever holds it, are
// StationLoop::aim's); each radio's "doppler" says whether trakbox tunes it now and, if not, why.
void add_control_status(const tracker::StationLoop& station, nlohmann::json& status);

}  // namespace tb::app
