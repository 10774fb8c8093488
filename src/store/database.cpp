#include "store/database.h"

#include <algorithm>

#include "store/mode_import.h"
#include "util/text.h"

namespace tb::store {

std::vector<radio::SatelliteMode> modes_of(const Satellite& s) {
  std::vector<radio::SatelliteMode> out = s.modes;
  for (auto& m : out)
    if (m.name == s.mode) {
      m.radio = s.radio;
      return out;
    }
  // No chosen mode among them: the record is one of its own (a satellite from before modes).
  if (s.radio == radio::SatelliteRadio{} && out.empty()) return out;
  radio::SatelliteMode own{s.mode.empty() ? radio::default_mode_name(s.radio) : s.mode, s.radio, 0, {}};
  out.insert(out.begin(), std::move(own));
  return out;
}

std::string chosen_mode(const Satellite& s) {
  const auto all = modes_of(s);
  for (const auto& m : all)
    if (m.name == s.mode) return m.name;
  return all.empty() ? std::string() : all.front().name;
}

std::optional<radio::SatelliteMode> find_mode(const Satellite& s, std::string_view name) {
  for (auto& m : modes_of(s))
    if (text::iequals(m.name, name)) return m;
  return std::nullopt;
}

void settle_modes(Satellite& s) {
  s.mode = chosen_mode(s);
  s.modes = modes_of(s);
}

bool choose_mode(Satellite& s, std::string_view name) {
  const auto m = find_mode(s, name);
  if (!m) return false;
  settle_modes(s);  // the working record kept in the mode it belongs to
  s.mode = m->name;
  s.radio = m->radio;
  return true;
}

std::optional<int> Database::find(std::string_view name) const {
  for (std::size_t i = 0; i < satellites.size(); ++i)
    if (satellites[i].name() == name) return static_cast<int>(i);
  return std::nullopt;
}

const Satellite* Database::listed(int number) const {
  if (number < 1 || number > static_cast<int>(selected.size())) return nullptr;
  const int i = selected[static_cast<std::size_t>(number - 1)];
  if (i < 0 || i >= static_cast<int>(satellites.size())) return nullptr;
  return &satellites[static_cast<std::size_t>(i)];
}

int Database::list_number(int db_index) const {
  for (std::size_t k = 0; k < selected.size(); ++k)
    if (selected[k] == db_index) return static_cast<int>(k) + 1;
  return 0;
}

int Database::select(int db_index) {
  if (db_index < 0 || db_index >= static_cast<int>(satellites.size())) return 0;
  if (const int n = list_number(db_index)) return n;
  if (static_cast<int>(selected.size()) >= kMaxSelected) return 0;
  selected.push_back(db_index);
  return static_cast<int>(selected.size());
}

std::optional<int> Database::marked_index() const {
  if (marked < 0 || marked >= static_cast<int>(selected.size())) return std::nullopt;
  return selected[static_cast<std::size_t>(marked)];
}

void Database::normalise() {
  if (static_cast<int>(satellites.size()) > kMaxDatabase) satellites.resize(kMaxDatabase);
  std::vector<int> clean;
  for (int i : selected) {
    if (i < 0 || i >= static_cast<int>(satellites.size())) continue;
    if (std::find(clean.begin(), clean.end(), i) != clean.end()) continue;
    if (static_cast<int>(clean.size()) >= kMaxSelected) break;
    clean.push_back(i);
  }
  selected = std::move(clean);
  if (marked >= static_cast<int>(selected.size())) marked = selected.empty() ? -1 : 0;
  if (marked < 0 && !selected.empty()) marked = 0;
  multi_count = std::clamp(multi_count, kMinMultiTrack, kMaxMultiTrack);
}

ElementsUpload build_elements_upload(const Database& old, const orbit::ParseResult& parsed) {
  ElementsUpload up;
  for (const auto& p : parsed.problems) {
    if (!p.warning) up.skipped.push_back(p.message());
  }
  for (const auto& e : parsed.sets) {
    Satellite s;
    s.elements = e;
    if (s.elements.name.empty()) s.elements.name = s.elements.label();
    if (up.database.find(s.name())) {
      up.skipped.push_back(s.name() + ": the same name again (names must differ), not taken");
      continue;
    }
    if (static_cast<int>(up.database.satellites.size()) >= kMaxDatabase) {
      up.skipped.push_back(s.name() + ": the database holds " + std::to_string(kMaxDatabase) +
                           " satellites, not taken");
      continue;
    }
    // A satellite that was already known keeps its frequencies and modes.
    if (const auto i = old.find(s.name())) {
      const Satellite& was = old.satellites[static_cast<std::size_t>(*i)];
      s.radio = was.radio;
      s.modes = was.modes;
      s.mode = was.mode;
    }
    up.accepted.push_back(s.name());
    up.database.satellites.push_back(std::move(s));
  }
  up.database.multi_count = old.multi_count;
  // Until a freq/mode file says otherwise, the list is the first 15 (3-3 then builds it anew).
  for (int i = 0; i < static_cast<int>(up.database.satellites.size()) && i < kMaxSelected; ++i)
    up.database.selected.push_back(i);
  up.database.marked = up.database.selected.empty() ? -1 : 0;
  return up;
}

namespace {
// A record of the freq/mode file as a mode of its satellite; false (and said) when the satellite
// has that mode already in the file, or too many.
bool take_mode(std::vector<radio::SatelliteMode>& modes, const radio::FreqModeRecord& r, FreqModeUpload& out) {
  radio::SatelliteMode m{r.mode.empty() ? radio::default_mode_name(r.radio) : r.mode, r.radio, r.arm_tone_tenths_hz, {}};
  mark_sources(m, "freqmode");  // each value the file's, until the operator or a list changes it
  const auto same = [&](const radio::SatelliteMode& x) { return text::iequals(x.name, m.name); };
  if (std::any_of(modes.begin(), modes.end(), same)) {
    out.skipped.push_back("line " + std::to_string(r.line) + ": (" + r.name + ") has mode " + m.name +
                          " on an earlier line, not taken");
    return false;
  }
  if (modes.size() >= radio::kMaxModes) {
    out.skipped.push_back("line " + std::to_string(r.line) + ": (" + r.name + ") has " +
                          std::to_string(radio::kMaxModes) + " modes already, not taken");
    return false;
  }
  modes.push_back(std::move(m));
  return true;
}

// The file's modes replace the satellite's; the mode chosen before stays chosen when the file
// still has it, else the file's first is.
void set_modes(Satellite& s, std::vector<radio::SatelliteMode> modes) {
  const std::string was = chosen_mode(s);
  s.modes = std::move(modes);
  s.mode = s.modes.front().name;
  s.radio = s.modes.front().radio;
  for (const auto& m : s.modes)
    if (text::iequals(m.name, was)) {
      s.mode = m.name;
      s.radio = m.radio;
    }
}
}  // namespace

FreqModeUpload apply_freqmode(Database& db, const std::vector<radio::FreqModeRecord>& records) {
  FreqModeUpload out;
  if (records.empty()) return out;  // the list stays as it was
  std::vector<int> list;
  std::vector<std::vector<radio::SatelliteMode>> modes(db.satellites.size());  // the file's, by satellite
  for (const auto& r : records) {
    const auto i = db.find(r.name);
    if (!i) {
      out.skipped.push_back("line " + std::to_string(r.line) + ": no satellite named (" + r.name +
                            ") in the database, not taken");
      continue;
    }
    if (!take_mode(modes[static_cast<std::size_t>(*i)], r, out)) continue;
    if (std::find(list.begin(), list.end(), *i) != list.end()) continue;
    if (static_cast<int>(list.size()) >= kMaxSelected) {
      out.skipped.push_back("line " + std::to_string(r.line) + ": (" + r.name +
                            ") updated but not selected: the list holds 15");
      continue;
    }
    list.push_back(*i);
    out.updated.push_back("Satellite (" + r.name + ") updated and selected as # " + std::to_string(list.size()));
  }
  for (std::size_t i = 0; i < modes.size(); ++i)
    if (!modes[i].empty()) set_modes(db.satellites[i], std::move(modes[i]));
  if (!list.empty()) {
    db.selected = std::move(list);
    db.marked = 0;
  }
  db.normalise();
  return out;
}

Database make_database(const std::vector<orbit::Elements>& sets, const std::vector<radio::FreqModeRecord>& records) {
  orbit::ParseResult parsed;
  parsed.sets = sets;
  ElementsUpload up = build_elements_upload(Database{}, parsed);
  apply_freqmode(up.database, records);
  up.database.normalise();
  return up.database;
}

}  // namespace tb::store
