// Element-set formats: NASA two/three-line, AMSAT verbose, gpredict satdata. See
// docs/element-formats.md for what is accepted and how problems are reported.
#include "orbit/elements.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdarg>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <system_error>

namespace tb::orbit {
namespace {

// ---------------------------------------------------------------------------------------------
// Text helpers

struct TextLine {
  std::string_view text;  // without its line break
  int number = 0;         // 1-based
};

// Splits on LF, CRLF or a lone CR. A UTF-8 byte-order mark is skipped; a Ctrl-Z (the end of an
// ASCII upload) ends the text.
std::vector<TextLine> split_lines(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  if (const auto z = text.find('\x1a'); z != std::string_view::npos) text = text.substr(0, z);
  std::vector<TextLine> lines;
  std::size_t start = 0;
  int number = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c != '\n' && c != '\r') continue;
    lines.push_back({text.substr(start, i - start), number++});
    if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
    start = i + 1;
  }
  if (start < text.size()) lines.push_back({text.substr(start), number});
  return lines;
}

bool is_space(char c) { return c == ' ' || c == '\t'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_upper(char c) { return c >= 'A' && c <= 'Z'; }
char to_lower(char c) { return is_upper(c) ? static_cast<char>(c - 'A' + 'a') : c; }

std::string_view trim_left(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  return s;
}
std::string_view trim_right(std::string_view s) {
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}
std::string_view trim(std::string_view s) { return trim_left(trim_right(s)); }
bool is_blank(std::string_view s) { return trim(s).empty(); }
bool all_digits(std::string_view s) { return !s.empty() && std::all_of(s.begin(), s.end(), is_digit); }

bool is_leap_year(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

// Parses all of s (no blanks) as a double with std::from_chars; s may not start with '+'.
std::optional<double> whole_double(std::string_view s, std::chars_format format) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v, format);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// A decimal number without exponent: optional sign (+ or -), digits with at most one point.
// Leading and trailing blanks are allowed, blanks inside are not.
std::optional<double> parse_fixed(std::string_view s) {
  s = trim(s);
  bool negative = false;
  if (!s.empty() && (s.front() == '+' || s.front() == '-')) {
    negative = s.front() == '-';
    s.remove_prefix(1);
  }
  int digits = 0, points = 0;
  for (const char c : s) {
    if (is_digit(c)) ++digits;
    else if (c == '.') ++points;
    else return std::nullopt;
  }
  if (digits == 0 || points > 1) return std::nullopt;
  const auto v = whole_double(s, std::chars_format::fixed);
  if (!v) return std::nullopt;
  return negative ? -*v : *v;
}

// A free-form number: optional sign, digits with at most one point, optional exponent.
std::optional<double> parse_general(std::string_view s) {
  bool negative = false;
  if (!s.empty() && (s.front() == '+' || s.front() == '-')) {
    negative = s.front() == '-';
    s.remove_prefix(1);
  }
  std::size_t i = 0;
  int digits = 0, points = 0;
  for (; i < s.size() && (is_digit(s[i]) || s[i] == '.'); ++i) {
    if (s[i] == '.') ++points;
    else ++digits;
  }
  if (digits == 0 || points > 1) return std::nullopt;
  if (i < s.size()) {
    if (s[i] != 'e' && s[i] != 'E') return std::nullopt;
    std::size_t j = i + 1;
    if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
    if (!all_digits(s.substr(j))) return std::nullopt;
  }
  const auto v = whole_double(s, std::chars_format::general);
  if (!v) return std::nullopt;
  return negative ? -*v : *v;
}

// Digits only (blanks around allowed), at most 9 of them.
std::optional<long> parse_unsigned(std::string_view s) {
  s = trim(s);
  if (!all_digits(s) || s.size() > 9) return std::nullopt;
  long v = 0;
  for (const char c : s) v = v * 10 + (c - '0');
  return v;
}

// The TLE's implied-decimal exponent field, 8 columns: sign (blank, + or -), five digits with an
// implied leading point, exponent sign (+ or -), one exponent digit. "-11606-4" = -0.11606e-4.
std::optional<double> parse_implied_exponent(std::string_view f) {
  if (f.size() != 8) return std::nullopt;
  const char sign = f[0];
  if (sign != ' ' && sign != '+' && sign != '-') return std::nullopt;
  const std::string_view mantissa = f.substr(1, 5);
  if (!all_digits(mantissa) || (f[6] != '+' && f[6] != '-') || !is_digit(f[7])) return std::nullopt;
  std::string text = "0.";
  text += mantissa;
  text += 'e';
  if (f[6] == '-') text += '-';
  text += f[7];
  const auto v = whole_double(text, std::chars_format::general);
  if (!v) return std::nullopt;
  return sign == '-' ? -*v : *v;
}

ParseProblem make_problem(std::string_view file, int line, int column, std::string field, std::string found,
                          std::string expected, bool warning = false) {
  ParseProblem p;
  p.file = std::string(file);
  p.line = line;
  p.column = column;
  p.field = std::move(field);
  p.found = std::move(found);
  p.expected = std::move(expected);
  p.warning = warning;
  return p;
}

// ---------------------------------------------------------------------------------------------
// NASA lines

// One element line as the parsers see it: the text, its line number in the file, and how far
// its column 1 is from the file's column 1 (5 for gpredict's "TLE1=").
struct ElementLine {
  std::string_view text;
  int number = 0;
  int column_offset = 0;
  std::string_view file;

  char at(int column) const {
    const auto i = static_cast<std::size_t>(column - 1);
    return i < text.size() ? text[i] : ' ';
  }
  std::string_view raw(int first, int last) const {
    const auto begin = static_cast<std::size_t>(first - 1);
    if (begin >= text.size()) return {};
    return text.substr(begin, static_cast<std::size_t>(last - first + 1));
  }
  ParseProblem problem(int first, int last, std::string field, std::string expected) const {
    return make_problem(file, number, first + column_offset, std::move(field), std::string(raw(first, last)),
                        std::move(expected));
  }
};

struct FieldSpec {
  int first;
  int last;
  const char* name;
};

constexpr FieldSpec kLine1Fields[] = {
    {1, 1, "line number"},      {3, 7, "catalog number"},   {8, 8, "classification"},
    {10, 17, "international designator"}, {19, 20, "epoch year"}, {21, 32, "epoch day"},
    {34, 43, "ndot/2"},         {45, 52, "nddot/6"},        {54, 61, "BSTAR"},
    {63, 63, "ephemeris type"}, {65, 68, "element set number"}, {69, 69, "checksum"},
};
constexpr FieldSpec kLine2Fields[] = {
    {1, 1, "line number"},        {3, 7, "catalog number"}, {9, 16, "inclination"},
    {18, 25, "RAAN"},             {27, 33, "eccentricity"}, {35, 42, "argument of perigee"},
    {44, 51, "mean anomaly"},     {53, 63, "mean motion"},  {64, 68, "revolution number"},
    {69, 69, "checksum"},
};

// A line shorter than the format: the first field it cuts is reported.
template <std::size_t N>
std::optional<ParseProblem> check_length(const ElementLine& l, const FieldSpec (&fields)[N], bool with_checksum) {
  const int needed = with_checksum ? 69 : 68;
  const int length = static_cast<int>(l.text.size());
  if (length >= needed) return std::nullopt;
  for (const FieldSpec& f : fields) {
    if (f.last > length) {
      return l.problem(f.first, f.last, f.name,
                       std::to_string(needed) + " columns (the line ends at column " + std::to_string(length) + ")");
    }
  }
  return std::nullopt;  // not reached: the checksum field always lies beyond a short line
}

std::optional<ParseProblem> check_blank(const ElementLine& l, int column) {
  if (l.at(column) == ' ') return std::nullopt;
  return l.problem(column, column, "separator", "blank");
}

std::optional<ParseProblem> check_checksum(const ElementLine& l) {
  const int sum = nasa_checksum(l.text);
  if (l.at(69) - '0' == sum) return std::nullopt;
  return l.problem(69, 69, "checksum", "checksum " + std::to_string(sum));
}

std::optional<ParseProblem> parse_catalog(const ElementLine& l, int& number) {
  number = decode_catalog_number(l.raw(3, 7));
  if (number >= 0) return std::nullopt;
  return l.problem(3, 7, "catalog number", "5 digits or Alpha-5 (letter A-Z without I and O, 4 digits)");
}

// Decimal field with a range check; blank is not allowed.
std::optional<ParseProblem> parse_decimal_field(const ElementLine& l, const FieldSpec& f, double low, double high,
                                                bool high_inclusive, double& out) {
  const auto v = parse_fixed(l.raw(f.first, f.last));
  if (!v) return l.problem(f.first, f.last, f.name, "decimal number");
  if (*v < low || *v > high || (!high_inclusive && *v == high)) {
    char range[64];
    std::snprintf(range, sizeof range, "number in [%g, %g%c", low, high, high_inclusive ? ']' : ')');
    return l.problem(f.first, f.last, f.name, range);
  }
  out = *v;
  return std::nullopt;
}

// Unsigned integer field, blank allowed (0).
std::optional<ParseProblem> parse_count_field(const ElementLine& l, const FieldSpec& f, long& out) {
  const std::string_view raw = l.raw(f.first, f.last);
  if (is_blank(raw)) {
    out = 0;
    return std::nullopt;
  }
  const auto v = parse_unsigned(raw);
  if (!v) return l.problem(f.first, f.last, f.name, "digits 0-9");
  out = *v;
  return std::nullopt;
}

// Implied-decimal exponent field; all blank is read as 0.
std::optional<ParseProblem> parse_exponent_field(const ElementLine& l, const FieldSpec& f, double& out) {
  const std::string_view raw = l.raw(f.first, f.last);
  if (is_blank(raw)) {
    out = 0.0;
    return std::nullopt;
  }
  const auto v = parse_implied_exponent(raw);
  if (!v) return l.problem(f.first, f.last, f.name, "implied-decimal exponent field such as -11606-4");
  out = *v;
  return std::nullopt;
}

std::optional<ParseProblem> parse_line1(const ElementLine& l, const ParseOptions& options, Elements& e) {
  const auto& F = kLine1Fields;
  if (auto p = check_length(l, F, options.verify_checksums)) return p;
  if (l.at(1) != '1') return l.problem(1, 1, F[0].name, "1");
  if (auto p = check_blank(l, 2)) return p;
  if (auto p = parse_catalog(l, e.catalog_number)) return p;

  const char cls = l.at(8);
  if (cls != ' ' && !is_upper(cls)) return l.problem(8, 8, F[2].name, "letter such as U, C or S");
  e.classification = cls == ' ' ? 'U' : cls;
  if (auto p = check_blank(l, 9)) return p;

  const std::string_view designator = l.raw(10, 17);
  if (!std::all_of(designator.begin(), designator.end(), [](char c) { return c == ' ' || is_digit(c) || is_upper(c); }))
    return l.problem(10, 17, F[3].name, "digits, capital letters and blanks, such as 98067A");
  e.international_designator = std::string(trim(designator));
  if (auto p = check_blank(l, 18)) return p;

  const std::string_view year = l.raw(19, 20);
  const auto yy = parse_unsigned(year);
  if (!yy || year[1] == ' ') return l.problem(19, 20, F[4].name, "two digits 00-99");
  e.epoch_year = expand_two_digit_year(static_cast<int>(*yy));
  const double day_limit = is_leap_year(e.epoch_year) ? 367.0 : 366.0;
  if (auto p = parse_decimal_field(l, F[5], 1.0, day_limit, false, e.epoch_day)) {
    if (p->expected != "decimal number") p->expected = "day of year in [1, " + std::to_string(int(day_limit)) + ")";
    return p;
  }
  if (auto p = check_blank(l, 33)) return p;

  const auto ndot = parse_fixed(l.raw(34, 43));
  if (!ndot) return l.problem(34, 43, F[6].name, "decimal number such as -.00002182");
  e.ndot_over_2 = *ndot;
  if (auto p = check_blank(l, 44)) return p;
  if (auto p = parse_exponent_field(l, F[7], e.nddot_over_6)) return p;
  if (auto p = check_blank(l, 53)) return p;
  if (auto p = parse_exponent_field(l, F[8], e.bstar)) return p;
  if (auto p = check_blank(l, 62)) return p;

  const char eph = l.at(63);
  if (eph != ' ' && !is_digit(eph)) return l.problem(63, 63, F[9].name, "digit 0-9 or blank");
  e.ephemeris_type = eph == ' ' ? 0 : eph - '0';
  if (auto p = check_blank(l, 64)) return p;

  long element_set = 0;
  if (auto p = parse_count_field(l, F[10], element_set)) return p;
  e.element_set_number = static_cast<int>(element_set);

  if (options.verify_checksums) return check_checksum(l);
  return std::nullopt;
}

std::optional<ParseProblem> parse_line2(const ElementLine& l, const ParseOptions& options, Elements& e) {
  const auto& F = kLine2Fields;
  if (auto p = check_length(l, F, options.verify_checksums)) return p;
  if (l.at(1) != '2') return l.problem(1, 1, F[0].name, "2");
  if (auto p = check_blank(l, 2)) return p;
  int catalog = 0;
  if (auto p = parse_catalog(l, catalog)) return p;
  if (catalog != e.catalog_number)
    return l.problem(3, 7, F[1].name, encode_catalog_number(e.catalog_number) + " as on line 1");
  if (auto p = check_blank(l, 8)) return p;
  if (auto p = parse_decimal_field(l, F[2], 0.0, 180.0, true, e.inclination_deg)) return p;
  if (auto p = check_blank(l, 17)) return p;
  if (auto p = parse_decimal_field(l, F[3], 0.0, 360.0, false, e.raan_deg)) return p;
  if (auto p = check_blank(l, 26)) return p;

  // Seven digits after an implied "0."; leading blanks read as zeros (right-aligned digits).
  std::string digits(l.raw(27, 33));
  const auto first_digit = digits.find_first_not_of(' ');
  if (first_digit != std::string::npos) std::fill_n(digits.begin(), first_digit, '0');
  if (!all_digits(digits)) return l.problem(27, 33, F[4].name, "7 digits (implied leading decimal point)");
  e.eccentricity = *whole_double("0." + digits, std::chars_format::fixed);
  if (auto p = check_blank(l, 34)) return p;

  if (auto p = parse_decimal_field(l, F[5], 0.0, 360.0, false, e.arg_perigee_deg)) return p;
  if (auto p = check_blank(l, 43)) return p;
  if (auto p = parse_decimal_field(l, F[6], 0.0, 360.0, false, e.mean_anomaly_deg)) return p;
  if (auto p = check_blank(l, 52)) return p;
  const auto n = parse_fixed(l.raw(53, 63));
  if (!n) return l.problem(53, 63, F[7].name, "decimal number");
  if (!(*n > 0.0)) return l.problem(53, 63, F[7].name, "number > 0");
  e.mean_motion_rev_per_day = *n;
  if (auto p = parse_count_field(l, F[8], e.revolution_number)) return p;

  if (options.verify_checksums) return check_checksum(l);
  return std::nullopt;
}

enum class LineKind { skip, name, line1, line2 };

LineKind classify(std::string_view line) {
  const std::string_view t = trim_left(line);
  if (t.empty() || t.front() == '#') return LineKind::skip;
  if (line.size() == 1 || line[1] == ' ') {
    if (line[0] == '1') return LineKind::line1;
    if (line[0] == '2') return LineKind::line2;
  }
  return LineKind::name;
}

std::string name_from_line(std::string_view line) {
  line = trim(line);
  if (line.starts_with("0 ")) line = trim(line.substr(2));  // Space-Track's three-line form
  return std::string(line);
}

// The line as quoted in a problem: trailing blanks removed, at most the 69 columns of the format.
std::string quote_line(std::string_view line) { return std::string(trim_right(line.substr(0, 69))); }

}  // namespace

