#include "util/cidr.h"

#include <doctest/doctest.h>

using namespace tb::net;

TEST_CASE("CIDR ranges: IPv4, IPv6, single addresses and IPv4-mapped clients") {
  const auto lan = parse_cidr("192.168.1.0/24");
  REQUIRE(lan);
  CHECK(contains(*lan, "192.168.1.77"));
  CHECK_FALSE(contains(*lan, "192.168.2.1"));
  CHECK(contains(*lan, "::ffff:192.168.1.9"));  // an IPv4 client on a dual-stack socket
  const auto one = parse_cidr("127.0.0.1");
  REQUIRE(one);
  CHECK(one->prefix == 32);
  CHECK(contains(*one, "127.0.0.1"));
  CHECK_FALSE(contains(*one, "127.0.0.2"));
  const auto v6 = parse_cidr("2001:db8::/32");
  REQUIRE(v6);
  CHECK(contains(*v6, "2001:db8:1::5"));
  CHECK_FALSE(contains(*v6, "2001:db9::1"));
  CHECK_FALSE(contains(*v6, "192.168.1.1"));
  const auto all = parse_cidr("0.0.0.0/0");
  REQUIRE(all);
  CHECK(contains(*all, "8.8.8.8"));
  for (const char* bad : {"", "/24", "192.168.1.0/33", "192.168.1/24", "::1/129", "10.0.0.1/", "10.0.0.1/x", "host"})
    CHECK_FALSE(parse_cidr(bad));
}

TEST_CASE("An empty allow-list allows everyone; loopback listeners are recognised") {
  CHECK(allowed({}, "203.0.113.5"));
  const std::vector<Cidr> only_local{*parse_cidr("127.0.0.1/32")};
  CHECK(allowed(only_local, "127.0.0.1"));
  CHECK_FALSE(allowed(only_local, "127.0.0.2"));
  CHECK(is_loopback("127.0.0.1"));
  CHECK(is_loopback("127.1.2.3"));
  CHECK(is_loopback("::1"));
  CHECK_FALSE(is_loopback("0.0.0.0"));
  CHECK_FALSE(is_loopback("::"));
  CHECK_FALSE(is_loopback("192.168.1.10"));
}

// Issue 33, defect 6: "::ffff:127.0.0.2/128" was refused at start while the mapped address itself
// was served; "127.0.0.2/8" was taken without a word about its host bits.
TEST_CASE("IPv4-mapped ranges are the IPv4 ranges they map; host bits are noticed") {
  const auto one = parse_cidr("::ffff:127.0.0.2/128");
  REQUIRE(one);
  CHECK_FALSE(one->v6);
  CHECK(one->prefix == 32);
  CHECK(contains(*one, "127.0.0.2"));
  CHECK(contains(*one, "::ffff:127.0.0.2"));
  CHECK_FALSE(contains(*one, "127.0.0.3"));
  const auto net = parse_cidr("::ffff:192.0.2.0/120");
  REQUIRE(net);
  CHECK(net->prefix == 24);
  CHECK(contains(*net, "192.0.2.200"));
  CHECK_FALSE(parse_cidr("::ffff:192.0.2.0/95"));  // a prefix inside the mapping's 96 bits
  CHECK(parse_cidr("::ffff:192.0.2.0/96")->prefix == 0);
  CHECK(has_host_bits(*parse_cidr("127.0.0.2/8")));
  CHECK_FALSE(has_host_bits(*parse_cidr("127.0.0.0/8")));
  CHECK_FALSE(has_host_bits(*parse_cidr("127.0.0.2")));
  CHECK(has_host_bits(*parse_cidr("2001:db8::1/32")));
  CHECK_FALSE(has_host_bits(*parse_cidr("2001:db8::/32")));
}
