// The web API's part in sharing the station (issue 44, docs/sharing.md): POST /api/v1/standby
// {"on":true|false}, POST /api/v1/control {"take_back":true[,"confirm":true]}, POST /api/v1/reserve
// {"start":ISO,"end":ISO[,"note":TEXT]}, and the refusal of
// an operation as a 409 that names the holder when the operator must confirm first.
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "tracker/operations.h"
#include "web/api.h"

namespace tb::web {

// The operation a standby or control body asks for, done; nothing when the body is not one of them.
std::optional<tracker::OpResult> control_post(tracker::StationOps& ops, const std::string& path,
                                              const nlohmann::json& body);
// 409 {"error": why} and, when a confirmation would do, "confirm_needed": true and "holder": {kind,
// label} (send the same request again with "confirm": true).
Response refused(const tracker::OpResult& r);

}  // namespace tb::web