// ---------------------------------------------------------------------------------------------
// Small public pieces

std::string Elements::label() const { return name.empty() ? std::to_string(catalog_number) : name; }

std::string ParseProblem::message() const {
  std::string m = file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + field + ": found ";
  m += found.empty() ? std::string("nothing") : "'" + found + "'";
  m += ", expected " + expected;
  if (warning) m += " (warning: set accepted)";
  return m;
}

bool ParseResult::ok() const {
  return std::none_of(problems.begin(), problems.end(), [](const ParseProblem& p) { return !p.warning; });
}

int nasa_checksum(std::string_view line) {
  int sum = 0;
  for (const char c : line.substr(0, 68)) {
    if (is_digit(c)) sum += c - '0';
    else if (c == '-') sum += 1;
  }
  return sum % 10;
}

namespace {
constexpr std::string_view kAlpha5Letters = "ABCDEFGHJKLMNPQRSTUVWXYZ";  // A=10 ... Z=33
}

int decode_catalog_number(std::string_view s) {
  if (s.size() != 5) return -1;
  if (is_upper(s[0])) {
    const auto letter = kAlpha5Letters.find(s[0]);
    if (letter == std::string_view::npos || !all_digits(s.substr(1))) return -1;
    return static_cast<int>(letter + 10) * 10000 + static_cast<int>(*parse_unsigned(s.substr(1)));
  }
  const std::string_view digits = trim_left(s);  // leading blanks: an unpadded number
  if (!all_digits(digits)) return -1;
  return static_cast<int>(*parse_unsigned(digits));
}

