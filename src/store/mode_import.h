// Modes imported from the public lists and merged into the satellites' modes (issue 59, item 3).
//
//   file text --read_mode_list(format)--> ModeList (every mode the list offers, or one error naming
//   the file, line and field) --merge_modes--> the database's modes, each field with its source
//
// Readers (pure, each refusing the whole file with one sentence naming file, line and field):
//   satnogs     SatNOGS DB transmitters JSON (db.satnogs.org/api/transmitters/): every transmitter
//               that is alive and "active" becomes a mode; no tones (the list has none).
//   trsp        Gpredict's NNNNN.trsp (INI, one [group] per transponder: UP_LOW, UP_HIGH, DOWN_LOW,
//               DOWN_HIGH in Hz, INVERT=true|false, MODE, BAUD); the catalog number is the file's name.
//   sqf         SatPC32's Doppler.SQF: `name,down kHz,up kHz,down mode,up mode,NOR|REV,down offset,
//               up offset,comment`, one line per mode (the comment names it).
//   subtone     SatPC32's SubTone.SQF: `name,tone Hz` per satellite (its FM voice modes: named FM or
//               FM-2 ..., with an FM uplink; not APRS or packet).
//   oscarwatch  OscarWatch's satellite_database.json: satellites with name, norad_id,
//               alternative_names and modes[{type, downlink kHz, uplink kHz, downlink_mode,
//               uplink_mode, doppler NOR|REV, ctcss, ctcss_arm}].
//
// Merge: a list's satellite is matched by catalog number, else by name (case, dashes and leading
// zeros aside: "AO-7" is "AO-07"); its mode by name (case aside), else by frequency (a transponder's
// passbands overlapping the mode's, or a downlink within 5 kHz of the mode's in the same radio mode;
// a spot inside a passband, as RS-44's FT4, is a mode of its own). Each field keeps
// its source (radio::FieldSource). A field that is empty or came from a list takes the list's
// value; one from the operator or the freq/mode file is kept and a different value is reported as a
// conflict ("RS-44 SSB downlink: kept your 435.640 MHz (operator); satnogs says 435.650 MHz") and
// remembered for `trakbox radio diff`; `replace` takes the list's value over those too. A mode the
// satellite lacks is added. What a list does not give (a tone, the uplink of a receive-only entry)
// is a gap, not "none": the mode's value stays. Values stored before sources existed count as the operator's.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "store/database.h"

namespace tb::store {

enum class ListFormat { satnogs, trsp, sqf, subtone, oscarwatch };
const char* to_string(ListFormat f);                      // "satnogs", "trsp", "sqf", "subtone", "oscarwatch"
std::optional<ListFormat> parse_list_format(std::string_view text);
// The source name a format's values get: "satnogs", "gpredict", "satpc32" (sqf, subtone), "oscarwatch".
const char* source_name(ListFormat f);
// The format a file is in, from its content and name; nullopt when neither tells.
std::optional<ListFormat> guess_list_format(std::string_view text, std::string_view file_name);

// The fields of a mode that carry a source.
enum class ModeField : unsigned { downlink, uplink, downlink_mode, uplink_mode, passbands, inverting, tone, arm, count };
const char* to_string(ModeField f);  // "downlink", "uplink", "downlink_mode", ... (the sources' keys)
constexpr unsigned field_bit(ModeField f) { return 1u << static_cast<unsigned>(f); }
// The field's value in canonical text ("435640000", "USB", "435610000-435670000/145935000-145995000",
// "y", "670"); "" when the field is empty (0, none, no passbands).
std::string field_value(const radio::SatelliteMode& m, ModeField f);
// The value as the operator reads it ("435.640 MHz", "USB", "67.0 Hz", "inverting").
std::string field_shown(const radio::SatelliteMode& m, ModeField f);
// Who gave the field's value now: its recorded source while the value is still the one recorded,
// else "operator"; "" for an empty field without a source.
std::string field_source(const radio::SatelliteMode& m, ModeField f);
// Records `from` as the source of every non-empty field of m (the freq/mode file's upload).
void mark_sources(radio::SatelliteMode& m, const std::string& from);

// One mode a list offers.
struct ListedMode {
  long long catalog = 0;       // 0: the list gives none (matched by name)
  std::vector<std::string> names;  // the list's names of the satellite (the first shown)
  radio::SatelliteMode mode;   // name and the fields the list gives
  unsigned given = 0;          // field_bit()s of the fields the list gives
  bool fm_uplinks = false;     // SubTone.SQF: the tone goes to the satellite's FM modes with an uplink
  int line = 0;                // where in the file (for messages); 0 when the format has no lines
};

struct ModeList {
  ListFormat format = ListFormat::satnogs;
  std::vector<ListedMode> modes;
  int not_offered = 0;         // SatNOGS transmitters not alive or not active
  std::string error;           // "44909.trsp: line 4, UP_LOW: ..."; nothing is offered then
  bool ok() const { return error.empty(); }
};

// Reads the whole file; `file_name` names it in errors (and gives a .trsp file its catalog number).
ModeList read_mode_list(ListFormat format, std::string_view text, std::string_view file_name);

struct MergeReport {
  std::vector<std::string> added;      // "RS-44 CW: added from satnogs (435.605 MHz CW)"
  std::vector<std::string> updated;    // "RS-44 SSB uplink: 145.965 MHz from satnogs (was 145.960 MHz, gpredict)"
  std::vector<std::string> conflicts;  // "RS-44 SSB downlink: kept your 435.640 MHz (operator); satnogs says 435.650 MHz"
  std::vector<std::string> skipped;    // not in the database, no room for another mode
  int unchanged = 0;                   // modes matched whose fields all agreed
  bool changed = false;                // the database differs
};

// Merges the list's modes into db (whole: the caller commits db only when it wants the result).
MergeReport merge_modes(Database& db, const ModeList& list, bool replace);

// The report as lines for a terminal, the last a count: "2 added, 1 updated, 1 conflict, ...".
std::vector<std::string> report_lines(const MergeReport& r, const ModeList& list);

// `trakbox radio diff`: every mode of every satellite with a value from a list or a conflict, one
// line per field: "RS-44 SSB downlink 435.640 MHz operator; satnogs says 435.650 MHz".
// `satellite`: that one's only (its name as the database has it); `conflicts`: only the fields a
// list said otherwise.
std::vector<std::string> diff_lines(const Database& db, std::string_view satellite = {}, bool conflicts = false);


// ---- `trakbox radio import|diff` (cli/radio_client.cpp), on the running station or the state file

class ModelOwner;
enum class Origin;

// A request {"action": "import", "file": NAME, "format": "trsp" | absent (guessed), "text": TEXT,
// "replace": bool} or {"action": "diff"[, "satellite": NAME][, "conflicts": true]}, done through the model's owner (import: one named edit of
// the radio entries, after the whole file was read). The answer: {"lines": [...], "changed": bool}
// or {"error": "..."} (nothing changed).
nlohmann::json radio_request(ModelOwner& owner, const nlohmann::json& request, Origin origin);

}  // namespace tb::store
