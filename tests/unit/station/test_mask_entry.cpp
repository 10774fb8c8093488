// The horizon mask as an operator types it (menu 4, the page; issue 57): the reader's forms, none,
// and the reader's sentence for a bad one.
#include <doctest/doctest.h>

#include "station/station.h"

using tb::station::describe_mask;
using tb::station::read_mask_entry;

TEST_CASE("a typed horizon mask: pairs joined by ';', pairs one a line, a step list, none") {
  CHECK(read_mask_entry("0 5; 214 25;263 5").text == std::optional<std::string>("0 5; 214 25; 263 5"));
  CHECK(read_mask_entry("0 5\n214 25\r\n263 5\n").text == std::optional<std::string>("0 5; 214 25; 263 5"));
  CHECK(read_mask_entry("  0 0 190 25 230 0 360 ").text == std::optional<std::string>("0 0 190 25 230 0 360"));
  for (const char* none : {"none", "NONE", " None ", "", "  \n"}) {
    CAPTURE(none);
    CHECK(read_mask_entry(none).text == std::optional<std::string>(""));
  }
}

TEST_CASE("a typed horizon mask that does not read: the reader's sentence, no text") {
  const auto bad = read_mask_entry("0 0; 190 25; 400 0");
  CHECK_FALSE(bad.text);
  CHECK(bad.error == "horizon mask pair 3: azimuth 400 is outside 0..360");
  CHECK(read_mask_entry("0 0 190 25").error.find("a step list ends with an azimuth") != std::string::npos);
  CHECK(read_mask_entry("nothing").error == "horizon mask line 1: 'nothing' is not a number");
}

TEST_CASE("the station's mask described: none, or as the status says it") {
  tb::station::StationConfig st;
  CHECK(describe_mask(st) == "none");
  st.horizon_mask = "0 0 190 25 230 0 360";
  CHECK(describe_mask(st) == "stepped, 3 steps, 0.0..25.0 deg");
}