std::string encode_catalog_number(int number) {
  char buf[16];
  if (number >= 0 && number <= 99999) {
    std::snprintf(buf, sizeof buf, "%05d", number);
  } else if (number >= 100000 && number <= 339999) {
    std::snprintf(buf, sizeof buf, "%c%04d", kAlpha5Letters[static_cast<std::size_t>(number / 10000 - 10)],
                  number % 10000);
  } else {
    return {};
  }
  return buf;
}

// ---------------------------------------------------------------------------------------------
// NASA parser

ParseResult parse_nasa(std::string_view text, std::string_view file_name, const ParseOptions& options) {
  ParseResult result;
  const std::vector<TextLine> lines = split_lines(text);
  const std::size_t n = lines.size();
  auto next_significant = [&](std::size_t i) {
    while (i < n && classify(lines[i].text) == LineKind::skip) ++i;
    return i;
  };
  auto kind_at = [&](std::size_t i) { return i < n ? classify(lines[i].text) : LineKind::skip; };
  auto element_line = [&](std::size_t i) { return ElementLine{lines[i].text, lines[i].number, 0, file_name}; };

  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::size_t name_index = kNone;  // the text line just before, a candidate name
  for (std::size_t i = next_significant(0); i < n; i = next_significant(i)) {
    const TextLine& line = lines[i];
    switch (classify(line.text)) {
      case LineKind::skip:  // not reached: next_significant() passes over these
        ++i;
        break;
      case LineKind::name:
        name_index = i;  // a text line not followed by line 1 is simply replaced (bulletin text)
        ++i;
        break;
      case LineKind::line2: {
        // Line 2 without line 1. When line 1 of the same satellite follows and is not itself
        // followed by a line 2, the two were swapped: one problem for the pair.
        const std::size_t j = next_significant(i + 1);
        const bool swapped = kind_at(j) == LineKind::line1 && kind_at(next_significant(j + 1)) != LineKind::line2 &&
                             element_line(i).raw(3, 7) == element_line(j).raw(3, 7);
        result.problems.push_back(make_problem(file_name, line.number, 1, "line 1", quote_line(line.text),
                                               "line 1 before line 2"));
        i = swapped ? j + 1 : i + 1;
        name_index = kNone;
        break;
      }
      case LineKind::line1: {
        Elements e;
        e.source = ElementFormat::nasa;
        if (name_index != kNone) e.name = name_from_line(lines[name_index].text);
        name_index = kNone;
        const std::size_t j = next_significant(i + 1);
        const bool has_line2 = kind_at(j) == LineKind::line2;
        std::optional<ParseProblem> problem = parse_line1(element_line(i), options, e);
        if (!problem && !has_line2) {
          if (j < n) {
            problem = make_problem(file_name, lines[j].number, 1, "line 2", quote_line(lines[j].text),
                                   "line 2 after line 1");
          } else {
            problem = make_problem(file_name, line.number + 1, 1, "line 2", "", "line 2 after line 1");
          }
        }
        if (!problem) problem = parse_line2(element_line(j), options, e);
        if (problem) result.problems.push_back(std::move(*problem));
        else result.sets.push_back(std::move(e));
        i = has_line2 ? j + 1 : i + 1;
        break;
      }
    }
  }
  return result;
}

