// The freq/mode file of menu 3-3: after a kepele upload TrakBox asks for one line per satellite,
//
//   NAME DOWN_MHZ UP_MHZ DOWN_MODE UP_MODE DOPPLER PHASE [REVERSE]
//   AO-13S 2400.730/-2256.000 435.620 usb lsb mic ma
//
// seven fields separated by spaces (tabs accepted), the name case-sensitive, a frequency with an
// optional converter offset after '/', modes usb/lsb/fm/cw/none, Doppler cat/mic, phase ma/no.
// Frequencies are converted from the decimal text exactly (no floating point).
//
// The same parser reads the later firmware's FREQ.DAT (v3.20d-3.50b), a superset:
//   ; a comment line (blank lines are skipped too)
//   FO-29 435.850 145.950,145.960,145.970,145.980 usb lsb cat no kr
// up to four uplinks separated by commas (the first the default, the others kept as alternatives
// in SatelliteRadio::alternate_uplinks_hz; an offset after the last applies to all), `cw` as a
// mode, and an optional 8th field `ir`/`kr` (SatelliteRadio::reverse). A 1994 file reads as before.
//
// The parser reads the whole text and returns every record and every problem; it applies
// nothing. A line with a problem gives no record; the other lines do. The callers (3-3, --data,
// SIGHUP) apply the good records and report the problems with their line numbers.
// One record per line: the manual's printed sample was flattened onto one line by OCR, which this
// parser reports as a line of 112 fields rather than guessing where records end.
//
// trakbox's own options may follow a record (written back only when set, so other readers see the
// same 7 or 8 fields otherwise):
//   RS-44 435.640 145.965 usb lsb cat no down=435.610-435.670 up=145.935-145.995 inv=y
//   SO-50 436.795 145.850 fm fm cat no tone=67.0
// down=/up= a linear transponder's passbands (MHz, both or neither), inv=y|n whether it inverts,
// tone= the uplink's CTCSS tone in Hz.
//
// A satellite worked in several ways has one line per mode, each naming it (issue 59):
//   RS-44 435.640 145.965 usb lsb cat no down=435.610-435.670 up=145.935-145.995 inv=y mode=SSB
//   RS-44 435.611 145.99361 usb usb cat no down=435.610-435.670 up=145.935-145.995 inv=y mode=FT4
//   SO-50 436.795 145.850 fm fm cat no tone=67.0 arm=74.4 mode=FM
// mode=NAME (radio::mode_name_problem's rule) the mode's name, arm=HZ the tone that arms the
// repeater. The first line of a satellite is its default mode. A name given twice with the same
// mode (or twice without any) is a problem on the later line.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "radio/config.h"

namespace tb::radio {

struct FreqModeRecord {
  int line = 0;            // 1-based line of the upload it came from (0 when built by hand)
  std::string name;        // exactly as in the kepele data (case-sensitive)
  SatelliteRadio radio;
  std::string mode;            // mode=NAME; "": the satellite's one mode (radio::default_mode_name)
  int arm_tone_tenths_hz = 0;  // arm=HZ
  bool operator==(const FreqModeRecord&) const = default;
};

struct FreqModeProblem {
  int line = 0;            // 1-based
  int field = 0;           // 1..8, 0 for the line as a whole; an option's place on the line
  std::string found;
  std::string expected;
  bool option = false;     // one of trakbox's options (down= up= inv= tone= arm= mode=) after the record
  // "line 3, field 2 (downlink frequency): found "43x.1", expected ..."
  std::string message() const;
};

struct FreqModeParse {
  std::vector<FreqModeRecord> records;
  std::vector<FreqModeProblem> problems;
  bool ok() const { return problems.empty(); }
};

// Reads up to the end of the text or the first Ctrl-Z (0x1A), whichever comes first. Lines end in
// CR, LF or CR LF; blank lines are skipped. A name given twice is a problem on the later line.
FreqModeParse parse_freqmode(std::string_view text);

// The field names used in problems: 1 "satellite name", 2 "downlink frequency", ...
const char* freqmode_field_name(int field);

// Decimal MHz text to Hz, exactly: "435.12", "2400.730", "-2256.000", "+1.5", "145". At most six
// decimals carry value (1 Hz); further decimals must be zeros. nullopt when not a number.
std::optional<Hz> parse_mhz(std::string_view text);
struct FrequencyField {
  Hz rf_hz = 0;
  Hz offset_hz = 0;
};
// "2400.730/-2256.000" or "435.620". The RF part must not be negative; the offset may be.
std::optional<FrequencyField> parse_frequency_field(std::string_view text);
struct UplinkField {
  std::vector<Hz> rf_hz;  // 1 to kMaxUplinkChannels, the default first
  Hz offset_hz = 0;
};
// "145.900", "145.950,145.960,145.970,145.980" or "1268.100,1268.200/-1124.000": the FREQ.DAT
// uplink field. nullopt when a channel is empty, negative or not a number, or there are more than 4.
std::optional<UplinkField> parse_uplink_field(std::string_view text);

// Hz to MHz text with at least three decimals and as many more as needed (up to six):
// 435120000 -> "435.120", 435123450 -> "435.12345", -2256000000 -> "-2256.000".
std::string format_mhz(Hz hz);
// "2400.730/-2256.000", or just "435.620" when the offset is zero.
std::string format_frequency_field(Hz rf_hz, Hz offset_hz);

// One line (without a line end) and a whole file ("\n" after each line, no Ctrl-Z); alternative
// uplinks and the ir/kr flag are written in the later firmware's form.
std::string format_freqmode_line(const FreqModeRecord& r);
std::string write_freqmode(const std::vector<FreqModeRecord>& records);

}  // namespace tb::radio
