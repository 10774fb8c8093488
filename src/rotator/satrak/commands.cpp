#include "rotator/satrak/commands.h"
#include "util/text.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace tb::satrak {

namespace {

using text::trim;
constexpr char upper(char c) { return text::to_upper(c); }

bool word_char(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
}

std::optional<double> angle_with_hemisphere(std::string_view s, char pos, char neg, double limit) {
  if (s.empty()) return std::nullopt;
  const char last = upper(s.back());
  double sign = 1.0;
  if (last >= 'A' && last <= 'Z') {
    if (last == neg) sign = -1.0;
    else if (last != pos) return std::nullopt;
    s.remove_suffix(1);
    s = trim(s);
    if (!s.empty() && (s.front() == '-' || s.front() == '+')) return std::nullopt;  // "-12N": ambiguous
  }
  const auto v = parse_number(s);
  if (!v || std::abs(*v) > limit) return std::nullopt;
  return sign * *v;
}

}  // namespace

int code(Error e) { return static_cast<int>(e); }

const char* describe(Error e) {
  switch (e) {
    case Error::bad_checksum: return "bad checksum";
    case Error::malformed_frame: return "malformed frame";
    case Error::frame_too_long: return "frame too long";
    case Error::unknown_command: return "unknown command";
    case Error::parameter_count: return "wrong parameter count";
    case Error::bad_value: return "bad value";
    case Error::out_of_range: return "value out of range";
    case Error::not_allowed: return "not allowed in the current state";
    case Error::file_not_found: return "file not found";
    case Error::satellite_not_found: return "satellite not found";
    case Error::invalid_file: return "invalid file";
    case Error::internal: return "internal error";
  }
  return "error";
}

std::optional<Command> parse_payload(std::string_view payload) {
  std::size_t k = 0;
  while (k < payload.size() && payload[k] != '?' && payload[k] != '=') ++k;
  if (k == payload.size()) return std::nullopt;
  const std::string_view word = trim(payload.substr(0, k));
  // No command word is longer, and the unit echoes the word in its refusals: a word with blanks
  // inside (a tab would reach the peer) or of hundreds of letters is not a command.
  if (word.empty() || word.size() > 32) return std::nullopt;
  Command c;
  for (char ch : word) {
    if (!word_char(ch)) return std::nullopt;
    c.word += upper(ch);
  }
  c.kind = payload[k] == '?' ? Kind::query : Kind::request;
  std::string_view rest = payload.substr(k + 1);
  // `DATETIMEG?=,...` (the seed's framing example): a query marker followed by `=`.
  if (c.kind == Kind::query && !rest.empty() && rest.front() == '=') rest.remove_prefix(1);
  rest = trim(rest);
  if (!rest.empty() && rest.front() == ',') rest.remove_prefix(1);
  if (trim(rest).empty()) return c;
  for (;;) {
    const std::size_t comma = rest.find(',');
    c.fields.emplace_back(trim(rest.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  return c;
}

std::string sanitize_word(std::string_view word) {
  std::string out;
  for (char ch : word) {
    if (!word_char(ch)) continue;
    out += upper(ch);
    if (out.size() == 32) break;
  }
  return out;
}

std::string reply_ok(std::string_view head) { return std::string(head) + ",OK"; }

std::string reply_error(std::string_view head, Error e) {
  std::string out(head);
  if (!out.empty()) out += ',';
  out += "ERR," + std::to_string(code(e));
  return out;
}

std::string reply_error(std::string_view head, Error e, std::string_view reason) {
  std::string out = reply_error(head, e);
  std::string why;
  for (char ch : reason) {
    const auto u = static_cast<unsigned char>(ch);
    why += (u < 0x20 || u >= 0x7F || ch == ',' || ch == '*' || ch == '$') ? ' ' : upper(ch);
  }
  if (const std::string_view w = trim(why); !w.empty()) {
    out += ',';
    out += w;
  }
  return out;
}

std::string reply_values(std::string_view head, const std::vector<std::string>& values) {
  std::string out(head);
  for (const auto& v : values) {
    out += ',';
    out += v;
  }
  return out;
}

std::optional<double> parse_number(std::string_view s) {
  if (s.empty() || s.size() > 40) return std::nullopt;
  for (char c : s)
    if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+')) return std::nullopt;  // no exponents, no "inf"
  return text::parse_double(s);
}

std::optional<long long> parse_integer(std::string_view s) {
  if (s.size() > (!s.empty() && s.front() == '+' ? 19u : 18u)) return std::nullopt;
  return text::parse_integer(s);
}

std::optional<double> parse_latitude(std::string_view s) { return angle_with_hemisphere(s, 'N', 'S', 90.0); }
std::optional<double> parse_longitude(std::string_view s) { return angle_with_hemisphere(s, 'E', 'W', 180.0); }

std::string format_fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  // "-0.00" -> "0.00"
  if (s.front() == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

std::string format_latitude(double deg) { return format_fixed(std::abs(deg), 4) + (deg < 0 ? "S" : "N"); }
std::string format_longitude(double deg) { return format_fixed(std::abs(deg), 4) + (deg < 0 ? "W" : "E"); }

}  // namespace tb::satrak
