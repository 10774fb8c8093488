// A refused number quoted as it was sent (issue 46): the shortest text that reads back as the same
// double, never %g's six digits; no "-0".
#include <doctest/doctest.h>

#include "util/exact_number.h"

using tb::text::az_el_text;
using tb::text::exact_number;

TEST_CASE("exact_number: the value refused, exactly") {
  CHECK(exact_number(90.0000001) == "90.0000001");
  CHECK(exact_number(90) == "90");
  CHECK(exact_number(360.5) == "360.5");
  CHECK(exact_number(-0.0) == "0");
  CHECK(exact_number(0.0) == "0");
  CHECK(exact_number(-12.25) == "-12.25");
  CHECK(exact_number(0.1) == "0.1");
  CHECK(exact_number(1e300) == "1e+300");
  CHECK(exact_number(123456789.123) == "123456789.123");
}

TEST_CASE("az_el_text: one decimal, and a value that rounds to zero is 0.0") {
  CHECK(az_el_text(-0.0, -0.0) == "AZ0.0 EL0.0");
  CHECK(az_el_text(123.0, 45.06) == "AZ123.0 EL45.1");
  CHECK(az_el_text(359.96, -0.04) == "AZ360.0 EL0.0");
  CHECK(az_el_text(10, -1.5) == "AZ10.0 EL-1.5");
}
