#include "rotator/satrak/frame.h"

namespace tb::satrak {

namespace {

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

}  // namespace

std::uint8_t checksum(std::string_view payload) {
  std::uint8_t x = 0;
  for (char c : payload) x ^= static_cast<std::uint8_t>(c);
  return x;
}

std::string encode(std::string_view payload) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  const std::uint8_t sum = checksum(payload);
  std::string out;
  out.reserve(payload.size() + 6);
  out += '$';
  out += payload;
  out += '*';
  out += kHex[sum >> 4];
  out += kHex[sum & 0x0F];
  out += "\r\n";
  return out;
}

bool decode_line(std::string_view line, Decoded& out) {
  const std::size_t dollar = line.rfind('$');
  if (dollar == std::string_view::npos) return false;
  std::string_view body = line.substr(dollar + 1);
  // Trailing blanks after the checksum (a terminal program's padding) are not part of the frame.
  while (!body.empty() && (body.back() == ' ' || body.back() == '\t')) body.remove_suffix(1);
  out = Decoded{};
  const std::size_t star = body.rfind('*');
  if (star == std::string_view::npos || body.size() - star != 3) {
    out.kind = Decoded::Kind::malformed;
    out.payload = std::string(star == std::string_view::npos ? body : body.substr(0, star));
    return true;
  }
  const std::string_view payload = body.substr(0, star);
  const int hi = hex_value(body[star + 1]);
  const int lo = hex_value(body[star + 2]);
  out.payload = std::string(payload);
  if (hi < 0 || lo < 0) {
    out.kind = Decoded::Kind::malformed;
    return true;
  }
  out.found = static_cast<std::uint8_t>(hi * 16 + lo);
  out.expected = checksum(payload);
  out.kind = out.found == out.expected ? Decoded::Kind::frame : Decoded::Kind::bad_checksum;
  return true;
}

void Decoder::finish_line(std::vector<Decoded>& out) {
  if (!discarding_ && !line_.empty()) {
    Decoded d;
    if (decode_line(line_, d)) out.push_back(std::move(d));
  }
  line_.clear();
  discarding_ = false;
}

void Decoder::feed(std::string_view bytes, std::vector<Decoded>& out) {
  while (!bytes.empty()) {
    // Everything up to the next line end belongs to the current line.
    std::size_t end = 0;
    while (end < bytes.size() && bytes[end] != '\n' && bytes[end] != '\r') ++end;
    const std::string_view piece = bytes.substr(0, end);
    if (!discarding_) {
      if (line_.size() + piece.size() > max_line_) {
        // Report the overflow now (not at a line end that may never come), keep only the start.
        line_.append(piece.substr(0, max_line_ - line_.size()));
        Decoded d;
        d.kind = Decoded::Kind::overlong;
        const std::size_t dollar = line_.rfind('$');
        d.payload = dollar == std::string::npos ? line_ : line_.substr(dollar + 1);
        out.push_back(std::move(d));
        line_.clear();
        discarding_ = true;
      } else {
        line_.append(piece);
      }
    }
    if (end == bytes.size()) break;
    finish_line(out);
    bytes.remove_prefix(end + 1);
  }
}

}  // namespace tb::satrak
