// The SmartSDR TCP/IP API of the FlexRadio 6000/8000 (radio/flex/codec.h): the exact lines of
// FlexRadio's API wiki ("SmartSDR TCPIP API": V/H on connect, C<seq>|command, R<seq>|<hex>|data;
// "TCPIP slice": slice create/tune/set and their error codes; "SmartSDR Status Responses": the
// slice's S lines) and of FlexLib's Slice.cs, which tunes with "slice tune <n> <MHz, f6>".
#include <doctest/doctest.h>

#include <stdexcept>

#include "radio/flex/codec.h"

using namespace tb::radio;

TEST_CASE("flex: frequencies in MHz with six decimals") {
  CHECK(flex::mhz(435'640'000) == "435.640000");
  CHECK(flex::mhz(145'965'000) == "145.965000");
  CHECK(flex::mhz(14'200'001) == "14.200001");
  CHECK(flex::mhz(10'489'550'000) == "10489.550000");
  CHECK(flex::mhz(0) == "0.000000");
  CHECK_THROWS_AS(flex::mhz(-1), std::invalid_argument);
  CHECK_THROWS_AS(flex::mhz(100'000'000'000), std::invalid_argument);
  CHECK(flex::decode_mhz("435.640000") == 435'640'000);
  CHECK(flex::decode_mhz("14.2012") == 14'201'200);          // the status page's example
  CHECK(flex::decode_mhz("10.0") == 10'000'000);
  CHECK(flex::decode_mhz("145") == 145'000'000);
  CHECK(flex::decode_mhz("435.6400005") == 435'640'001);     // the seventh decimal rounds
  CHECK(flex::decode_mhz("435.64000049") == 435'640'000);
  CHECK_FALSE(flex::decode_mhz(""));
  CHECK_FALSE(flex::decode_mhz("-1.0"));
  CHECK_FALSE(flex::decode_mhz("43x.1"));
  CHECK_FALSE(flex::decode_mhz("435.64e3"));
}

TEST_CASE("flex: the commands trakbox sends") {
  CHECK(flex::command(12, flex::tune(0, 435'640'000)) == "C12|slice tune 0 435.640000\n");
  CHECK(flex::command(13, *flex::set_mode(0, Mode::usb)) == "C13|slice set 0 mode=USB\n");
  CHECK(flex::create(145'965'000, Mode::lsb) == "slice create freq=145.965000 mode=LSB");
  CHECK(flex::create(10'000'000) == "slice create freq=10.000000");
  CHECK(flex::set_tx(1) == "slice set 1 tx=1");
  CHECK(*flex::set_mode(2, Mode::cw) == "slice set 2 mode=CW");
  CHECK(*flex::set_mode(1, Mode::fm) == "slice set 1 mode=FM");
  CHECK_FALSE(flex::set_mode(0, Mode::none));
  CHECK(flex::set_tone(1, 670) == "slice set 1 fm_tone_mode=CTCSS_TX fm_tone_value=67.0");
  CHECK(flex::set_tone(1, 0) == "slice set 1 fm_tone_mode=OFF");
  CHECK(flex::subscribe_slices() == "sub slice all");
  CHECK(flex::list_slices() == "slice list");
  CHECK(flex::ping() == "ping");
  CHECK(flex::full_duplex(true) == "radio set full_duplex_enabled=1");
}

TEST_CASE("flex: modes both ways") {
  CHECK(flex::mode_from_name("USB") == Mode::usb);
  CHECK(flex::mode_from_name("lsb") == Mode::lsb);
  CHECK(flex::mode_from_name("NFM") == Mode::fm);
  CHECK(flex::mode_from_name("DFM") == Mode::fm);
  CHECK(flex::mode_from_name("CW") == Mode::cw);
  CHECK_FALSE(flex::mode_from_name("DIGU"));
  CHECK_FALSE(flex::mode_from_name("AM"));
}

TEST_CASE("flex: the radio's greeting and replies") {
  CHECK(flex::decode_version("V1.0.0.0") == "1.0.0.0");
  CHECK(flex::decode_version("V3.4.35.140") == "3.4.35.140");
  CHECK_FALSE(flex::decode_version("V1.0"));
  CHECK(flex::decode_handle("H6F4EC23D") == 0x6F4EC23Du);
  CHECK_FALSE(flex::decode_handle("Hxyz"));
  CHECK_FALSE(flex::decode_handle("H123456789"));

  const auto created = flex::decode_reply("R21|0|2|OK Slice receiver 2 created on 10.000 MHz on port ANT1");
  REQUIRE(created);
  CHECK(created->seq == 21);
  CHECK(created->status == 0);
  CHECK(created->data == "2");   // the debug part after the third '|' is not data
  const auto bad = flex::decode_reply("R12|50000016|Malformed Command");
  REQUIRE(bad);
  CHECK(bad->status == 0x50000016u);
  CHECK(bad->data == "Malformed Command");
  const auto empty = flex::decode_reply("R19|0|");
  REQUIRE(empty);
  CHECK(empty->data.empty());
  CHECK(flex::decode_reply("R44|0|0x6F54A02B|OK")->data == "0x6F54A02B");
  CHECK_FALSE(flex::decode_reply("R|0|"));
  CHECK_FALSE(flex::decode_reply("R12|zz|"));
  CHECK_FALSE(flex::decode_reply("S12|0|"));
  CHECK(flex::error_text(0x50000016) == "50000016 malformed command");
  CHECK(flex::error_text(0x50000032) == "50000032 bad mode");
  CHECK(flex::error_text(0x500000AA) == "error 500000AA");
  CHECK(flex::decode_slice_list("0 1") == std::vector<int>{0, 1});
  CHECK(flex::decode_slice_list("") == std::vector<int>{});
  CHECK_FALSE(flex::decode_slice_list("0 A"));
}

TEST_CASE("flex: a slice's status") {
  const auto s = flex::decode_slice_status("S6F4EC23D|slice 0 RF_frequency=435.640000 mode=USB tx=0 in_use=1 wide=1");
  REQUIRE(s);
  CHECK(s->handle == 0x6F4EC23Du);
  CHECK(s->index == 0);
  CHECK(s->hz == 435'640'000);
  CHECK(s->mode == Mode::usb);
  CHECK(s->tx == false);
  CHECK(s->in_use == true);
  const auto turn = flex::decode_slice_status("S12AB34CD|slice 1 RF_frequency=14.2012");
  REQUIRE(turn);
  CHECK(turn->index == 1);
  CHECK(turn->hz == 14'201'200);
  CHECK_FALSE(turn->mode);
  CHECK_FALSE(turn->tx);
  const auto gone = flex::decode_slice_status("S0|slice 3 in_use=0");
  REQUIRE(gone);
  CHECK(gone->in_use == false);
  CHECK_FALSE(flex::decode_slice_status("S6F4EC23D|radio slices=2 full_duplex_enabled=1"));
  CHECK_FALSE(flex::decode_slice_status("S6F4EC23D|slice x RF_frequency=1.0"));
  CHECK_FALSE(flex::decode_slice_status("R1|0|"));
}
