// HOST:PORT as every network peer is read (util/host_port.h): --udp-events (a port required),
// satrak:, rotctld: and rigctld: (a default port), and the reasons others are refused for.
#include <doctest/doctest.h>

#include "util/host_port.h"

namespace {
std::optional<tb::inet::HostPort> parse_udp_target(const std::string& text, std::string& why) {
  return tb::inet::parse_host_port(text, why);
}
}  // namespace

TEST_CASE("--udp-events: HOST:PORT and [IPV6]:PORT; others refused with the form") {
  std::string why;
  auto t = parse_udp_target("192.168.1.20:9000", why);
  REQUIRE(t.has_value());
  CHECK(t->host == "192.168.1.20");
  CHECK(t->port == 9000);
  t = parse_udp_target("[2001:db8::2]:65535", why);
  REQUIRE(t.has_value());
  CHECK(t->host == "2001:db8::2");
  CHECK(t->port == 65535);
  t = parse_udp_target("logger.local:1", why);
  REQUIRE(t.has_value());
  CHECK(t->host == "logger.local");

  CHECK_FALSE(parse_udp_target("nohost", why));
  CHECK(why == "expected HOST:PORT, e.g. 192.168.1.20:9000 or [2001:db8::2]:9000");
  CHECK_FALSE(parse_udp_target("host:0", why));
  CHECK(why == "PORT '0' is not a TCP port (1..65535)");
  CHECK_FALSE(parse_udp_target("host:70000", why));
  CHECK_FALSE(parse_udp_target("host:9.5", why));
  CHECK_FALSE(parse_udp_target(":9000", why));
  CHECK_FALSE(parse_udp_target("2001:db8::2:9000", why));
  CHECK_FALSE(parse_udp_target("[2001:db8::2]9000", why));
  CHECK(why == "expected ':' after ']'");
  CHECK_FALSE(parse_udp_target("host:+80", why));
  CHECK_FALSE(parse_udp_target("host:", why));
  CHECK(why == "empty PORT");
  CHECK_FALSE(parse_udp_target("[::1", why));
  CHECK(why == "unclosed '['");
}

TEST_CASE("a default port: HOST and [IPV6] alone take it; the same refusals otherwise") {
  std::string why;
  auto t = tb::inet::parse_host_port("acu.example", why, 4001);
  REQUIRE(t);
  CHECK(*t == tb::inet::HostPort{"acu.example", 4001});
  t = tb::inet::parse_host_port("[::1]", why, 4533);
  REQUIRE(t);
  CHECK(*t == tb::inet::HostPort{"::1", 4533});
  t = tb::inet::parse_host_port("[::1]:4002", why, 4001);
  REQUIRE(t);
  CHECK(t->port == 4002);
  CHECK(tb::inet::host_port_text(*t) == "[::1]:4002");
  CHECK_FALSE(tb::inet::parse_host_port("a:b:c", why, 4001));
  CHECK(why == "too many ':' (an IPv6 address goes in brackets)");
  CHECK_FALSE(tb::inet::parse_host_port(":4001", why, 4001));
  CHECK(why == "missing HOST");
  CHECK_FALSE(tb::inet::parse_host_port("", why, 4001));
  CHECK(why == "missing HOST");
}
