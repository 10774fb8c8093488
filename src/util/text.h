#pragma once
// The small text helpers every parser of outside input needs, written once: trimming, ASCII case,
// splitting, and whole-string number parsing. ASCII only on purpose: element sets, CAT replies,
// Satrak frames and menu answers are ASCII, and the locale must never change what a byte means.
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace tb::text {

inline constexpr std::string_view kBlanks = " \t";                   // what a field's padding is
inline constexpr std::string_view kWhitespace = " \t\r\n\v\f";       // what std::isspace calls space

constexpr bool is_digit(char c) { return c >= '0' && c <= '9'; }
constexpr char to_lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }
constexpr char to_upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }

// s without the characters of `chars` at either end (blanks by default).
constexpr std::string_view trim_left(std::string_view s, std::string_view chars = kBlanks) {
  const auto b = s.find_first_not_of(chars);
  return b == std::string_view::npos ? std::string_view{} : s.substr(b);
}
constexpr std::string_view trim_right(std::string_view s, std::string_view chars = kBlanks) {
  const auto e = s.find_last_not_of(chars);
  return e == std::string_view::npos ? std::string_view{} : s.substr(0, e + 1);
}
constexpr std::string_view trim(std::string_view s, std::string_view chars = kBlanks) {
  return trim_left(trim_right(s, chars), chars);
}

inline std::string lower(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = to_lower(c);
  return r;
}
inline std::string upper(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = to_upper(c);
  return r;
}

constexpr bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (to_lower(a[i]) != to_lower(b[i])) return false;
  return true;
}

// The pieces of s between separators, empty pieces kept: split("a,,b", ',') = {"a", "", "b"};
// split("", ',') = {""}.
inline std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  for (;;) {
    const auto p = s.find(sep);
    out.push_back(s.substr(0, p));
    if (p == std::string_view::npos) return out;
    s.remove_prefix(p + 1);
  }
}

// All of s as a finite number: an optional '+' or '-' sign, then what std::from_chars reads
// (decimal, optional exponent). No blanks, no "inf"/"nan", no hex. Callers trim first if they allow
// blanks around the number.
inline std::optional<double> parse_double(std::string_view s) {
  if (!s.empty() && s.front() == '+') {
    s.remove_prefix(1);
    if (!s.empty() && (s.front() == '+' || s.front() == '-')) return std::nullopt;  // "+-1"
  }
  if (s.empty()) return std::nullopt;
  double v = 0.0;
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || p != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// All of s as an integer of type T: an optional '+' or '-' sign, then decimal digits that fit T.
template <typename T = long long>
std::optional<T> parse_integer(std::string_view s) {
  if (!s.empty() && s.front() == '+') {
    s.remove_prefix(1);
    if (!s.empty() && (s.front() == '+' || s.front() == '-')) return std::nullopt;  // "+-1"
  }
  if (s.empty()) return std::nullopt;
  T v{};
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || p != s.data() + s.size()) return std::nullopt;
  return v;
}

// Appends `value` as printf's "%W.Pf" would write it (right-aligned in `width` columns, `precision`
// decimals), without printf: std::to_chars is specified to give printf's characters in the C
// locale (exact value, rounded to nearest), so output does not change, only its cost (the
// propagate command writes seven numbers per line).
inline void append_fixed(std::string& out, double value, int width, int precision) {
  char buf[400];  // DBL_MAX has 309 integer digits; with a sign, the point and 40 decimals it fits
  const auto r = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed, precision);
  const std::size_t n = r.ec == std::errc() ? static_cast<std::size_t>(r.ptr - buf) : 0;
  if (static_cast<int>(n) < width) out.append(static_cast<std::size_t>(width) - n, ' ');
  out.append(buf, n);
}

}  // namespace tb::text
