#include "web/live_feed.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "util/json_limits.h"
#include "web/merge_patch.h"

namespace tb::web {

namespace {
using json = nlohmann::json;
std::string text(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }
}  // namespace

namespace {

// An array made an object of its entries by position ("0", "1", ...); anything else left as it is.
void by_position(json& list) {
  if (!list.is_array()) return;
  json out = json::object();
  for (std::size_t i = 0; i < list.size(); ++i) out[std::to_string(i)] = std::move(list[i]);
  list = std::move(out);
}

double hundredths(double v) { return std::round(v * 100.0) / 100.0; }

}  // namespace

void shape_for_live(json& status) {
  if (!status.is_object()) return;
  const auto list = status.find("tracking_list");
  if (list != status.end() && list->is_array()) {
    for (json& entry : *list) {
      if (!entry.is_object()) continue;
      entry.erase("now");
      const auto age = entry.find("element_age_days");
      if (age != entry.end() && age->is_number()) *age = hundredths(age->get<double>());
      const auto next = entry.find("next_pass");
      if (next != entry.end() && next->is_object()) {
        const auto el = next->find("max_el_deg");
        if (el != next->end() && el->is_number()) *el = hundredths(el->get<double>());
      }
    }
    by_position(*list);
  }
  // The radios (a radio's tuning moves every second, the rest of it seldom) and the satellites
  // followed: by position too, so a patch carries the members that changed, not the whole list.
  if (const auto radios = status.find("radios"); radios != status.end()) by_position(*radios);
  if (const auto tracking = status.find("tracking"); tracking != status.end() && tracking->is_object())
    if (const auto sats = tracking->find("satellites"); sats != tracking->end()) by_position(*sats);
}

LiveFeed::LiveFeed() = default;
LiveFeed::~LiveFeed() = default;

std::optional<std::string> LiveFeed::next(json doc) {
  std::optional<json> patch;
  if (last_) {
    patch = merge_patch_diff(*last_, doc);
    if (patch && patch->empty()) return std::nullopt;
  }
  ++seq_;
  last_ = std::make_unique<json>(std::move(doc));
  full_.reset();
  if (!patch) return full();
  return text(json{{"type", "patch"}, {"seq", seq_}, {"patch", std::move(*patch)}});
}

std::optional<std::string> LiveFeed::full() {
  if (!last_) return std::nullopt;
  if (!full_) {
    json whole = *last_;
    whole["seq"] = seq_;
    full_ = text(whole);
  }
  return full_;
}

void LiveFeed::forget() {
  last_.reset();
  full_.reset();
}

bool LiveFeed::asks_full(std::string_view message) {
  if (message.size() > 256) return false;
  std::string why;
  const json j = json_limits::parse_bounded<json>(message, why, 2);
  if (!j.is_object()) return false;
  const auto type = j.find("type");
  return type != j.end() && type->is_string() && type->get_ref<const std::string&>() == "full";
}

}  // namespace tb::web
