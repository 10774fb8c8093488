// The logbook's endpoints (docs/logbook.md), behind web::Api's access rules:
//   GET  /api/v1/log[?since=DATE]     the QSOs (since a UTC date or time), newest last, and a summary
//   GET  /api/v1/log.adi[?since=DATE] the ADIF export (with the warnings in X-Trakbox-Warnings)
//   POST /api/v1/log                  log one: {"call", "grid", "rst_sent", ...}; the rest from the pass
//   POST /api/v1/log/edit             {"id", fields to change}: the previous version is kept
//   POST /api/v1/log/delete           {"id"}: marked deleted
// A QSO is acknowledged (200 with the stored record) only after its transaction committed.
#pragma once
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "web/api.h"

namespace tb::web {

bool is_log_path(const std::string& path);
Response log_get(tracker::StationLoop& station, const std::string& path, const std::string& target,
                 std::int64_t wall_now_unix, const std::string& version);
Response log_post(tracker::StationLoop& station, const std::string& path, const nlohmann::json& body);

}  // namespace tb::web
