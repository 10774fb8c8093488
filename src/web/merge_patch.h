// The live page's changes as JSON merge patches (RFC 7386): the patch that turns one document into
// the next, for the WebSocket to carry only what changed (web/live_feed.h). Pure.
// (nlohmann::json::diff writes the other kind, RFC 6902 JSON Patch; its merge_patch applies one.)
#pragma once
#include <optional>

#include <nlohmann/json_fwd.hpp>

namespace tb::web {

// The merge patch P such that applying P to `from` (RFC 7386 section 2) gives `to`, members that
// are equal left out; for a `from` that is not an object, `to` itself. Nothing when no merge patch
// can: a member of an object in `to` whose value is null (a null in a patch removes the member).
std::optional<nlohmann::json> merge_patch_diff(const nlohmann::json& from, const nlohmann::json& to);

}  // namespace tb::web
