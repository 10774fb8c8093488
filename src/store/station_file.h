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
// The later firmware (v3.20d-3.50b) reads seven lines, `;` comment lines and blank lines allowed:
//
//   1 CALL LAT LON HEIGHT S|N [BAUD]        + the COM port speed (station.com_baud)
//   2 AZMIN AZMAX ELMIN ELMAX [F]           + F: flip mode (rotator.el_flip_allowed)
//   3 AZ_DB EL_DB AZ_SKEW EL_SKEW           as 1994
//   4 RIG FULL|AOS RXADDR TXADDR [BAUD]     RIG also KENWOOD711, YAESU_o, YAESU_847, YAESU_736,
//                                           YAESUw736, YAESUw847 (radio.rig_model, ft736_wide_fm);
//                                           + CAT baud (radio.cat_baud)
//   5 PARK[m][n] PARK_AZ PARK_EL ROTOR_START_EL P16_ON_EL P16_OFF_EL
//                                           parking, mic-click digits (radio.mic_click.park_*),
//                                           park position, Model::pass_events
//   6 PF RX_MHZ TX_MHZ RX_MODE TX_MODE TIMEOUT_S
//                                           radio.parking, Model::rotator_error_detection,
//                                           rotator.stall_s
//   7 LIMIT AZMIN AZMAX ELMIN ELMAX         rotator limits (degrees; azimuth may wrap through North)
//
// The form is told by line 5 (7 items: later, 9: 1994), or else by lines numbered 6 or 7.
//
// The parser reads the whole text and reports every problem with its line and field, what it found
// and what was expected; it applies nothing. apply_station_file() (station_file_model.h) commits to a
// model only when the result is a valid configuration as a whole.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "radio/config.h"
#include "rotator/config.h"
#include "station/station.h"
#include "store/model.h"

namespace tb::store {

// What the five lines carry, in the configurations they belong to. Only the fields the lines name
// are read (the others keep their defaults here) and only those are applied: line 1 is the station's
// callsign, position and rotor start; lines 2, 3 and 5 the rotator's span, dead band, skew, parking
// and limits; line 4 the radio's rig, F/A policy and Icom addresses.
struct StationFile {
  station::StationConfig station;
  rotator::RotatorConfig rotator;
  radio::RadioConfig radio;
  // The later firmware's seven-line file: what it carries beyond the 1994 lines.
  bool later_firmware = false;
  bool com_baud_given = false;   // line 1's optional BAUD
  bool cat_baud_given = false;   // line 4's optional BAUD
  bool wide_fm_given = false;    // line 4 named a Yaesu model (YAESU_736: standard filter, YAESUw736: wide)
  PassEvents pass_events;        // line 5
  bool rotator_error_detection = true;  // line 6

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
std::string station_file_item_name(int line, int field, bool later_firmware = false);

}  // namespace tb::store
