#include "web/control_api.h"

#include <nlohmann/json.hpp>

namespace tb::web {

std::optional<tracker::OpResult> control_post(tracker::StationOps& ops, const std::string& path,
                                              const nlohmann::json& b) {
  if (path == "/api/v1/standby") {
    const auto it = b.find("on");
    if (it == b.end() || !it->is_boolean()) return std::nullopt;
    return ops.standby(it->get<bool>());
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
