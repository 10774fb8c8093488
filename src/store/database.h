// The kepele database (up to 32 satellites with their radio entries) and the tracking list
// (up to 15 of them, in the order the operator selected them). Menus 3-1 to 3-4 work on this.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "orbit/elements.h"
#include "radio/config.h"
#include "radio/freqmode.h"

namespace tb::store {

inline constexpr int kMaxDatabase = 32;
inline constexpr int kMaxSelected = 15;
inline constexpr int kMinMultiTrack = 2;
inline constexpr int kMaxMultiTrack = 5;

// A satellite and how it is worked. `radio` is the record of the chosen mode, the one everything
// that tunes, logs and edits reads and writes (menu 3-1, the freq/mode file, tones, the page);
// `modes` holds every named mode (issue 59), the chosen one's record as it was when it was last
// chosen or stored: modes_of() gives them with `radio` in the chosen one's place.
struct Satellite {
  orbit::Elements elements;
  radio::SatelliteRadio radio;
  std::vector<radio::SatelliteMode> modes;  // at most radio::kMaxModes, names differ (case aside)
  std::string mode;                         // the chosen (default) mode's name; "" without modes
  const std::string& name() const { return elements.name; }
};

// The satellite's modes as stored: `radio` as the chosen one's record. A satellite with a radio
// record and no modes (a state written before modes, an upload of the 1994 file) has one, named
// radio::default_mode_name; one without either has none.
std::vector<radio::SatelliteMode> modes_of(const Satellite& s);
// The name of the chosen mode as modes_of gives it ("" without modes).
std::string chosen_mode(const Satellite& s);
// The mode named `name` (case aside) of modes_of(s), or nothing.
std::optional<radio::SatelliteMode> find_mode(const Satellite& s, std::string_view name);
// Chooses the mode named `name` (case aside): the working record is kept in the mode it belongs
// to, and `radio` becomes the new mode's. False, nothing changed, when there is no such mode.
bool choose_mode(Satellite& s, std::string_view name);
// Puts the modes into their stored form: `modes` = modes_of(s), `mode` its chosen one.
void settle_modes(Satellite& s);

struct Database {
  std::vector<Satellite> satellites;  // database order, at most kMaxDatabase
  std::vector<int> selected;          // tracking list: indices into satellites, #1 first
  int marked = -1;                    // the '*': position in `selected` of the last one chosen
  int multi_count = 2;                // menu 3-4: the first N of the list are multi-tracked

  // Case-sensitive name lookup (the manual: names are case sensitive).
  std::optional<int> find(std::string_view name) const;
  // The satellite at tracking-list number n (1-based), if any.
  const Satellite* listed(int number) const;
  // Tracking-list number (1-based) of database index i, 0 if not listed.
  int list_number(int db_index) const;
  // Menu 3-2: append database index i to the list (no duplicates, at most 15). Returns the new
  // list number, or 0 when the list is full or i is invalid; an index already listed returns its
  // number unchanged.
  int select(int db_index);
  // Marked satellite's database index, if the mark is valid.
  std::optional<int> marked_index() const;
  // Keeps `selected` and `marked` consistent after edits.
  void normalise();
};

// Menu 3-3 step 1: a kepele upload replaces the whole database. Built from a parse result without
// touching the stored database; the caller commits it only when the upload ended cleanly.
struct ElementsUpload {
  Database database;                 // the new database (radio entries carried over by name)
  std::vector<std::string> accepted; // names in database order ("NASA>#1 AO-10" lines)
  std::vector<std::string> skipped;  // one line per record not taken, with where and why
};
ElementsUpload build_elements_upload(const Database& old, const orbit::ParseResult& parsed);

// Menu 3-3 step 2: the freq/mode file updates radio entries by satellite name and builds the
// tracking list in the order of the file. Without records the list is the first 15 satellites.
struct FreqModeUpload {
  std::vector<std::string> updated;  // "Satellite (NAME) updated and selected as # n"
  std::vector<std::string> skipped;  // records whose name is not in the database, or beyond 15
};
FreqModeUpload apply_freqmode(Database& db, const std::vector<radio::FreqModeRecord>& records);

// A database made from element sets and freq/mode records (the shipped defaults).
Database make_database(const std::vector<orbit::Elements>& sets, const std::vector<radio::FreqModeRecord>& records);

}  // namespace tb::store