// ---------------------------------------------------------------------------------------------
// AMSAT verbose format

int amsat_checksum(const std::vector<std::string_view>& lines) {
  int sum = 0;
  for (const std::string_view line : lines) {
    for (const char c : line) {
      if (is_digit(c)) sum += c - '0';
      else if (c == '-') sum += 1;
      else if (c == '+') sum += 2;
    }
  }
  return sum;
}

namespace {

enum AmsatField {
  kSatellite, kCatalog, kEpochTime, kElementSet, kInclination, kRaan, kEccentricity, kArgPerigee,
  kMeanAnomaly, kMeanMotion, kDecayRate, kEpochRev, kChecksum, kAmsatFieldCount
};

// Labels as the format writes them; matched without regard to case or runs of blanks.
constexpr const char* kAmsatLabels[kAmsatFieldCount] = {
    "Satellite",      "Catalog number", "Epoch time",  "Element set", "Inclination", "RA of node", "Eccentricity",
    "Arg of perigee", "Mean anomaly",   "Mean motion", "Decay rate",  "Epoch rev",   "Checksum",
};

// "Label: value" -> the label folded to lower case with single blanks, and where the value starts.
struct LabelledLine {
  std::string label;                         // empty when the line has no colon
  std::size_t value_begin = 0;               // index of the first character after the blanks
};

LabelledLine split_label(std::string_view line) {
  LabelledLine out;
  const auto colon = line.find(':');
  if (colon == std::string_view::npos) return out;
  for (const char c : trim(line.substr(0, colon))) {
    if (is_space(c)) {
      if (!out.label.empty() && out.label.back() != ' ') out.label += ' ';
    } else {
      out.label += to_lower(c);
    }
  }
  std::size_t v = colon + 1;
  while (v < line.size() && is_space(line[v])) ++v;
  out.value_begin = v;
  if (out.label.empty()) out.label = " ";  // a colon without a label: still a labelled line
  return out;
}

int amsat_field_of(const std::string& label) {
  for (int f = 0; f < kAmsatFieldCount; ++f) {
    std::string folded;
    for (const char* c = kAmsatLabels[f]; *c; ++c) folded += to_lower(*c);
    if (folded == label) return f;
  }
  return -1;
}

struct AmsatValue {
  bool present = false;
  std::size_t index = 0;   // into the line list
  int line = 0;
  int column = 0;          // 1-based column of the value
  std::string_view token;  // the value up to the first blank (units follow)
  std::string_view rest;   // everything after the colon, trimmed (names have blanks)
};

class AmsatBlock {
 public:
  AmsatBlock(const std::vector<TextLine>& lines, std::size_t start, std::string_view file, const ParseOptions& options)
      : lines_(lines), start_(start), file_(file), options_(options) {}

