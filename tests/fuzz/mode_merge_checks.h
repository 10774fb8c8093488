// The properties every merge of a mode list keeps (fuzz_mode_lists.cpp, fuzz_satnogs.cpp): the
// database's shape and elements stay; without `replace` a value of the operator's or the freq/mode
// file's is never changed; the result is a state the state reader takes back (so the owner's named
// edit accepts it); each satellite's modes at most radio::kMaxModes with valid, distinct names.
#pragma once
#include <optional>
#include <string>

#include "fuzz_station.h"
#include "store/mode_import.h"
#include "util/text.h"

namespace tb::fuzz {

inline void check_merge(const store::Database& was, const store::Database& now, bool replace, const std::string& why) {
  TB_FUZZ_CHECK(now.satellites.size() == was.satellites.size() && now.selected == was.selected,
                "the database's shape changed: " + why);
  for (std::size_t i = 0; i < now.satellites.size(); ++i) {
    const store::Satellite& n = now.satellites[i];
    const store::Satellite& w = was.satellites[i];
    TB_FUZZ_CHECK(n.elements.name == w.elements.name && n.elements.epoch_day == w.elements.epoch_day,
                  "elements changed: " + why);
    const auto modes = store::modes_of(n);
    TB_FUZZ_CHECK(modes.size() <= radio::kMaxModes, n.name() + ": too many modes: " + why);
    for (std::size_t a = 0; a < modes.size(); ++a) {
      TB_FUZZ_CHECK(radio::mode_name_problem(modes[a].name).empty(), n.name() + ": bad name " + modes[a].name);
      for (std::size_t b = a + 1; b < modes.size(); ++b)
        TB_FUZZ_CHECK(!text::iequals(modes[a].name, modes[b].name), n.name() + ": name twice " + modes[a].name);
    }
    if (replace) continue;
    for (const auto& m : store::modes_of(w)) {
      const auto after = store::find_mode(n, m.name);
      TB_FUZZ_CHECK(after.has_value(), n.name() + " lost mode " + m.name + ": " + why);
      for (unsigned f = 0; f < static_cast<unsigned>(store::ModeField::count); ++f) {
        const auto field = static_cast<store::ModeField>(f);
        const std::string src = store::field_source(m, field);
        if (src == "operator" || src == "freqmode")
          TB_FUZZ_CHECK(store::field_value(*after, field) == store::field_value(m, field),
                        n.name() + " " + m.name + " " + store::to_string(field) + " (" + src + ") changed: " + why);
      }
    }
  }
  // The read-back of the merged state: a pure function of `now`, so a database equal in every
  // stored field to the one checked last (a refused or empty list leaves the shipped one as it was)
  // is not serialized and read back again; that round trip was nearly all of a replay's time.
  static std::optional<store::Database> last_read_back;
  if (last_read_back && same_stored_database(*last_read_back, now)) return;
  static const store::Model base = testing::shipped_model();
  store::Model model = base;
  model.db = now;
  const nlohmann::json saved = store::to_json(model);
  TB_FUZZ_CHECK(store::to_json(store::model_from_json(saved)) == saved, "the merged state does not read back: " + why);
  last_read_back = now;
}

}  // namespace tb::fuzz
