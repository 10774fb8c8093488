// Field parsers and writers that the element-set formats share: lines of text, problems, numbers,
// epochs. The NASA (elements_tle.cpp), AMSAT (elements_amsat.cpp) and gpredict
// (elements_gpredict.cpp) readers use them, and a reader of another format (OMM) can: none of them
// knows a format's layout. Private to src/orbit.
#pragma once
#include <algorithm>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "orbit/elements.h"
#include "util/format.h"
#include "util/text.h"

namespace tb::orbit::detail {

// ---------------------------------------------------------------------------------------------
// Text

struct TextLine {
  std::string_view text;  // without its line break
  int number = 0;         // 1-based
};

// Splits on LF, CRLF or a lone CR. A UTF-8 byte-order mark is skipped; a Ctrl-Z (the end of an
// ASCII upload) ends the text.
std::vector<TextLine> split_lines(std::string_view text);

// Blanks are what pads the formats' fields: ' ' and '\t' (text::kBlanks, trim's default), never a
// line break or another control character.
using text::is_digit;
using text::to_lower;
using text::trim;
using text::trim_left;
using text::trim_right;
inline bool is_space(char c) { return text::kBlanks.find(c) != std::string_view::npos; }
inline bool is_upper(char c) { return c >= 'A' && c <= 'Z'; }
inline bool is_blank(std::string_view s) { return trim(s).empty(); }
inline bool all_digits(std::string_view s) { return !s.empty() && std::all_of(s.begin(), s.end(), is_digit); }

ParseProblem make_problem(std::string_view file, int line, int column, std::string field, std::string found,
                          std::string expected, bool warning = false);

// ---------------------------------------------------------------------------------------------
// Numbers

// The formats' numbers are stricter than text::parse_double and text::parse_integer (which take a sign
// and an exponent wherever std::from_chars does, and no blanks around): these check the format's
// syntax first, then convert with text.h.
//
// A decimal number without exponent: optional sign (+ or -), digits with at most one point.
// Leading and trailing blanks are allowed, blanks inside are not.
std::optional<double> parse_fixed(std::string_view s);
// A free-form number: optional sign, digits with at most one point, optional exponent.
std::optional<double> parse_general(std::string_view s);
// Digits only (blanks around allowed), at most 9 of them: no sign.
std::optional<long> parse_unsigned(std::string_view s);
// Nothing when v lies in [low, high] (high_inclusive) or [low, high); otherwise what a problem says
// was expected: "number in [0, 360)".
std::optional<std::string> out_of_range(double v, double low, double high, bool high_inclusive);

// ---------------------------------------------------------------------------------------------
// Writers

using text::printf_string;  // util/format.h
// Fixed-point text with at least `decimals` decimals, more when needed to give back the value.
std::string round_trip_fixed(double v, int decimals);
// "YYDDD.DDDDDDDD" (also columns 19-32 of line 1).
std::string epoch_text(int year, double day, bool round_trip);

}  // namespace tb::orbit::detail
