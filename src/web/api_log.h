// The logbook's endpoints (docs/logbook.md, docs/web-api.md), behind web::Api's access rules:
//   GET  /api/v1/log[?since=DATE][&limit=N][&after=CURSOR]
//                                    one page of QSOs (since a UTC date or time), oldest first, at
//                                    most `limit` (default 500, at most 1000), with "next": the
//                                    cursor of the page after it (null at the end), and a summary
//   GET  /api/v1/log.adi[?since=DATE] the ADIF export, streamed page by page (the warnings' count in
//                                    the trailer X-Trakbox-Warnings)
//   POST /api/v1/log                  log one: {"call", "grid", "rst_sent", ...}; the rest from the pass
//   POST /api/v1/log/edit             {"id", fields to change}: the previous version is kept
//   POST /api/v1/log/delete           {"id"}: marked deleted
// A QSO is acknowledged (200 with the stored record) only after its transaction committed. Every
// change and every refusal is logged with who asked, the QSO and why (issue 56, item 13).
#pragma once
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "web/api.h"

namespace tb::web {

bool is_log_path(const std::string& path);
Response log_get(tracker::StationLoop& station, const std::string& path, const std::string& target,
                 std::int64_t wall_now_unix, const std::string& version);
// `who` names the asker in the log ("web 127.0.0.1").
Response log_post(tracker::StationLoop& station, const std::string& path, const nlohmann::json& body,
                  const std::string& who);

}  // namespace tb::web
