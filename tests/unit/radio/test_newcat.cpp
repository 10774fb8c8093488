// Yaesu's ASCII CAT (radio/yaesu/newcat.h) for the FT-991/991A, FTX-1, FT-710 and FTdx10: the
// strings of docs/radio.md ("CAT formats"), from the FT-991 CAT operation reference (FA/FB nine
// digits, MD0 with the mode character, AB, LK, CN/CT, ID) and Hamlib's newcat.c / ft991.c, which
// send the same for rig_set_freq / rig_set_mode (compared with rigctl -m 1035 on a pty: docs/radio.md).
#include <doctest/doctest.h>

#include <stdexcept>

#include "radio/yaesu/newcat.h"

using namespace tb::radio;

TEST_CASE("newcat: FA/FB with nine digits of Hz") {
  CHECK(newcat::set_frequency(newcat::Vfo::a, 435'640'000) == "FA435640000;");
  CHECK(newcat::set_frequency(newcat::Vfo::b, 145'965'000) == "FB145965000;");
  CHECK(newcat::set_frequency(newcat::Vfo::a, 29'450'000) == "FA029450000;");
  CHECK(newcat::set_frequency(newcat::Vfo::a, 0) == "FA000000000;");
  CHECK_THROWS_AS(newcat::set_frequency(newcat::Vfo::a, 1'000'000'000), std::invalid_argument);
  CHECK_THROWS_AS(newcat::set_frequency(newcat::Vfo::b, -1), std::invalid_argument);
  CHECK(newcat::read_frequency(newcat::Vfo::a) == "FA;");
  CHECK(newcat::read_frequency(newcat::Vfo::b) == "FB;");
}

TEST_CASE("newcat: MD0/MD1 and the mode character") {
  CHECK(newcat::set_mode('0', Mode::lsb) == "MD01;");
  CHECK(newcat::set_mode('0', Mode::usb) == "MD02;");
  CHECK(newcat::set_mode('0', Mode::cw) == "MD03;");
  CHECK(newcat::set_mode('0', Mode::fm) == "MD04;");
  CHECK(newcat::set_mode('1', Mode::lsb) == "MD11;");   // the FTX-1's Sub
  CHECK_FALSE(newcat::set_mode('0', Mode::none));
  CHECK_THROWS_AS(newcat::set_mode('2', Mode::usb), std::invalid_argument);
  CHECK(newcat::read_mode('0') == "MD0;");
}

TEST_CASE("newcat: the other commands trakbox sends; never ST") {
  CHECK(newcat::identify() == "ID;");
  CHECK(newcat::copy_a_to_b() == "AB;");
  CHECK(newcat::lock(true) == "LK1;");
  CHECK(newcat::lock(false) == "LK0;");
  CHECK(newcat::set_tone(670) == "CN00000;CT02;");     // 67.0 Hz: the first of 50
  CHECK(newcat::set_tone(885) == "CN00008;CT02;");     // 88.5 Hz
  CHECK(newcat::set_tone(2541) == "CN00049;CT02;");    // 254.1 Hz: the last
  CHECK_FALSE(newcat::set_tone(1750));                  // not a CTCSS tone of the list
  CHECK(newcat::tone_off() == "CT00;");
}

TEST_CASE("newcat: answers decoded") {
  const auto a = newcat::decode_frequency("FA435640000;");
  REQUIRE(a);
  CHECK(a->vfo == newcat::Vfo::a);
  CHECK(a->hz == 435'640'000);
  const auto b = newcat::decode_frequency("FB145965000");
  REQUIRE(b);
  CHECK(b->vfo == newcat::Vfo::b);
  CHECK(b->hz == 145'965'000);
  CHECK_FALSE(newcat::decode_frequency("FA00435640000;"));   // eleven digits: the TS-2000's, not this family's
  CHECK_FALSE(newcat::decode_frequency("FA43564000x;"));
  CHECK_FALSE(newcat::decode_frequency("?;"));
  CHECK(newcat::decode_mode("MD02;") == Mode::usb);
  CHECK(newcat::decode_mode("MD1B;") == Mode::fm);     // FM-N
  CHECK(newcat::decode_mode("MD07;") == Mode::cw);     // CW-L
  CHECK_FALSE(newcat::decode_mode("MD05;"));           // AM: not ours
  CHECK(newcat::decode_id("ID0670;") == "0670");
  CHECK(newcat::decode_id("ID0840;") == "0840");
  CHECK_FALSE(newcat::decode_id("ID067;"));
  CHECK(newcat::is_refusal("?;"));
  CHECK_FALSE(newcat::is_refusal("FA435640000;"));
}
