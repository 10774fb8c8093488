#pragma once
// The small text helpers every parser of outside input needs, written once: trimming, ASCII case,
// splitting, and whole-string number parsing. ASCII only on purpose: element sets, CAT replies,
// Satrak frames and menu answers are ASCII, and the locale must never change what a byte means.
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
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

// trim() as a string of its own (what a prompt's answer is kept as), any white space taken off.
inline std::string trimmed(std::string_view s, std::string_view chars = kWhitespace) {
  return std::string(trim(s, chars));
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
namespace detail {
// printf's %.Pf of a finite |value| < 2^53 with P <= 9, into buf (sign, integer part, point, P
// decimals); the number of characters, or 0 when the value is outside that range. The binary value
// is m 2^e exactly; its integer part is m >> -e and its fraction f / 2^-e, so the decimals are
// f 10^P / 2^-e rounded half to even, as glibc rounds the exact value: one 128-bit product and a
// shift, where to_chars runs its general algorithm (a quarter of the time of `propagate`).
inline std::size_t fixed_small(char* buf, double value, int precision) {
  static constexpr std::uint64_t kPow10[] = {1,      10,      100,      1000,      10000,
                                             100000, 1000000, 10000000, 100000000, 1000000000};
  if (precision < 0 || precision > 9 || !(std::fabs(value) < 0x1p53)) return 0;  // also NaN
  const auto bits = std::bit_cast<std::uint64_t>(value);
  const bool negative = bits >> 63;
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  const std::uint64_t fraction_bits = bits & ((std::uint64_t{1} << 52) - 1);
  const std::uint64_t m = biased == 0 ? fraction_bits : fraction_bits | (std::uint64_t{1} << 52);
  const int shift = (biased == 0 ? 1 : biased) - 1075;  // value = m 2^shift; shift <= 0 below 2^53
  const std::uint64_t scale = kPow10[precision];
  std::uint64_t whole = 0, decimals = 0;
  if (shift >= 0) {
    whole = m << shift;
  } else {
    const int s = -shift;
    whole = s < 64 ? m >> s : 0;
    const std::uint64_t f = s < 64 ? m & ((std::uint64_t{1} << s) - 1) : m;  // fraction f / 2^s
    if (s < 128) {
      using U128 = unsigned __int128;
      const U128 x = static_cast<U128>(f) * scale;  // < 2^83
      const U128 q = x >> s;
      const U128 rem = x - (q << s);
      const U128 half = U128{1} << (s - 1);
      const bool odd = precision == 0 ? (whole & 1) != 0 : (q & 1) != 0;  // the last digit printed
      decimals = static_cast<std::uint64_t>(q) + ((rem > half || (rem == half && odd)) ? 1 : 0);
    }  // else the fraction is below 2^-44 of a unit of the last decimal: it rounds to 0
    if (decimals == scale) {  // rounded up into the next whole number
      decimals = 0;
      ++whole;
    }
  }
  char* p = buf;
  if (negative) *p++ = '-';  // printf keeps the sign of a negative value that rounds to zero
  p = std::to_chars(p, p + 20, whole).ptr;
  if (precision > 0) {
    *p++ = '.';
    for (int k = precision - 1; k >= 0; --k) {
      p[k] = static_cast<char>('0' + decimals % 10);
      decimals /= 10;
    }
    p += precision;
  }
  return static_cast<std::size_t>(p - buf);
}
}  // namespace detail

inline void append_fixed(std::string& out, double value, int width, int precision) {
  char buf[400];  // DBL_MAX has 309 integer digits; with a sign, the point and 40 decimals it fits
  std::size_t n = detail::fixed_small(buf, value, precision);
  if (n == 0) {
    const auto r = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed, precision);
    n = r.ec == std::errc() ? static_cast<std::size_t>(r.ptr - buf) : 0;
  }
  if (static_cast<int>(n) < width) out.append(static_cast<std::size_t>(width) - n, ' ');
  out.append(buf, n);
}

}  // namespace tb::text
