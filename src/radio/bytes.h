// The byte helpers every CAT codec shares: hex text, packed BCD both ways round, and the range
// check of a frequency an encoder is given. Pure.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "radio/config.h"

namespace tb::radio {

using Bytes = std::vector<std::uint8_t>;

// "FE FE 10 E0 05 00 00 95 45 01 FD" (upper-case hex, one space between bytes).
std::string to_hex(std::span<const std::uint8_t> bytes);
// The reverse; spaces optional ("FEFE..." works). nullopt on a bad digit or an odd count.
std::optional<Bytes> from_hex(std::string_view text);

// Packed BCD, least significant byte first, low digit in the low nibble (Icom).
Bytes bcd_little_endian(std::uint64_t value, int bytes);
std::optional<std::uint64_t> decode_bcd_little_endian(std::span<const std::uint8_t> bytes);
// Packed BCD, most significant byte first (Yaesu). Keeps the low 2*bytes digits.
Bytes bcd_big_endian(std::uint64_t value, int bytes);
std::optional<std::uint64_t> decode_bcd_big_endian(std::span<const std::uint8_t> bytes);

// 10^n.
std::uint64_t pow10(int n);
// Throws std::invalid_argument naming `what` for a frequency below 0 or at or above `limit` Hz.
void require_frequency(Hz hz, std::uint64_t limit, const char* what);

}  // namespace tb::radio