  // Records a labelled line of the block; false when it is the second line with that label.
  void add(int field, std::size_t index, const LabelledLine& l) {
    AmsatValue& v = values_[field];
    const std::string_view text = lines_[index].text;
    std::string_view value = l.value_begin < text.size() ? text.substr(l.value_begin) : std::string_view{};
    const auto blank = value.find_first_of(" \t");
    AmsatValue nv{true, index, lines_[index].number, static_cast<int>(l.value_begin) + 1,
                  value.substr(0, blank), trim(value)};
    if (v.present) {
      if (!duplicate_) {
        duplicate_ = make_problem(file_, nv.line, nv.column, kAmsatLabels[field], std::string(nv.token),
                                  std::string("one '") + kAmsatLabels[field] + ":' line in the block");
      }
      return;
    }
    v = nv;
  }

  // Appends the set or the problems to the result.
  void finish(ParseResult& result) {
    Elements e;
    if (auto p = decode(e)) {
      result.problems.push_back(std::move(*p));
      return;
    }
    // The checksum: digits of the lines from "Satellite:" to "Epoch rev:", '-' 1, '+' 2.
    std::vector<std::string_view> summed;
    for (std::size_t i = start_; i <= values_[kEpochRev].index; ++i) summed.push_back(lines_[i].text);
    const int sum = amsat_checksum(summed);
    const AmsatValue& c = values_[kChecksum];
    std::optional<ParseProblem> checksum_problem;
    if (!c.present) {
      checksum_problem = make_problem(file_, lines_[start_].number, 0, kAmsatLabels[kChecksum], "",
                                      "a 'Checksum:' line (" + std::to_string(sum) + " for this block)");
    } else if (const auto given = parse_unsigned(c.token); !given || *given != sum) {
      checksum_problem = make_problem(file_, c.line, c.column, kAmsatLabels[kChecksum], std::string(c.token),
                                      "checksum " + std::to_string(sum));
    }
    if (checksum_problem) {
      // Strict (a serial upload) rejects a wrong checksum; a block without a "Checksum:" line, which
      // the TrakBox manual never mentions, is accepted with a warning either way.
      const bool reject = options_.strict_amsat_checksum && c.present;
      checksum_problem->warning = !reject;
      result.problems.push_back(std::move(*checksum_problem));
      if (reject) return;
    }
    result.sets.push_back(std::move(e));
  }

 private:
  ParseProblem problem(int field, std::string expected) const {
    const AmsatValue& v = values_[field];
    return make_problem(file_, v.line, v.column, kAmsatLabels[field], std::string(v.token), std::move(expected));
  }

  std::optional<ParseProblem> number(int field, double low, double high, bool high_inclusive, double& out) const {
    const auto v = parse_general(values_[field].token);
    if (!v) return problem(field, "decimal number");
    if (*v < low || *v > high || (!high_inclusive && *v == high)) {
      char range[64];
      std::snprintf(range, sizeof range, "number in [%g, %g%c", low, high, high_inclusive ? ']' : ')');
      return problem(field, range);
    }
    out = *v;
    return std::nullopt;
  }

  std::optional<ParseProblem> count(int field, long& out) const {
    const auto v = parse_unsigned(values_[field].token);
    if (!v) return problem(field, "digits 0-9");
    out = *v;
    return std::nullopt;
  }

