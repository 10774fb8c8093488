#include "web/merge_patch.h"

#include <nlohmann/json.hpp>

namespace tb::web {

namespace {
using json = nlohmann::json;

// false when `to` holds a null member somewhere down its objects (arrays are replaced whole, so the
// nulls inside them travel as they are).
bool build(const json& from, const json& to, json& out) {
  if (!to.is_object()) {
    out = to;
    return true;
  }
  static const json kEmpty = json::object();
  const json& base = from.is_object() ? from : kEmpty;  // a patch object makes a non-object target {}
  out = json::object();
  for (auto it = base.begin(); it != base.end(); ++it)
    if (!to.contains(it.key())) out[it.key()] = nullptr;
  for (auto it = to.begin(); it != to.end(); ++it) {
    const json& value = it.value();
    const auto was = base.find(it.key());
    if (was != base.end() && *was == value) continue;
    if (value.is_null()) return false;
    json sub;
    if (!build(was != base.end() ? *was : json(), value, sub)) return false;
    out[it.key()] = std::move(sub);
  }
  return true;
}
}  // namespace

std::optional<json> merge_patch_diff(const json& from, const json& to) {
  json out;
  if (!build(from, to, out)) return std::nullopt;
  return out;
}

}  // namespace tb::web
