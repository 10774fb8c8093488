#include "web/control_api.h"

#include <nlohmann/json.hpp>

#include "util/safe_text.h"

namespace tb::web {

std::optional<tracker::OpResult> control_post(tracker::StationOps& ops, const std::string& path,
                                              const nlohmann::json& b) {
  if (path == "/api/v1/standby") {
    const auto it = b.find("on");
    if (it == b.end() || !it->is_boolean()) return std::nullopt;
    return ops.standby(it->get<bool>());
  }
  if (path == "/api/v1/reserve") {
    const auto start = b.find("start"), end = b.find("end");
    if (start == b.end() || end == b.end() || !start->is_string() || !end->is_string()) return std::nullopt;
    const auto t0 = orbit::parse_iso8601(start->get<std::string>());
    const auto t1 = orbit::parse_iso8601(end->get<std::string>());
    if (!t0 || !t1) return tracker::OpResult::refuse("reserve: \"start\" and \"end\" must be ISO 8601 UTC times");
    const auto note = b.find("note");
    return ops.reserve(*t0, *t1, note != b.end() && note->is_string() ? text::safe_text(note->get<std::string>()) : "");
  }
  const auto it = b.find("take_back");
  if (it == b.end() || !it->is_boolean() || !it->get<bool>()) return std::nullopt;
  return ops.take_back();
}

Response refused(const tracker::OpResult& r) {
  nlohmann::json j{{"error", r.refusal.value_or("refused")}};
  if (r.confirm) {
    j["confirm_needed"] = true;
    j["holder"] = {{"kind", tracker::kind_name(r.confirm->kind)}, {"label", r.confirm->label}};
  }
  Response res;
  res.status = 409;
  res.body = j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return res;
}

}  // namespace tb::web