  std::optional<ParseProblem> decode(Elements& e) const {
    for (int f = kCatalog; f <= kEpochRev; ++f) {
      if (!values_[f].present) {
        return make_problem(file_, lines_[start_].number, 0, kAmsatLabels[f], "",
                            std::string("a '") + kAmsatLabels[f] + ":' line in the block");
      }
    }
    if (duplicate_) return duplicate_;

    e.source = ElementFormat::amsat;
    e.name = std::string(values_[kSatellite].rest);

    const std::string_view catalog = values_[kCatalog].token;
    if (const auto digits = parse_unsigned(catalog)) e.catalog_number = static_cast<int>(*digits);
    else e.catalog_number = decode_catalog_number(catalog);
    if (e.catalog_number < 0) return problem(kCatalog, "digits or Alpha-5 (letter A-Z without I and O, 4 digits)");

    // YYDDD.DDDDDDDD; leading zeros of the year may have been dropped by a generator.
    const std::string_view epoch = values_[kEpochTime].token;
    const auto point = epoch.find('.');
    const std::string_view whole = epoch.substr(0, point);
    const std::string_view fraction = point == std::string_view::npos ? std::string_view{} : epoch.substr(point + 1);
    if (!all_digits(whole) || whole.size() > 5 || (!fraction.empty() && !all_digits(fraction)))
      return problem(kEpochTime, "YYDDD.DDDDDDDD");
    const long yyddd = *parse_unsigned(whole);
    e.epoch_year = expand_two_digit_year(static_cast<int>(yyddd / 1000));
    const std::string day_text = std::to_string(yyddd % 1000) + "." + (fraction.empty() ? "0" : std::string(fraction));
    e.epoch_day = *whole_double(day_text, std::chars_format::fixed);
    const double day_limit = is_leap_year(e.epoch_year) ? 367.0 : 366.0;
    if (e.epoch_day < 1.0 || e.epoch_day >= day_limit)
      return problem(kEpochTime, "day of year in [1, " + std::to_string(int(day_limit)) + ")");

    long element_set = 0;
    if (auto p = count(kElementSet, element_set)) return p;
    e.element_set_number = static_cast<int>(element_set);
    if (auto p = number(kInclination, 0.0, 180.0, true, e.inclination_deg)) return p;
    if (auto p = number(kRaan, 0.0, 360.0, false, e.raan_deg)) return p;
    if (auto p = number(kEccentricity, 0.0, 1.0, false, e.eccentricity)) return p;
    if (auto p = number(kArgPerigee, 0.0, 360.0, false, e.arg_perigee_deg)) return p;
    if (auto p = number(kMeanAnomaly, 0.0, 360.0, false, e.mean_anomaly_deg)) return p;
    const auto n = parse_general(values_[kMeanMotion].token);
    if (!n) return problem(kMeanMotion, "decimal number");
    if (!(*n > 0.0)) return problem(kMeanMotion, "number > 0");
    e.mean_motion_rev_per_day = *n;
    const auto decay = parse_general(values_[kDecayRate].token);
    if (!decay) return problem(kDecayRate, "decimal number such as -4.5e-07");
    e.ndot_over_2 = *decay;
    if (auto p = count(kEpochRev, e.revolution_number)) return p;
    return std::nullopt;
  }

  const std::vector<TextLine>& lines_;
  std::size_t start_;
  std::string_view file_;
  const ParseOptions& options_;
  AmsatValue values_[kAmsatFieldCount];
  std::optional<ParseProblem> duplicate_;
};

}  // namespace

ParseResult parse_amsat(std::string_view text, std::string_view file_name, const ParseOptions& options) {
  ParseResult result;
  const std::vector<TextLine> lines = split_lines(text);
  std::unique_ptr<AmsatBlock> block;  // the block being read
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string_view line = lines[i].text;
    const LabelledLine l = is_blank(line) ? LabelledLine{} : split_label(line);
    const int field = l.label.empty() ? -1 : amsat_field_of(l.label);
    if (block) {
      // A block ends at a blank line, a line without a colon (free text, "/EX"), the next
      // "Satellite:" or after its "Checksum:". Other labelled lines ("Beacon:") are ignored.
      if (l.label.empty() || field == kSatellite) {
        block->finish(result);
        block.reset();
      } else {
        if (field >= 0) block->add(field, i, l);
        if (field == kChecksum) {
          block->finish(result);
          block.reset();
        }
        continue;
      }
    }
    if (field == kSatellite) {
      block = std::make_unique<AmsatBlock>(lines, i, file_name, options);
      block->add(kSatellite, i, l);
    }
  }
  if (block) block->finish(result);
  return result;
}

// ---------------------------------------------------------------------------------------------
// gpredict satdata

namespace {

struct GpredictSection {
  int header_line = 0;  // 0: keys before any [section]
  std::string title;
  std::string name;
  std::optional<ElementLine> tle[2];
};

void finish_section(const GpredictSection& s, std::string_view file, const ParseOptions& options, ParseResult& result) {
  static constexpr const char* kKeys[2] = {"TLE1", "TLE2"};
  for (int k = 0; k < 2; ++k) {
    if (!s.tle[k]) {
      result.problems.push_back(make_problem(file, s.header_line, 0, kKeys[k], "",
                                             std::string("a ") + kKeys[k] + "= line in section [" + s.title + "]"));
      return;
    }
  }
  Elements e;
  e.source = ElementFormat::nasa;
  e.name = s.name;
  std::optional<ParseProblem> problem = parse_line1(*s.tle[0], options, e);
  if (!problem) problem = parse_line2(*s.tle[1], options, e);
  if (problem) result.problems.push_back(std::move(*problem));
  else result.sets.push_back(std::move(e));
}

}  // namespace

