#pragma once
// Text from outside (element names and files, gpsd, clients of the station's socket) made safe at
// the boundary where it enters, the one copy (issue 38): whatever trakbox keeps of it may go to a
// terminal and into JSON as it is.
//
//   safe_text(s): valid UTF-8 with no control character. What is not well-formed UTF-8 (a stray
//   continuation byte, a sequence cut short, an overlong form, a surrogate U+D800..U+DFFF, anything
//   above U+10FFFF, the bytes C0 C1 F5..FF) becomes U+FFFD (EF BF BD), one for each maximal ill-formed
//   subpart as Unicode recommends (Python's bytes.decode("utf-8", "replace") gives the same); each
//   control character -- C0 (U+0000..
//   U+001F, tab included), DEL (U+007F) and C1 (U+0080..U+009F, which some terminals obey as ESC [
//   and friends) -- becomes U+FFFD as well. Everything else is kept byte for byte: safe_text of
//   printable UTF-8 is the same string.
//   is_safe_text(s): safe_text(s) == s, without building it.
//   visible_bytes(s): for a message that shows what the outside sent: printable ASCII kept (a
//   backslash doubled), every other byte as \xHH. "IS\xff\xfeS" -> "IS\\xff\\xfeS".
#include <cstddef>
#include <string>
#include <string_view>

namespace tb::text {

namespace detail {
// The length of the well-formed UTF-8 sequence at s[i] and its code point, or 0 when s[i] does not
// begin one (Unicode 15, table 3-7); then `bad` is the length of the ill-formed part to replace by
// one U+FFFD: the maximal subpart (the lead byte and the continuation bytes that were still right),
// at least 1 -- Unicode's recommended practice, which Python's decode(errors="replace") follows.
inline std::size_t utf8_sequence(std::string_view s, std::size_t i, char32_t& cp, std::size_t& bad) {
  bad = 1;
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  if (c < 0x80) {
    cp = c;
    return 1;
  }
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
    cp = c & 0x1Fu;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    cp = c & 0x0Fu;
    if (c == 0xE0) lo = 0xA0;  // no overlong forms
    if (c == 0xED) hi = 0x9F;  // no surrogates
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    cp = c & 0x07u;
    if (c == 0xF0) lo = 0x90;  // no overlong forms
    if (c == 0xF4) hi = 0x8F;  // nothing above U+10FFFF
  } else {
    return 0;
  }
  for (std::size_t k = 1; k < n; ++k) {
    if (i + k >= s.size()) return 0;
    const unsigned char t = b(i + k);
    if (t < (k == 1 ? lo : 0x80) || t > (k == 1 ? hi : 0xBF)) return 0;
    cp = (cp << 6) | (t & 0x3Fu);
    bad = k + 1;
  }
  return n;
}
constexpr bool is_control(char32_t cp) { return cp < 0x20 || (cp >= 0x7F && cp <= 0x9F); }
}  // namespace detail

inline constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD

inline std::string safe_text(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    char32_t cp = 0;
    std::size_t bad = 1;
    const std::size_t n = detail::utf8_sequence(s, i, cp, bad);
    if (n == 0 || detail::is_control(cp)) {
      out.append(kReplacement);
      i += n == 0 ? bad : n;
      continue;
    }
    out.append(s.substr(i, n));
    i += n;
  }
  return out;
}

inline bool is_safe_text(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    char32_t cp = 0;
    std::size_t bad = 1;
    const std::size_t n = detail::utf8_sequence(s, i, cp, bad);
    if (n == 0 || detail::is_control(cp)) return false;
    i += n;
  }
  return true;
}

inline std::string visible_bytes(std::string_view s) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\\') {
      out += "\\\\";
    } else if (c >= 0x20 && c < 0x7F) {
      out += ch;
    } else {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 0xF];
    }
  }
  return out;
}

}  // namespace tb::text
