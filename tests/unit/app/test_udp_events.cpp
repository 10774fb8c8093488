// --udp-events HOST:PORT: the destinations it takes and the sentences it refuses others with.
#include <doctest/doctest.h>

#include "app/udp_events.h"

using tb::app::parse_udp_target;

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
  CHECK(why == "'nohost': expected HOST:PORT, e.g. 192.168.1.20:9000 or [2001:db8::2]:9000");
  CHECK_FALSE(parse_udp_target("host:0", why));
  CHECK(why == "'host:0': expected HOST:PORT with a port 1 to 65535");
  CHECK_FALSE(parse_udp_target("host:70000", why));
  CHECK_FALSE(parse_udp_target("host:9.5", why));
  CHECK_FALSE(parse_udp_target(":9000", why));
  CHECK_FALSE(parse_udp_target("2001:db8::2:9000", why));
  CHECK_FALSE(parse_udp_target("[2001:db8::2]9000", why));
  CHECK(why == "'[2001:db8::2]9000': expected [IPV6]:PORT");
}