ParseResult parse_gpredict_satdata(std::string_view text, std::string_view file_name, const ParseOptions& options) {
  ParseResult result;
  std::optional<GpredictSection> section;
  for (const TextLine& line : split_lines(text)) {
    const std::string_view t = trim(line.text);
    if (t.empty() || t.front() == '#' || t.front() == ';') continue;
    if (t.front() == '[') {
      if (section) finish_section(*section, file_name, options, result);
      section.emplace();
      section->header_line = line.number;
      section->title = std::string(trim(t.substr(1, t.size() - (t.back() == ']' ? 2 : 1))));
      continue;
    }
    const auto equals = line.text.find('=');
    if (equals == std::string_view::npos) {
      result.problems.push_back(make_problem(file_name, line.number, 1, "line", std::string(t),
                                             "[section], KEY=value, comment or blank line", true));
      continue;
    }
    if (!section) section.emplace();  // keys before any section: read them as one
    const std::string_view key = trim(line.text.substr(0, equals));
    std::size_t value_begin = equals + 1;
    while (value_begin < line.text.size() && is_space(line.text[value_begin])) ++value_begin;
    const std::string_view value = line.text.substr(value_begin);
    if (key == "NAME") {
      section->name = std::string(trim(value));
    } else if (key == "TLE1" || key == "TLE2") {
      section->tle[key == "TLE1" ? 0 : 1] =
          ElementLine{value, line.number, static_cast<int>(value_begin), file_name};
    }
  }
  if (section) finish_section(*section, file_name, options, result);
  return result;
}

// ---------------------------------------------------------------------------------------------
// Writers

namespace {

std::string printf_string(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string printf_string(const char* format, ...) {
  char buf[128];
  va_list args;
  va_start(args, format);
  const int n = std::vsnprintf(buf, sizeof buf, format, args);
  va_end(args);
  return n < 0 ? std::string() : std::string(buf, std::min<std::size_t>(static_cast<std::size_t>(n), sizeof buf - 1));
}

// Right-aligned fixed-point text of exactly `width` columns, with as many of `decimals` decimals
// as fit; '*' when even no decimal fits (a value no element set can hold).
std::string fixed_columns(double v, int width, int decimals) {
  for (int d = decimals; d >= 0; --d) {
    std::string t = printf_string("%*.*f", width, d, v);
    if (static_cast<int>(t.size()) <= width) return t;
  }
  return std::string(static_cast<std::size_t>(width), '*');
}

// An angle in [0, 360) in columns "ddd.dddd": a value that rounds up to 360 is written as 0.
std::string angle_columns(double deg) {
  std::string t = fixed_columns(deg, 8, 4);
  return t == "360.0000" ? "  0.0000" : t;
}

// ndot/2 in 10 columns: sign or blank, then the number without its leading zero (".00002182").
std::string ndot_columns(double v) {
  const char sign = std::signbit(v) ? '-' : ' ';
  for (int d = 8; d >= 0; --d) {
    std::string t = printf_string("%.*f", d, std::fabs(v));
    if (t.starts_with("0.")) t.erase(0, 1);
    if (t.size() <= 9) return sign + std::string(9 - t.size(), ' ') + t;
  }
  return std::string(10, '*');
}

// The implied-decimal exponent field, 8 columns: "-11606-4" for -0.11606e-4. Zero is " 00000-0".
std::string implied_exponent_columns(double v) {
  const std::string sign(1, std::signbit(v) ? '-' : ' ');
  const double a = std::fabs(v);
  if (a == 0.0) return sign + "00000-0";
  const std::string e = printf_string("%.4e", a);  // d.dddde+XX, correctly rounded
  const int exponent = std::atoi(e.c_str() + 7) + 1;
  if (exponent > 9) return sign + "99999+9";  // beyond the field: the largest it holds
  if (exponent < -9) {                         // below 0.1e-9: leading zeros in the mantissa
    const long long m = std::llround(a * 1e14);
    return m == 0 ? sign + "00000-0" : sign + printf_string("%05lld", m) + "-9";
  }
  return sign + e.substr(0, 1) + e.substr(2, 4) + (exponent < 0 ? '-' : '+') +
         static_cast<char>('0' + std::abs(exponent));
}

// Fixed-point text with at least `decimals` decimals, more when needed to give back the value.
std::string round_trip_fixed(double v, int decimals) {
  std::string t = printf_string("%.*f", decimals, v);
  if (parse_fixed(t) == v) return t;
  char buf[400];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed);
  return ec == std::errc() ? std::string(buf, end) : t;
}

// Shortest scientific text that gives back the value, in the AMSAT style "-4.5e-07".
std::string decay_rate_text(double v) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
  std::string t(buf, end);
  if (t.find('.') == std::string::npos) t.insert(t.find('e'), ".0");
  return t;
}

// "YYDDD.DDDDDDDD" (also columns 19-32 of line 1).
std::string epoch_text(int year, double day, bool round_trip) {
  std::string d = printf_string("%012.8f", day);
  if (round_trip && parse_fixed(d) != day) {
    d = round_trip_fixed(day, 8);
    const auto point = d.find('.');
    if (point != std::string::npos && point < 3) d.insert(0, 3 - point, '0');
  }
  return printf_string("%02d", ((year % 100) + 100) % 100) + d;
}

// A name the NASA parser would take for something else gets Space-Track's "0 " prefix.
std::string name_line(const std::string& name) {
  if (classify(name) != LineKind::name || name.starts_with("0 ")) return "0 " + name;
  return name;
}

}  // namespace

