#pragma once
// "HOST", "HOST:PORT", "[IPV6]" and "[IPV6]:PORT", read one way wherever trakbox takes a network
// peer: --udp-events and the stored destinations (a port required), --rotator satrak:HOST[:PORT]
// and `trakbox satrak` (4001), --rotator rotctld:HOST[:PORT] (4533), --radio rigctld:HOST[:PORT]
// (4532). Written back by host_port_text the same way.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "util/safe_text.h"
#include "util/text.h"

namespace tb::inet {

struct HostPort {
  std::string host;  // a name or an address (IPv6 without its brackets)
  std::uint16_t port = 0;
  bool operator==(const HostPort&) const = default;
};

// default_port: the port when the text gives none (0: a port is required). nullopt otherwise, with
// `error` saying what is wrong, without the text itself (the caller says where it came from):
// "expected HOST:PORT, e.g. ...", "unclosed '['", "expected ':' after ']'", "too many ':' (an IPv6
// address goes in brackets)", "missing HOST", "empty PORT", "PORT 'x' is not a TCP port (1..65535)".
inline std::optional<HostPort> parse_host_port(std::string_view text, std::string& error, std::uint16_t default_port = 0) {
  std::string_view host = text, port;
  bool has_port = false;
  if (!text.empty() && text.front() == '[') {
    const auto close = text.find(']');
    if (close == std::string_view::npos) {
      error = "unclosed '['";
      return std::nullopt;
    }
    host = text.substr(1, close - 1);
    const std::string_view after = text.substr(close + 1);
    if (!after.empty()) {
      if (after.front() != ':') {
        error = "expected ':' after ']'";
        return std::nullopt;
      }
      port = after.substr(1);
      has_port = true;
    }
  } else if (const auto colon = text.find(':'); colon != std::string_view::npos) {
    if (text.find(':', colon + 1) != std::string_view::npos) {
      error = "too many ':' (an IPv6 address goes in brackets)";
      return std::nullopt;
    }
    host = text.substr(0, colon);
    port = text.substr(colon + 1);
    has_port = true;
  }
  if (host.empty()) {
    error = "missing HOST";
    return std::nullopt;
  }
  const bool odd = std::any_of(host.begin(), host.end(), [](unsigned char c) {
    return c <= ' ' || c == 0x7F || c == '[' || c == ']';
  });
  if (odd) {
    error = "HOST '" + text::safe_text(host) + "' is not a name or an address";
    return std::nullopt;
  }
  if (!has_port && default_port == 0) {
    error = "expected HOST:PORT, e.g. 192.168.1.20:9000 or [2001:db8::2]:9000";
    return std::nullopt;
  }
  if (has_port && port.empty()) {
    error = "empty PORT";
    return std::nullopt;
  }
  HostPort out{std::string(host), default_port};
  if (has_port) {
    const auto p = port.front() == '+' ? std::nullopt : text::parse_integer<long>(port);
    if (!p || *p < 1 || *p > 65535) {
      error = "PORT '" + std::string(port) + "' is not a TCP port (1..65535)";
      return std::nullopt;
    }
    out.port = static_cast<std::uint16_t>(*p);
  }
  return out;
}

// A host as it is written before ":PORT": an IPv6 address in brackets ("[2001:db8::2]"), as
// parse_host_port reads it back and Hamlib takes it in a pathname.
inline std::string host_text(std::string_view host) {
  return host.find(':') != std::string_view::npos ? "[" + std::string(host) + "]" : std::string(host);
}

// The text parse_host_port reads back: "[2001:db8::2]:9000" for an IPv6 address.
inline std::string host_port_text(const HostPort& h) { return host_text(h.host) + ":" + std::to_string(h.port); }

}  // namespace tb::inet
