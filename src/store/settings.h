// Every stored setting, declared once (issue 55): its key (the path of its field in the state
// document), type, unit, range or choices, the --option and the menu that set it, and one line of
// help. The default is the factory model's value (store::factory_defaults), not a second number.
//
// Whoever reads or sets a setting takes its bounds and its refusal from here: the state reader
// (model.cpp), the command line, `trakbox settings`, host mode, the web API and the menus' input
// bounds. A value is refused with one sentence per setting, the same wherever it was typed:
//   "station.height_m: 12000 is outside -500 .. 9000 m"
// Pure: values in, values or sentences out.
#pragma once
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>  // ParsedSetting holds a value

namespace tb::store {

struct Model;

enum class SettingType { number, integer, boolean, choice, text };

struct Setting {
  std::string_view key;     // "station.height_m": the state document's path
  SettingType type;
  std::string_view unit;    // "m", "deg", "s", "counts", "Hz", "" (shown after numbers)
  double lo = 0.0, hi = 0.0;             // number, integer: the range, both ends taken
  std::span<const std::string_view> choices;  // choice: the words taken; text: unused
  std::size_t max_len = 0;               // text: the longest taken
  std::string_view option;  // "--az-travel" ("" when the command line does not set it)
  std::string_view menu;    // "6-4" ("" when no menu shows it)
  std::string_view help;    // one line
  // The setting's value in a model, as the state document holds it.
  nlohmann::json (*get)(const Model&);
  // Puts an already checked value into a model.
  void (*put)(Model&, const nlohmann::json&);
};

// The table, in the state document's order.
std::span<const Setting> settings();
const Setting* find_setting(std::string_view key);

// The sentence refusing `value` for `s`, nothing when it is taken. The value is in the state
// document's JSON form (a number, true/false, a string).
std::optional<std::string> refusal(const Setting& s, const nlohmann::json& value);

// A value as an operator types it ("9000", "on", "yes", "north", "cloudlog:https://...") into the
// setting's JSON form, checked: the value, or the sentence refusing it.
struct ParsedSetting {
  std::optional<nlohmann::json> value;  // set when taken
  std::string error;
};
ParsedSetting parse_setting(const Setting& s, std::string_view typed);

// What the operator is told after setting `key` in `m` (`trakbox settings set`), nothing when all
// is well: a parking position below the horizon mask after station.horizon_mask or the parking
// switch (issue 57: the parking position is the operator's, never moved; rotator/parking_mask.h).
std::optional<std::string> setting_warning(std::string_view key, const Model& m);

// The value as `trakbox settings` shows it ("9000 m", "on", "north", "\"\"").
std::string shown(const Setting& s, const nlohmann::json& value);
// "-500 .. 9000 m", "north, south", "on or off", "text, at most 10 characters".
std::string range_text(const Setting& s);

// The state reader's side: the value of `s` in `object` (the setting's parent object in the
// document, `where` its path), checked. Throws std::runtime_error with the setting's sentence, or
// "KEY: missing" when it is absent.
nlohmann::json read_setting(const nlohmann::json& object, std::string_view key);

// Every setting of `m` as `trakbox settings --json` lists them: key, value (the state document's
// form), shown, type, unit, range, default, from (`from(key)`: "default", "state", "command line",
// ...), option, menu, help.
nlohmann::json settings_document(const Model& m, const std::function<std::string(std::string_view)>& from);
// The same as text, one setting a line: key, value, from, range, and the option or menu.
std::string settings_text(const nlohmann::json& document);

// The station's position as an operator types it, one reading for every front end (--station, host
// mode's QTH, `passes --station`): LAT,LON[,HEIGHT_M] in degrees (+ north, + east; or 48.85N,2.35E,
// W and S for west and south; east longitudes to 360 taken) or a Maidenhead locator's centre
// (JN18du[,HEIGHT_M], height 0 unless given). Each number by the table's rule and sentence. A
// position typed without a height has none (`height_m` empty: the caller keeps the stored one).
struct ParsedPosition {
  double lat_deg = 0.0, lon_deg = 0.0;
  std::optional<double> height_m;
  std::string error;  // set when refused: what, in the text, and what is expected
  bool ok() const { return error.empty(); }
};
ParsedPosition parse_position(std::string_view text);

// A number's bounds for the readers that take them as a pair (the command line's Range, a menu's
// prompt): the table's lo and hi of a number or integer setting.
struct Bounds {
  double lo, hi;
};
Bounds bounds(std::string_view key);

}  // namespace tb::store