std::string format_nasa(const Elements& e, bool with_name) {
  std::string catalog = encode_catalog_number(e.catalog_number);
  if (catalog.empty()) catalog = "*****";  // not representable: the output will not parse

  std::string l1 = "1 " + catalog;
  l1 += is_upper(e.classification) ? e.classification : 'U';
  l1 += ' ';
  std::string designator = e.international_designator.substr(0, 8);
  designator.resize(8, ' ');
  l1 += designator + ' ';
  std::string epoch = epoch_text(e.epoch_year, e.epoch_day, false);
  if (epoch.size() != 14) epoch = std::string(14, '*');
  l1 += epoch + ' ';
  l1 += ndot_columns(e.ndot_over_2) + ' ';
  l1 += implied_exponent_columns(e.nddot_over_6) + ' ';
  l1 += implied_exponent_columns(e.bstar) + ' ';
  l1 += static_cast<char>(e.ephemeris_type >= 0 && e.ephemeris_type <= 9 ? '0' + e.ephemeris_type : '0');
  l1 += ' ';
  l1 += printf_string("%4d", e.element_set_number >= 0 ? e.element_set_number % 10000 : 0);
  l1 += static_cast<char>('0' + nasa_checksum(l1));

  std::string l2 = "2 " + catalog + ' ';
  l2 += fixed_columns(e.inclination_deg, 8, 4) + ' ';
  l2 += angle_columns(e.raan_deg) + ' ';
  const std::string ecc = printf_string("%.7f", std::clamp(e.eccentricity, 0.0, 0.9999999));
  l2 += ecc.substr(2, 7) + ' ';
  l2 += angle_columns(e.arg_perigee_deg) + ' ';
  l2 += angle_columns(e.mean_anomaly_deg) + ' ';
  l2 += fixed_columns(e.mean_motion_rev_per_day, 11, 8);
  l2 += printf_string("%5ld", e.revolution_number >= 0 ? e.revolution_number % 100000 : 0L);
  l2 += static_cast<char>('0' + nasa_checksum(l2));

  std::string out;
  if (with_name && !e.name.empty()) out += name_line(e.name) + "\n";
  return out + l1 + "\n" + l2 + "\n";
}

std::string format_amsat(const Elements& e) {
  // The layout AMSAT's bulletins use: four values left-aligned at column 17/18, the others
  // right-aligned to end at column 26, then the unit.
  auto right = [](const char* label, const std::string& value, const char* unit) {
    std::string line = std::string(label) + ":";
    const std::size_t used = line.size() + value.size();
    line += std::string(used < 26 ? 26 - used : 1, ' ') + value;
    if (*unit) line += std::string(" ") + unit;
    return line;
  };
  std::vector<std::string> lines;
  lines.push_back(e.name.empty() ? "Satellite:" : "Satellite: " + e.name);
  lines.push_back("Catalog number: " + (e.catalog_number >= 0 && e.catalog_number <= 99999
                                            ? printf_string("%05d", e.catalog_number)
                                            : std::to_string(e.catalog_number)));
  lines.push_back("Epoch time:      " + epoch_text(e.epoch_year, e.epoch_day, true));
  lines.push_back("Element set:     " + std::to_string(e.element_set_number));
  lines.push_back(right("Inclination", round_trip_fixed(e.inclination_deg, 4), "deg"));
  lines.push_back(right("RA of node", round_trip_fixed(e.raan_deg, 4), "deg"));
  lines.push_back(right("Eccentricity", round_trip_fixed(e.eccentricity, 7), ""));
  lines.push_back(right("Arg of perigee", round_trip_fixed(e.arg_perigee_deg, 4), "deg"));
  lines.push_back(right("Mean anomaly", round_trip_fixed(e.mean_anomaly_deg, 4), "deg"));
  lines.push_back(right("Mean motion", round_trip_fixed(e.mean_motion_rev_per_day, 8), "rev/day"));
  lines.push_back(right("Decay rate", decay_rate_text(e.ndot_over_2), "rev/day^2"));
  lines.push_back(right("Epoch rev", std::to_string(e.revolution_number), ""));
  const std::vector<std::string_view> summed(lines.begin(), lines.end());
  lines.push_back(right("Checksum", std::to_string(amsat_checksum(summed)), ""));
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

// ---------------------------------------------------------------------------------------------
// Detection and files

namespace {
enum class Detected { nasa, amsat, gpredict };

Detected detect(std::string_view text) {
  for (const TextLine& l : split_lines(text)) {
    const std::string_view t = trim_left(l.text);
    if (t.empty() || t.front() == '#') continue;
    if (t.starts_with("TLE1=") || t.starts_with("TLE1 =")) return Detected::gpredict;
    const LabelledLine label = split_label(t);
    if (!label.label.empty() && amsat_field_of(label.label) == kSatellite) return Detected::amsat;
  }
  return Detected::nasa;
}
}  // namespace

ParseResult parse_elements(std::string_view text, std::string_view file_name, const ParseOptions& options) {
  switch (detect(text)) {
    case Detected::amsat:
      return parse_amsat(text, file_name, options);
    case Detected::gpredict:
      return parse_gpredict_satdata(text, file_name, options);
    case Detected::nasa:
      break;
  }
  return parse_nasa(text, file_name, options);
}

ParseResult load_elements_file(const std::string& path, const ParseOptions& options) {
  std::string text;
  int error = 0;
  errno = 0;
  if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
    char buf[65536];
    std::size_t got = 0;
    while ((got = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, got);
    if (std::ferror(f)) error = errno ? errno : EIO;  // e.g. EISDIR for a folder
    std::fclose(f);
  } else {
    error = errno ? errno : ENOENT;
  }
  if (error) {
    ParseResult r;
    r.problems.push_back(make_problem(path, 0, 0, "file", std::strerror(error), "a readable file of element sets"));
    return r;
  }
  return parse_elements(text, path, options);
}

}  // namespace tb::orbit
