// Satrak ACU payloads: a command word, `?` (query) or `=` (request), and comma-separated fields.
// Parsing is liberal (docs/satrak.md, "Parsing"): the comma after `?`/`=` may be missing
// (`ANGLE_SETTINGS=0,39049,...`, the reply `STATUS?0,299.49,...`), blanks around the word and the
// fields are ignored (`TRACK_AUTO_ENABLE =,1`, `SATELLITE_HTTP=, https://...`), the word may be in
// any case. Replies are exact: the canonical word, `,OK`, `,ERR,<code>` or the values.
//
// Pure: values in, values out. The same parser reads requests (the server) and replies (the client).
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tb::satrak {

// The error codes of `WORD,ERR,<code>` (docs/satrak.md, "Error codes"). The seed names none; this
// table is trakbox's own and every reply uses it.
enum class Error : int {
  bad_checksum = 1,     // the frame's checksum does not match: nothing was done
  malformed_frame = 2,  // `$` without `*` and two hex digits
  frame_too_long = 3,   // a line longer than 512 bytes: discarded up to its end
  unknown_command = 4,  // no such command word, or not as a query/request (`STOP?`)
  parameter_count = 5,  // too few or too many fields
  bad_value = 6,        // a field is not what it must be (a number, 0/1, a file name, ...)
  out_of_range = 7,     // a number outside the allowed range, a date that does not exist
  not_allowed = 8,      // not in the current state (rotor control off, no satellite, no GPS, ...)
  file_not_found = 9,   // the TLE file or image file does not exist
  satellite_not_found = 10,  // the satellite is not in the TLE file
  invalid_file = 11,    // the file exists but does not parse or validate (image, TLE)
  internal = 12,        // trakbox could not do it (a file could not be written, ...)
};
int code(Error e);
// One line for people: "bad checksum", "unknown command", ...
const char* describe(Error e);

enum class Kind { query, request };  // `?` / `=`

struct Command {
  std::string word;                 // upper case, blanks trimmed: "TRACK_AUTO_ENABLE"
  Kind kind = Kind::query;
  std::vector<std::string> fields;  // blanks trimmed; "" for an empty field
  // "STATUS?" / "MOVE=": how a reply begins.
  std::string head() const { return word + (kind == Kind::query ? "?" : "="); }
  friend bool operator==(const Command&, const Command&) = default;
};

// Splits a payload. Nothing when it has no `?` or `=`, or no word before it, or the word (blanks
// around it dropped) holds characters other than letters, digits and `_`, or more than 32 of them.
std::optional<Command> parse_payload(std::string_view payload);

// A word that is safe to echo in a reply: upper case, only letters, digits and `_`, at most 32
// characters; "" when nothing is left.
std::string sanitize_word(std::string_view word);

// Replies. `head` is "MOVE=" or "STATUS?".
std::string reply_ok(std::string_view head);                      // "MOVE=,OK"
std::string reply_error(std::string_view head, Error e);          // "MOVE=,ERR,5"; "ERR,3" without head
// A refusal that says why, in a field after the code: "RTC_REUPDATE=,ERR,8,NO GPS RECEIVER". The
// reason is upper-cased and anything that would break the frame (`,` `*` `$`,
// control bytes, non-ASCII) becomes a blank; an empty reason gives the plain form.
std::string reply_error(std::string_view head, Error e, std::string_view reason);
std::string reply_values(std::string_view head, const std::vector<std::string>& values);  // "TPOS?,1,2"

// Field readers: nothing when the text is not exactly that (blanks already trimmed by the parser).
std::optional<double> parse_number(std::string_view s);    // "12", "-3.5", "+2", ".5" (finite)
std::optional<long long> parse_integer(std::string_view s);  // "12", "-3", "+2"
// "41.01N", "29.17E", "12.5S", "-12.5" (sign or hemisphere letter, either case). Nothing when
// the letter does not fit the axis (N/S for latitude, E/W for longitude) or the value is past 90/180.
std::optional<double> parse_latitude(std::string_view s);
std::optional<double> parse_longitude(std::string_view s);
// "41.0100N" / "29.1700E" (four decimals).
std::string format_latitude(double deg);
std::string format_longitude(double deg);
// Fixed decimals, never "-0.00".
std::string format_fixed(double v, int decimals);

}  // namespace tb::satrak
