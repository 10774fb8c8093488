#pragma once
// Address ranges for the TCP endpoints' allow-lists (--allow): "192.168.1.0/24", "2001:db8::/32",
// "127.0.0.1" (one address: /32 or /128). An IPv4 client seen on an IPv6 socket ("::ffff:a.b.c.d")
// is matched as the IPv4 address it is.
#include <arpa/inet.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tb::net {

struct Cidr {
  bool v6 = false;
  std::array<std::uint8_t, 16> bytes{};  // network byte order; IPv4 in the first 4
  int prefix = 0;                         // bits
};

namespace detail {
// The address's bytes, IPv4-mapped IPv6 read as IPv4.
inline std::optional<std::pair<bool, std::array<std::uint8_t, 16>>> parse_address(const std::string& text) {
  std::array<std::uint8_t, 16> b{};
  if (::inet_pton(AF_INET, text.c_str(), b.data()) == 1) return std::pair{false, b};
  if (::inet_pton(AF_INET6, text.c_str(), b.data()) == 1) {
    static constexpr std::uint8_t kMapped[12] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xff, 0xff};
    if (std::equal(b.begin(), b.begin() + 12, kMapped)) {
      std::array<std::uint8_t, 16> v4{};
      std::copy(b.begin() + 12, b.end(), v4.begin());
      return std::pair{false, v4};
    }
    return std::pair{true, b};
  }
  return std::nullopt;
}
}  // namespace detail

// "ADDRESS[/PREFIX]"; nothing when it is not one (the caller names the option in its message).
// An IPv4-mapped IPv6 range ("::ffff:192.0.2.0/120") is the IPv4 range it maps (192.0.2.0/24):
// its prefix must reach past the 96 bits of the mapping.
inline std::optional<Cidr> parse_cidr(std::string_view text) {
  const auto slash = text.find('/');
  const std::string address(text.substr(0, slash));
  const auto a = detail::parse_address(address);
  if (!a) return std::nullopt;
  Cidr c;
  c.v6 = a->first;
  c.bytes = a->second;
  const bool mapped = !c.v6 && address.find(':') != std::string::npos;
  const int max = c.v6 || mapped ? 128 : 32;
  c.prefix = c.v6 ? 128 : 32;
  if (slash != std::string_view::npos) {
    const std::string_view p = text.substr(slash + 1);
    int n = -1;
    const auto [end, ec] = std::from_chars(p.data(), p.data() + p.size(), n);
    if (p.empty() || ec != std::errc() || end != p.data() + p.size() || n < 0 || n > max) return std::nullopt;
    if (mapped && n < 96) return std::nullopt;
    c.prefix = mapped ? n - 96 : n;
  }
  return c;
}

// True when the address has bits set past its prefix ("127.0.0.2/8"): the range is still the
// network's (127.0.0.0/8), but the operator may have meant something else, so it is worth a word.
inline bool has_host_bits(const Cidr& c) {
  for (int bit = c.prefix; bit < (c.v6 ? 128 : 32); ++bit)
    if (c.bytes[static_cast<std::size_t>(bit / 8)] & (0x80u >> (bit % 8))) return true;
  return false;
}

inline bool contains(const Cidr& c, const std::string& address) {
  const auto a = detail::parse_address(address);
  if (!a || a->first != c.v6) return false;
  for (int bit = 0; bit < c.prefix; ++bit) {
    const std::uint8_t mask = static_cast<std::uint8_t>(0x80u >> (bit % 8));
    if ((a->second[static_cast<std::size_t>(bit / 8)] & mask) != (c.bytes[static_cast<std::size_t>(bit / 8)] & mask))
      return false;
  }
  return true;
}

// An empty list allows everyone (the servers' default: they listen on loopback unless told).
inline bool allowed(const std::vector<Cidr>& allow, const std::string& address) {
  if (allow.empty()) return true;
  for (const Cidr& c : allow)
    if (contains(c, address)) return true;
  return false;
}

// True for 127.0.0.0/8, ::1 and the like: an address only this machine can reach.
inline bool is_loopback(const std::string& listen_address) {
  static const Cidr v4 = *parse_cidr("127.0.0.0/8"), v6 = *parse_cidr("::1/128");
  return contains(v4, listen_address) || contains(v6, listen_address) || listen_address == "localhost";
}

}  // namespace tb::net
