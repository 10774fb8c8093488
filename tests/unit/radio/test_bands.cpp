// A band a radio lacks (issue 61): the limit's name ("no 70 cm") and the check every serial link
// makes before it sends a frequency (radio/link_common.h).
#include <doctest/doctest.h>

#include "radio/link_common.h"

using namespace tb::radio;

TEST_CASE("band names: the amateur band a frequency is in, its MHz outside them") {
  CHECK(link::band_name(29'450'000) == "10 m");
  CHECK(link::band_name(50'100'000) == "6 m");
  CHECK(link::band_name(145'965'000) == "2 m");
  CHECK(link::band_name(435'640'000) == "70 cm");
  CHECK(link::band_name(1'268'100'000) == "23 cm");
  CHECK(link::band_name(2'400'050'000) == "13 cm");
  CHECK(link::band_name(5'760'100'000) == "5.7 GHz");
  CHECK(link::band_name(10'489'550'000) == "10 GHz");
  CHECK(link::band_name(300'000'000) == "300.000 MHz");
}

TEST_CASE("require_band: inside a band nothing, outside a limit learnt (lacks), not a fault") {
  const HzRange bands[] = {{30'000, 74'800'000}};
  CHECK_NOTHROW(link::require_band("the IC-7300", bands, Link::downlink, 29'450'000));
  CHECK_NOTHROW(link::require_band("any radio", {}, Link::downlink, 435'640'000));   // no bands given: not checked
  try {
    link::require_band("the IC-7300", bands, Link::downlink, 435'640'000);
    FAIL("no limit");
  } catch (const LinkError& e) {
    CHECK(e.action == LinkError::Action::lacks);
    CHECK(e.capability == "no 70 cm");
    CHECK(std::string(e.what()) == "the IC-7300 has no 70 cm band: the downlink at 435640000 Hz is not sent");
  }
}
