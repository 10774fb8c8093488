// Field parsers and writers shared by the element-set formats (elements_fields.h).
#include "orbit/elements_fields.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <system_error>

namespace tb::orbit::detail {

namespace {
// A UTF-8 byte-order mark opens a file; files joined with `cat` carry one at the start of a line
// inside, where it is as meaningless (a name that began with one would not be the same name).
std::string_view without_bom(std::string_view line) {
  if (line.starts_with("\xEF\xBB\xBF")) line.remove_prefix(3);
  return line;
}
}  // namespace

std::vector<TextLine> split_lines(std::string_view text) {
  if (const auto z = text.find('\x1a'); z != std::string_view::npos) text = text.substr(0, z);
  std::vector<TextLine> lines;
  std::size_t start = 0;
  int number = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c != '\n' && c != '\r') continue;
    lines.push_back({without_bom(text.substr(start, i - start)), number++});
    if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
    start = i + 1;
  }
  if (start < text.size()) lines.push_back({without_bom(text.substr(start)), number});
  return lines;
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
  const auto v = text::parse_double(s);  // s: digits and one point, no sign
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
  const auto v = text::parse_double(s);  // s: checked above, no sign
  if (!v) return std::nullopt;
  return negative ? -*v : *v;
}

// Digits only (blanks around allowed), at most 9 of them.
std::optional<long> parse_unsigned(std::string_view s) {
  s = trim(s);
  if (!all_digits(s) || s.size() > 9) return std::nullopt;
  return text::parse_integer<long>(s);
}

std::optional<std::string> out_of_range(double v, double low, double high, bool high_inclusive) {
  if (!(v < low || v > high || (!high_inclusive && v == high))) return std::nullopt;
  char range[64];
  std::snprintf(range, sizeof range, "number in [%g, %g%c", low, high, high_inclusive ? ']' : ')');
  return std::string(range);
}

ParseProblem make_problem(std::string_view file, int line, int column, std::string field, std::string found,
                          std::string expected, bool warning) {
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

std::string round_trip_fixed(double v, int decimals) {
  std::string t = printf_string("%.*f", decimals, v);
  if (parse_fixed(t) == v) return t;
  char buf[400];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed);
  return ec == std::errc() ? std::string(buf, end) : t;
}

std::string epoch_text(int year, double day, bool round_trip) {
  std::string d = printf_string("%012.8f", day);
  if (round_trip && parse_fixed(d) != day) {
    d = round_trip_fixed(day, 8);
    const auto point = d.find('.');
    if (point != std::string::npos && point < 3) d.insert(0, 3 - point, '0');
  }
  return printf_string("%02d", ((year % 100) + 100) % 100) + d;
}

}  // namespace tb::orbit::detail
