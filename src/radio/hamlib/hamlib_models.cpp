#include "radio/hamlib/hamlib_models.h"

#include <hamlib/rig.h>

#include <algorithm>
#include <cctype>
#include <mutex>
#include <vector>

namespace tb::radio {

namespace {

struct Known {
  int model;
  std::string mfg, name;     // as Hamlib spells them
  std::string key, full_key; // model_key(name), model_key(mfg + name)
};

const std::vector<Known>& hamlib_rigs() {
  static const std::vector<Known> rigs = [] {
    std::vector<Known> out;
    rig_set_debug(RIG_DEBUG_NONE);
    rig_load_all_backends();
    rig_list_foreach(
        [](const rig_caps* caps, void* data) -> int {
          auto& v = *static_cast<std::vector<Known>*>(data);
          const std::string mfg = caps->mfg_name ? caps->mfg_name : "";
          const std::string name = caps->model_name ? caps->model_name : "";
          v.push_back({static_cast<int>(caps->rig_model), mfg, name, model_key(name), model_key(mfg + name)});
          return 1;   // go on
        },
        &out);
    std::sort(out.begin(), out.end(), [](const Known& a, const Known& b) { return a.model < b.model; });
    return out;
  }();
  return rigs;
}

std::mutex& lookup_mutex() {
  static std::mutex m;
  return m;
}

// Levenshtein distance, for "did you mean".
std::size_t distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string model_key(std::string_view name) {
  std::string k;
  for (char c : name)
    if (std::isalnum(static_cast<unsigned char>(c))) k.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  return k;
}

HamlibModelLookup hamlib_rig_by_name(std::string_view name) {
  const std::string key = model_key(name);
  if (key.empty()) return {std::nullopt, "\"" + std::string(name) + "\" is not a Hamlib model number or name (see rigctl -l)"};
  std::lock_guard lock(lookup_mutex());
  const auto& rigs = hamlib_rigs();
  std::vector<const Known*> hits;
  for (const Known& k : rigs)
    if (k.key == key || k.full_key == key) hits.push_back(&k);
  if (hits.size() == 1) return {hits.front()->model, {}};
  auto label = [](const Known& k) { return k.mfg + " " + k.name + " (" + std::to_string(k.model) + ")"; };
  if (hits.size() > 1) {
    std::string e = "Hamlib model name \"" + std::string(name) + "\" names " + std::to_string(hits.size()) +
                    " models: ";
    for (std::size_t i = 0; i < hits.size(); ++i) e += (i ? ", " : "") + label(*hits[i]);
    return {std::nullopt, e + "; give the number"};
  }
  // Near matches: names that contain the key, or within an edit of it per four characters.
  const std::size_t edits = std::max<std::size_t>(1, key.size() / 4);
  std::vector<std::pair<std::size_t, const Known*>> near;
  for (const Known& k : rigs) {
    const std::size_t d = std::min(distance(key, k.key), distance(key, k.full_key));
    if (d <= edits || (key.size() >= 3 && k.key.find(key) != std::string::npos)) near.push_back({d, &k});
  }
  std::stable_sort(near.begin(), near.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::string e = "Hamlib has no rig model named \"" + std::string(name) + "\"";
  if (!near.empty()) {
    e += "; near: ";
    for (std::size_t i = 0; i < near.size() && i < 8; ++i) e += (i ? ", " : "") + label(*near[i].second);
  }
  return {std::nullopt, e + " (see rigctl -l)"};
}

}  // namespace tb::radio
