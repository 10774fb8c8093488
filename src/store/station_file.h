// The station information file of menu 6-9 ("Upload Station info data file (EOF:ctrl-Z)"):
//
//   1 WA7GXD 32.259 -110.778 842 S          callsign, latitude, longitude, height (m), rotor start N/S
//   2 3 1017 5 454                          ADC span: azimuth min, max, elevation min, max (counts)
//   3 5 3 0 0                               dead band az, el; skew az, el (counts)
//   4 ICOM A 10 14                          CAT rig, F/A, Icom RX address, Icom TX address (hex)
//   5 1 90 0 1 270 90 0 45                  parking on/off, park az, park el,
//                                           limit on/off, az min, az max, el min, el max (degrees)
//
// Items are separated by spaces or tabs; each line starts with its number and the lines come in
// order. Lines 2 and 3 are ADC counts; line 5 is degrees although the manual's note says counts
// (its own sample, "5 1 90 0 1 270 90 0 45", only makes sense in degrees: docs/menus/6-7-8.md).
//
// The parser reads the whole text and reports every problem with its line and field, what it found
// and what was expected; it applies nothing. apply_station_file() commits to a model only when the
// result is a valid configuration as a whole.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "radio/config.h"
#include "rotator/config.h"
#include "station/station.h"

namespace tb::store {

struct Model;

// What the five lines carry, in the configurations they belong to. Only the fields the lines name
// are read (the others keep their defaults here) and only those are applied: line 1 is the station's
// callsign, position and rotor start; lines 2, 3 and 5 the rotator's span, dead band, skew, parking
// and limits; line 4 the radio's rig, F/A policy and Icom addresses.
struct StationFile {
  station::StationConfig station;
  rotator::RotatorConfig rotator;
  radio::RadioConfig radio;

  bool operator==(const StationFile&) const = default;
};

struct StationFileProblem {
  int line = 0;        // 1-based line of the upload (0: the file as a whole)
  int field = 0;       // 1-based item of that line, the line number being item 1 (0: the whole line)
  std::string what;    // the item's name: "callsign", "azimuth maximum", ...
  std::string found;   // what the text had ("" when the item is missing)
  std::string expected;
  // line 2, item 3 (azimuth maximum): found "1030", expected ADC counts 0 to 1023
  std::string message() const;
};

struct StationFileParse {
  std::optional<StationFile> file;          // only when there is no problem
  std::vector<StationFileProblem> problems; // sorted by line, then item
  bool ok() const { return problems.empty(); }
};

// Reads up to the end of the text or the first Ctrl-Z (0x1A). Lines end in CR, LF or CR LF; blank
// lines are skipped (they still count for the line numbers in problems).
StationFileParse parse_station_file(std::string_view text);

// The name of item `field` of line `line` ("callsign", "Icom RX address", ...).
std::string station_file_item_name(int line, int field);

// Applies the file to the model (station, rotator span/dead band/skew/parking/limits, radio rig,
// F/A and Icom addresses) when the resulting rotator configuration passes rotator::validate; returns
// its complaints otherwise, and then the model is unchanged. The COM port speed, presets, Doppler
// corrections, mic-click values and the database are not in the file and are left as they are.
std::vector<std::string> apply_station_file(const StationFile& f, Model& m);

// The model's values as a station file (five lines, each ending in "\n"): what parse reads back.
std::string write_station_file(const Model& m);

}  // namespace tb::store
