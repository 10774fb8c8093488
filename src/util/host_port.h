#pragma once
// "HOST:PORT" and "[IPV6]:PORT" destinations (--udp-events), read and written back the same way:
// the command line and the stored state (store::Model::udp_events) share one reading.
#include <cstdint>
#include <optional>
#include <string>

#include "util/text.h"

namespace tb::inet {

struct HostPort {
  std::string host;  // a name or an address (IPv6 without its brackets)
  std::uint16_t port = 0;
  bool operator==(const HostPort&) const = default;
};

// nullopt with the reason ("'nohost': expected HOST:PORT, ...") otherwise.
inline std::optional<HostPort> parse_host_port(const std::string& text, std::string& error) {
  std::string host, port;
  if (!text.empty() && text.front() == '[') {
    const auto end = text.find("]:");
    if (end == std::string::npos) {
      error = "'" + text + "': expected [IPV6]:PORT";
      return std::nullopt;
    }
    host = text.substr(1, end - 1);
    port = text.substr(end + 2);
  } else {
    const auto colon = text.rfind(':');
    if (colon == std::string::npos || text.find(':') != colon) {
      error = "'" + text + "': expected HOST:PORT, e.g. 192.168.1.20:9000 or [2001:db8::2]:9000";
      return std::nullopt;
    }
    host = text.substr(0, colon);
    port = text.substr(colon + 1);
  }
  const auto p = text::parse_double(port);
  if (host.empty() || !p || *p < 1 || *p > 65535 || *p != static_cast<int>(*p)) {
    error = "'" + text + "': expected HOST:PORT with a port 1 to 65535";
    return std::nullopt;
  }
  return HostPort{host, static_cast<std::uint16_t>(*p)};
}

// The text parse_host_port reads back: "[2001:db8::2]:9000" for an IPv6 address.
inline std::string host_port_text(const HostPort& h) {
  const std::string host = h.host.find(':') != std::string::npos ? "[" + h.host + "]" : h.host;
  return host + ":" + std::to_string(h.port);
}

}  // namespace tb::inet
