// PstRotator's UDP protocol (rotator/pst/codec.h): the datagrams as PstRotator's own manual (rev.
// 2.9), Hamlib's PSTRotator backend, SatDump's PstRotatorHandler and the CSN S.A.T. scripts write
// them, both ways.
#include <doctest/doctest.h>

#include "rotator/pst/codec.h"

namespace pst = tb::rotator::pst;
using Kind = pst::Command::Kind;

TEST_CASE("PstRotator: the datagrams trakbox sends") {
  CHECK(pst::set_azimuth(173.0) == "<PST><AZIMUTH>173.0</AZIMUTH></PST>");
  CHECK(pst::set_elevation(25.0) == "<PST><ELEVATION>25.0</ELEVATION></PST>");
  CHECK(pst::stop() == "<PST><STOP>1</STOP></PST>");
  CHECK(pst::park() == "<PST><PARK>1</PARK></PST>");
  CHECK(pst::ask_azimuth() == "<PST>AZ?</PST>");
  CHECK(pst::ask_elevation() == "<PST>EL?</PST>");
  CHECK(pst::azimuth_reply(297.0) == "AZ:297.0");
  CHECK(pst::elevation_reply(7.25) == "EL:7.2");   // %.1f: 7.25 is a tie, to even
  CHECK(pst::kCommandPort == 12000);
}

TEST_CASE("PstRotator: the commands trakbox takes") {
  auto d = pst::parse_command("<PST><AZIMUTH>173.0</AZIMUTH></PST>");
  REQUIRE(d.error.empty());
  REQUIRE(d.commands.size() == 1);
  CHECK(d.commands[0].kind == Kind::azimuth);
  CHECK(d.commands[0].value == 173.0);
  d = pst::parse_command("<PST><ELEVATION>25</ELEVATION></PST>\r\n");
  REQUIRE(d.commands.size() == 1);
  CHECK(d.commands[0].kind == Kind::elevation);
  CHECK(d.commands[0].value == 25.0);
  d = pst::parse_command("<PST><AZIMUTH>10.5</AZIMUTH><ELEVATION>3</ELEVATION></PST>");
  REQUIRE(d.commands.size() == 2);
  CHECK(d.commands[1].kind == Kind::elevation);
  CHECK(pst::parse_command("<PST><STOP>1</STOP></PST>").commands.at(0).kind == Kind::stop);
  CHECK(pst::parse_command("<PST><PARK>1</PARK></PST>").commands.at(0).kind == Kind::park);
  CHECK(pst::parse_command("<PST>AZ?</PST>").commands.at(0).kind == Kind::ask_azimuth);
  CHECK(pst::parse_command("<PST>EL?</PST>").commands.at(0).kind == Kind::ask_elevation);
  CHECK(pst::parse_command("<PST><STOP>0</STOP></PST>").commands.empty());
  CHECK(pst::parse_command("<PST><STOP>0</STOP></PST>").error.empty());
}

TEST_CASE("PstRotator: a bad datagram is refused whole, saying why") {
  CHECK(pst::parse_command("AZ:10").error == "not a PstRotator command (<PST>...</PST>): \"AZ:10\"");
  CHECK(pst::parse_command("<PST></PST>").error == "an empty <PST></PST>");
  CHECK(pst::parse_command("<PST><AZIMUTH>abc</AZIMUTH></PST>").error == "<AZIMUTH> \"abc\" is not a number");
  CHECK(pst::parse_command("<PST><AZIMUTH>800</AZIMUTH></PST>").error == "<AZIMUTH> 800 is out of range");
  CHECK(pst::parse_command("<PST><ELEVATION>-91</ELEVATION></PST>").error == "<ELEVATION> -91 is out of range");
  CHECK(pst::parse_command("<PST><QRA>KN34BJ</QRA></PST>").error ==
        "<QRA> is not a command trakbox takes (AZIMUTH, ELEVATION, STOP, PARK, AZ?, EL?)");
  CHECK(pst::parse_command("<PST><AZIMUTH>1</ELEVATION></PST>").error == "<AZIMUTH> without its end tag");
  // One good command and one bad: nothing is taken.
  const auto d = pst::parse_command("<PST><AZIMUTH>1</AZIMUTH><ELEVATION>x</ELEVATION></PST>");
  CHECK(d.commands.empty());
  CHECK(d.error == "<ELEVATION> \"x\" is not a number");
  CHECK(pst::parse_command(std::string(600, ' ')).error == "longer than 512 bytes");
  CHECK(pst::parse_command("<PST><AZ\x01IMUTH>1</AZ\x01IMUTH></PST>").error.find('\x01') == std::string::npos);
}

TEST_CASE("PstRotator: a box's replies") {
  auto r = pst::parse_reply("AZ:297.0");
  CHECK(r.az == 297.0);
  CHECK_FALSE(r.el);
  r = pst::parse_reply("EL:25.5\r\n");
  CHECK(r.el == 25.5);
  r = pst::parse_reply("<PST>AZ:10.0\nEL:20.0</PST>");
  CHECK(r.az == 10.0);
  CHECK(r.el == 20.0);
  r = pst::parse_reply("AZ:banana");
  CHECK_FALSE(r.az);
  CHECK_FALSE(pst::parse_reply("OK").az);
}
