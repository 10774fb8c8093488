#include "radio/bytes.h"

#include <algorithm>
#include <stdexcept>

namespace tb::radio {

std::uint64_t pow10(int n) {
  std::uint64_t p = 1;
  while (n-- > 0) p *= 10;
  return p;
}

void require_frequency(Hz hz, std::uint64_t limit, const char* what) {
  if (hz < 0 || static_cast<std::uint64_t>(hz) >= limit)
    throw std::invalid_argument(std::string(what) + ": frequency " + std::to_string(hz) +
                                " Hz out of range");
}


std::string to_hex(std::span<const std::uint8_t> bytes) {
  static const char* digits = "0123456789ABCDEF";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    if (i) out.push_back(' ');
    out.push_back(digits[bytes[i] >> 4]);
    out.push_back(digits[bytes[i] & 0x0F]);
  }
  return out;
}

std::optional<Bytes> from_hex(std::string_view text) {
  Bytes out;
  int high = -1;
  for (char c : text) {
    if (c == ' ' || c == '\t') continue;
    int v;
    if (c >= '0' && c <= '9') v = c - '0';
    else if (c >= 'a' && c <= 'f') v = c - 'a' + 10;
    else if (c >= 'A' && c <= 'F') v = c - 'A' + 10;
    else return std::nullopt;
    if (high < 0) {
      high = v;
    } else {
      out.push_back(static_cast<std::uint8_t>(high << 4 | v));
      high = -1;
    }
  }
  if (high >= 0) return std::nullopt;
  return out;
}

Bytes bcd_little_endian(std::uint64_t value, int bytes) {
  Bytes out;
  for (int i = 0; i < bytes; ++i) {
    const int lo = static_cast<int>(value % 10);
    value /= 10;
    const int hi = static_cast<int>(value % 10);
    value /= 10;
    out.push_back(static_cast<std::uint8_t>(hi << 4 | lo));
  }
  return out;
}

std::optional<std::uint64_t> decode_bcd_little_endian(std::span<const std::uint8_t> bytes) {
  std::uint64_t v = 0;
  for (std::size_t i = bytes.size(); i-- > 0;) {
    const int hi = bytes[i] >> 4, lo = bytes[i] & 0x0F;
    if (hi > 9 || lo > 9) return std::nullopt;
    v = v * 100 + static_cast<std::uint64_t>(hi * 10 + lo);
  }
  return v;
}

Bytes bcd_big_endian(std::uint64_t value, int bytes) {
  Bytes out = bcd_little_endian(value, bytes);
  std::reverse(out.begin(), out.end());
  return out;
}

std::optional<std::uint64_t> decode_bcd_big_endian(std::span<const std::uint8_t> bytes) {
  Bytes rev(bytes.rbegin(), bytes.rend());
  return decode_bcd_little_endian(rev);
}

}  // namespace tb::radio
