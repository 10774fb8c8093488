// The logbook's JSON forms, shared by the web API, the station socket (`trakbox log ...`) and the
// status document: a QSO as an object, a request to log one, an edit, the log's summary.
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "tracker/log_ops.h"

namespace tb::tracker {

nlohmann::json qso_json(const logbook::Qso& q);
// {"call": ..., "grid", "rst_sent", "rst_rcvd", "note", "sat", "mode", "time_on" (ISO 8601 UTC),
// "power_w"} into r; the refusal names the key. Keys not listed are refused.
std::optional<std::string> log_request_from_json(const nlohmann::json& j, LogRequest& r);
// The fields an edit may change (call, grid, rst_sent, rst_rcvd, note, mode, time_on, power_w) set
// on q; "id" is allowed and ignored here. The refusal names the key.
std::optional<std::string> apply_edit_json(const nlohmann::json& j, logbook::Qso& q);
// For status: count, last QSO (call, satellite, time), the upload queue, a problem when the logbook
// could not be opened.
nlohmann::json log_summary(const LogOps& ops);

}  // namespace tb::tracker
