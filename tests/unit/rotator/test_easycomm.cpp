// The Easycomm codec (rotator/easycomm.h): the bytes are Hamlib's easycomm backend's
// (rotators/easycomm/easycomm.c: "AZ%.1f EL%.1f\n", "AZ EL \n", "SA SE \n"), the replies those the
// SatNOGS rotator firmware sends (libraries/easycomm.h: "AZxx.x ELyy.y\n", "VESatNOGS-v2.2") and the
// Easycomm II text's unsolicited alarm ("ALxxx").
#include <doctest/doctest.h>

#include "rotator/easycomm.h"

using namespace tb::rotator;
namespace ec = tb::rotator::easycomm;

TEST_CASE("Easycomm: the bytes of set, read and stop are Hamlib's") {
  CHECK(ec::set_position({180.0, 45.0}) == "AZ180.0 EL45.0\n");
  CHECK(ec::set_position({0.0, 0.0}) == "AZ0.0 EL0.0\n");
  CHECK(ec::set_position({359.96, 89.94}) == "AZ360.0 EL89.9\n");
  // One decimal as C's %.1f rounds it: 10.25 is exact in binary, a tie, rounded to even.
  CHECK(ec::set_position({10.25, 7.75}) == "AZ10.2 EL7.8\n");
  CHECK(ec::read_position() == "AZ EL \n");
  CHECK(ec::stop() == "SA SE \n");
  CHECK(ec::default_baud(ec::Version::three) == 19200);
  CHECK(ec::default_baud(ec::Version::two) == 9600);
  CHECK(ec::hamlib_model(ec::Version::three) == 204);
  CHECK(ec::hamlib_model(ec::Version::two) == 202);
}

TEST_CASE("Easycomm: a position reply, as the SatNOGS firmware and Hamlib's sscanf read it") {
  auto l = ec::parse_line("AZ123.4 EL45.6\r");
  REQUIRE(l.kind == ec::Line::Kind::position);
  CHECK(l.position.az == doctest::Approx(123.4));
  CHECK(l.position.el == doctest::Approx(45.6));
  l = ec::parse_line("AZ 7.0 EL 0.0");   // sscanf's %f skips blanks
  REQUIRE(l.kind == ec::Line::Kind::position);
  CHECK(l.position.az == doctest::Approx(7.0));
  l = ec::parse_line("AZ-2.5 EL-1.0");
  REQUIRE(l.kind == ec::Line::Kind::position);
  CHECK(l.position.az == doctest::Approx(-2.5));
  CHECK(l.position.el == doctest::Approx(-1.0));
}

TEST_CASE("Easycomm: alarms, echoes and what is not a position") {
  auto l = ec::parse_line("AL003");
  CHECK(l.kind == ec::Line::Kind::alarm);
  CHECK(l.text == "AL003");
  CHECK(ec::parse_line("VESatNOGS-v2.2").kind == ec::Line::Kind::other);
  CHECK(ec::parse_line("IP0,25.3").kind == ec::Line::Kind::other);
  CHECK(ec::parse_line("AZ EL").kind == ec::Line::Kind::other);   // the query echoed
  CHECK(ec::parse_line("").kind == ec::Line::Kind::other);
  l = ec::parse_line("AZ12.0");   // Hamlib's sscanf reads one field: -RIG_ERJCTED
  CHECK(l.kind == ec::Line::Kind::bad);
  CHECK(l.text == "not a position: \"AZ12.0\"");
  CHECK(ec::parse_line("AZ1x.0 EL3.0").kind == ec::Line::Kind::bad);
  CHECK(ec::parse_line("AZnan EL3.0").kind == ec::Line::Kind::bad);
  l = ec::parse_line("AZ9999.0 EL3.0");
  CHECK(l.kind == ec::Line::Kind::bad);
  CHECK(l.text == "a position out of any rotator's range: \"AZ9999.0 EL3.0\"");
  // Bytes from outside reach a message only as visible text.
  l = ec::parse_line(std::string("AZ\x01\xff EL1"));
  CHECK(l.kind == ec::Line::Kind::bad);
  CHECK(l.text.find('\x01') == std::string::npos);
}
