// Every byte string of docs/radio.md's "CAT formats" (from the manual's CAT section and the radios'
// own CAT references), byte for byte, and back.
#include <doctest/doctest.h>

#include <stdexcept>

#include "radio/cat.h"

using namespace tb::radio;

namespace {
std::string hex(const Bytes& b) { return to_hex(b); }
std::string hex(const yaesu::Command& c) { return to_hex(c); }
}  // namespace

TEST_CASE("hex helpers") {
  CHECK(to_hex(Bytes{0xFE, 0x0A, 0x00}) == "FE 0A 00");
  CHECK(from_hex("FE FE 10") == Bytes{0xFE, 0xFE, 0x10});
  CHECK(from_hex("fefe10") == Bytes{0xFE, 0xFE, 0x10});
  CHECK_FALSE(from_hex("FE F"));
  CHECK_FALSE(from_hex("FG"));
}

TEST_CASE("Icom CI-V: set frequency, 5-byte BCD little-endian") {
  CHECK(hex(icom::set_frequency(icom::kIc275, 145950000)) == "FE FE 10 E0 05 00 00 95 45 01 FD");
  CHECK(hex(icom::set_frequency(icom::kIc475, 435123450)) == "FE FE 14 E0 05 50 34 12 35 04 FD");
  CHECK(hex(icom::set_frequency(icom::kIc970, 1269500000)) == "FE FE 2E E0 05 00 00 50 69 12 FD");
  // TrakBox's default: the broadcast address.
  CHECK(hex(icom::set_frequency(icom::kBroadcast, 145950000)) == "FE FE 00 E0 05 00 00 95 45 01 FD");
  CHECK_THROWS_AS(icom::set_frequency(0x10, -1), std::invalid_argument);
  CHECK_THROWS_AS(icom::set_frequency(0x10, 10'000'000'000), std::invalid_argument);
}

TEST_CASE("Icom CI-V: 4-byte frequency variant (IC-820H/821H) drops the 100 MHz digit") {
  CHECK(hex(icom::set_frequency(icom::kIc821, 145950000, icom::FrequencyWidth::four_bytes)) ==
        "FE FE 4C E0 05 00 00 95 45 FD");
  CHECK(hex(icom::set_frequency(icom::kIc820, 435123450, icom::FrequencyWidth::four_bytes)) ==
        "FE FE 42 E0 05 50 34 12 35 FD");
}

TEST_CASE("Icom CI-V: the IC-905's 6-byte frequencies on its 10 GHz band, 5 bytes below") {
  constexpr auto six = icom::FrequencyWidth::five_or_six;
  // Icom's IC-905 CI-V reference: 12 digits, 100 GHz down to 1 Hz, least significant pair first.
  // 10489.550 MHz = 010 489 550 000 Hz: pairs 00 00 55 89 04 01.
  CHECK(hex(icom::set_frequency(0xAC, 10'489'550'000, six)) == "FE FE AC E0 05 00 00 55 89 04 01 FD");
  CHECK(hex(icom::set_frequency(0xAC, 10'000'000'000, six)) == "FE FE AC E0 05 00 00 00 00 00 01 FD");
  CHECK(hex(icom::set_frequency(0xAC, 10'450'123'456, six)) == "FE FE AC E0 05 56 34 12 50 04 01 FD");
  // Its bands below 10 GHz keep the 5 bytes every other Icom sends.
  CHECK(hex(icom::set_frequency(0xAC, 9'999'999'999, six)) == "FE FE AC E0 05 99 99 99 99 99 FD");
  CHECK(hex(icom::set_frequency(0xAC, 2'400'050'000, six)) == "FE FE AC E0 05 00 00 05 00 24 FD");
  CHECK(hex(icom::set_frequency(0xAC, 5'760'100'000, six)) == "FE FE AC E0 05 00 00 10 60 57 FD");
  CHECK(hex(icom::set_frequency(0xAC, 145'950'000, six)) == "FE FE AC E0 05 00 00 95 45 01 FD");
  CHECK_THROWS_AS(icom::set_frequency(0xAC, 1'000'000'000'000, six), std::invalid_argument);
  CHECK_THROWS_AS(icom::set_frequency(0xAC, 10'489'550'000), std::invalid_argument);   // 5 bytes cannot carry it
  // Read back: the radio's 03 answer and 1C 03 with 6 bytes on 10 GHz.
  auto a = icom::decode_frame(*from_hex("FE FE E0 AC 03 00 00 55 89 04 01 FD"));
  REQUIRE(a);
  CHECK(icom::decode_frequency(*a) == 10'489'550'000);
  auto t = icom::decode_frame(*from_hex("FE FE E0 AC 1C 03 00 50 12 00 24 FD"));
  REQUIRE(t);
  CHECK(icom::decode_frequency(*t) == 2'400'125'000);
  auto t6 = icom::decode_frame(*from_hex("FE FE E0 AC 1C 03 00 00 55 89 04 01 FD"));
  REQUIRE(t6);
  CHECK(icom::decode_frequency(*t6) == 10'489'550'000);
  CHECK_FALSE(icom::decode_frequency(*icom::decode_frame(*from_hex("FE FE E0 AC 03 00 00 55 89 04 01 00 FD"))));
}

TEST_CASE("Icom CI-V: mode without a filter byte, and the ack") {
  CHECK(hex(*icom::set_mode(icom::kIc275, Mode::usb)) == "FE FE 10 E0 06 01 FD");
  CHECK(hex(*icom::set_mode(icom::kIc275, Mode::lsb)) == "FE FE 10 E0 06 00 FD");
  CHECK(hex(*icom::set_mode(icom::kIc275, Mode::cw)) == "FE FE 10 E0 06 03 FD");
  CHECK(hex(*icom::set_mode(icom::kIc275, Mode::fm)) == "FE FE 10 E0 06 05 FD");
  CHECK_FALSE(icom::set_mode(icom::kIc275, Mode::none));
  CHECK(icom::mode_from_code(0x02) == std::nullopt);  // AM: not one of ours
  CHECK(icom::mode_from_code(0x07) == Mode::cw);      // CW-R
  CHECK(icom::parse_reply(*from_hex("FE FE E0 10 FB FD")) == icom::Reply::ok);
  CHECK(icom::parse_reply(*from_hex("FE FE E0 10 FA FD")) == icom::Reply::ng);
  CHECK(icom::parse_reply(*from_hex("FC FC FC")) == icom::Reply::collision);
  CHECK(icom::parse_reply(*from_hex("FE FE E0 10 FC FD")) == icom::Reply::collision);
  CHECK(icom::parse_reply(*from_hex("FE FE 10 E0 06 01 FD")) == icom::Reply::not_a_reply);
  CHECK(icom::parse_reply(*from_hex("FE FE E0 10 FB")) == icom::Reply::not_a_reply);
}

TEST_CASE("Icom CI-V: band and VFO select") {
  CHECK(hex(icom::select_band(icom::kIc910, icom::Band::main)) == "FE FE 60 E0 07 D0 FD");
  CHECK(hex(icom::select_band(icom::kIc910, icom::Band::sub)) == "FE FE 60 E0 07 D1 FD");
  CHECK(hex(icom::select_vfo(icom::kIc275, icom::Vfo::a)) == "FE FE 10 E0 07 00 FD");
  CHECK(hex(icom::select_vfo(icom::kIc275, icom::Vfo::b)) == "FE FE 10 E0 07 01 FD");
}

TEST_CASE("Icom CI-V: decoding frames back") {
  auto f = icom::decode_frame(*from_hex("FE FE 14 E0 05 50 34 12 35 04 FD"));
  REQUIRE(f);
  CHECK(f->to == 0x14);
  CHECK(f->from == 0xE0);
  CHECK(f->cmd == 0x05);
  CHECK(icom::decode_frequency(*f) == 435123450);
  auto m = icom::decode_frame(*from_hex("FE FE 10 E0 06 01 FD"));
  REQUIRE(m);
  CHECK(icom::decode_mode(*m) == Mode::usb);
  CHECK_FALSE(icom::decode_frame(*from_hex("FE FE 14 E0 05 50 34")));
  CHECK_FALSE(icom::decode_frame(*from_hex("FE 14 E0 05 FD")));
  for (Hz hz : {Hz{0}, Hz{28'000'000}, Hz{145'999'990}, Hz{1'299'999'999}, Hz{9'999'999'999}}) {
    auto g = icom::decode_frame(icom::set_frequency(0x2E, hz));
    REQUIRE(g);
    CHECK(icom::decode_frequency(*g) == hz);
  }
}

TEST_CASE("Icom CI-V: the frame reader cuts a stream, keeps a jam code") {
  icom::FrameReader r;
  r.feed(*from_hex("00 FE FE 10 E0 06"));
  CHECK_FALSE(r.next());
  r.feed(*from_hex("01 FD FE FE E0 10 FB FD FC"));
  CHECK(hex(*r.next()) == "FE FE 10 E0 06 01 FD");
  CHECK(hex(*r.next()) == "FE FE E0 10 FB FD");
  CHECK(hex(*r.next()) == "FC");
  CHECK_FALSE(r.next());
  CHECK(r.skipped() == 1);
}

TEST_CASE("Kenwood TS-790: FA/FB with 11 digits, MD, FN") {
  CHECK(kenwood::set_frequency(kenwood::Vfo::a, 435123450) == "FA00435123450;");
  CHECK(kenwood::set_frequency(kenwood::Vfo::b, 145950000) == "FB00145950000;");
  CHECK(kenwood::set_frequency(kenwood::Vfo::a, 1269500000) == "FA01269500000;");
  CHECK(*kenwood::set_mode(Mode::usb) == "MD2;");
  CHECK(*kenwood::set_mode(Mode::lsb) == "MD1;");
  CHECK(*kenwood::set_mode(Mode::cw) == "MD3;");
  CHECK(*kenwood::set_mode(Mode::fm) == "MD4;");
  CHECK_FALSE(kenwood::set_mode(Mode::none));
  CHECK(kenwood::select_vfo(kenwood::Vfo::a) == "FN0;");
  CHECK(kenwood::select_vfo(kenwood::Vfo::b) == "FN1;");
  CHECK(kenwood::select_vfo(kenwood::Vfo::b, 'R') == "FR1;");   // the TS-2000's (Hamlib's kenwood_set_vfo)
  CHECK(kenwood::split(true) == "SP1;");
  CHECK(kenwood::split(false) == "SP0;");
  CHECK(kenwood::up() == "UP;");
  CHECK(kenwood::down() == "DN;");
  CHECK(kenwood::identify() == "ID;");
  CHECK_THROWS_AS(kenwood::set_frequency(kenwood::Vfo::a, 100'000'000'000), std::invalid_argument);
}

TEST_CASE("Kenwood: decoding back") {
  auto f = kenwood::decode_frequency("FA00435123450;");
  REQUIRE(f);
  CHECK(f->vfo == kenwood::Vfo::a);
  CHECK(f->hz == 435123450);
  CHECK(kenwood::decode_frequency("FB00145950000")->vfo == kenwood::Vfo::b);
  CHECK_FALSE(kenwood::decode_frequency("FA0043512345;"));
  CHECK_FALSE(kenwood::decode_frequency("MD2;"));
  CHECK(kenwood::decode_mode("MD2;") == Mode::usb);
  CHECK(kenwood::mode_from_digit('7') == Mode::cw);   // CW-R
  CHECK(kenwood::mode_from_digit('5') == std::nullopt);  // AM
  std::string rest;
  auto cmds = kenwood::split_commands("FN0;MD2;FA00435123450;FB0014", &rest);
  REQUIRE(cmds.size() == 3);
  CHECK(cmds[2] == "FA00435123450;");
  CHECK(rest == "FB0014");
}

// The strings other trackers send a TS-2000, as operators captured them (docs/radio.md, "TS-2000 SA"):
// SatPC32 SA1010110; at start and SA0010000; at exit (OscarWatch-Tracker issue #71); OscarWatch's
// own SA1010000; (TRACE off, "for PC-managed Doppler") and SA1011000; (CTRL on Sub, TRACE off);
// Hamlib: the answer is 18 characters, on when the third is 1; Hamlib's simulator answers SA0;.
TEST_CASE("Kenwood TS-2000: SA satellite mode, as SatPC32 and OscarWatch send it") {
  const auto found = kenwood::decode_satellite("SA0010000ISS     ;");   // as SatPC32 leaves the radio
  REQUIRE(found);
  CHECK_FALSE(found->on());
  CHECK(kenwood::set_satellite(*found) == "SA0010000;");                                   // SatPC32 at exit
  CHECK(kenwood::set_satellite(kenwood::satellite_working(*found, false)) == "SA1010000;");   // OscarWatch, TRACE off
  CHECK(kenwood::set_satellite(kenwood::satellite_working(*found, true)) == "SA1011000;");    // its CTRL on Sub
  // Found as SatPC32 runs it (TRACE and REV on): trakbox turns TRACE off, keeps REV and P2.
  const auto satpc32 = kenwood::decode_satellite("SA1010110        ;");
  REQUIRE(satpc32);
  CHECK(satpc32->on());
  CHECK(kenwood::set_satellite(kenwood::satellite_working(*satpc32, false)) == "SA1010010;");
  // On a satellite memory channel, Main up: back to VFO, the uplink on Sub.
  CHECK(kenwood::set_satellite(kenwood::satellite_working(*kenwood::decode_satellite("SA0200001        ;"), false)) ==
        "SA1210000;");
  // Hamlib's simulator answers SA0;: off, the other digits unknown (0).
  const auto sim = kenwood::decode_satellite("SA0;");
  REQUIRE(sim);
  CHECK(sim->digits == "0000000");
  CHECK_FALSE(kenwood::decode_satellite("SA;"));
  CHECK_FALSE(kenwood::decode_satellite("SAX010000;"));
  CHECK_FALSE(kenwood::decode_satellite("FA00435123450;"));
  CHECK(kenwood::read_satellite() == "SA;");
  CHECK(kenwood::is_refusal("?;"));
  CHECK(kenwood::is_refusal("E;"));
  CHECK(kenwood::is_refusal("O;"));
  CHECK_FALSE(kenwood::is_refusal("SA0;"));
}

// Hamlib's ts2000.c: TN with the 1-based number in its list of 38 tones and 1750 Hz; SatPC32's
// Doppler.sqf gives SO-50 67.0 Hz number 1, 74.4 Hz number 3 and SO-67 233.6 Hz number 36.
TEST_CASE("Kenwood TS-2000: CTCSS tone numbers and the encoder") {
  CHECK(kenwood::set_tone_number(670) == "TN01;");
  CHECK(kenwood::set_tone_number(744) == "TN03;");
  CHECK(kenwood::set_tone_number(2336) == "TN36;");
  CHECK(kenwood::set_tone_number(2503) == "TN38;");
  CHECK(kenwood::set_tone_number(17500) == "TN39;");   // SatPC32's TN39 at exit: the 1750 Hz tone
  CHECK_FALSE(kenwood::set_tone_number(693));          // 69.3 Hz: not in the TS-2000's list
  CHECK_FALSE(kenwood::set_tone_number(0));
  CHECK(kenwood::tone(true) == "TO1;");
  CHECK(kenwood::tone(false) == "TO0;");
  CHECK(kenwood::read_tone() == "TO;");
}

TEST_CASE("Yaesu FT-736: CAT and satellite mode on/off") {
  CHECK(hex(yaesu::cat_on()) == "00 00 00 00 00");
  CHECK(hex(yaesu::cat_off()) == "80 80 80 80 80");
  CHECK(hex(yaesu::sat_mode_on()) == "00 00 00 00 0E");
  CHECK(hex(yaesu::sat_mode_off()) == "00 00 00 00 8E");
}

TEST_CASE("Yaesu FT-736: frequencies in 10 Hz BCD, the 1.2 GHz rule") {
  CHECK(hex(yaesu::set_frequency(yaesu::Target::main, 435123450)) == "43 51 23 45 01");
  CHECK(hex(yaesu::set_frequency(yaesu::Target::sat_rx, 435123450)) == "43 51 23 45 1E");
  CHECK(hex(yaesu::set_frequency(yaesu::Target::sat_tx, 145950000)) == "14 59 50 00 2E");
  CHECK(hex(yaesu::set_frequency(yaesu::Target::main, 1296123450)) == "C9 61 23 45 01");
  CHECK(hex(yaesu::set_frequency(yaesu::Target::main, 50123450)) == "05 01 23 45 01");
  // Rounded to 10 Hz.
  CHECK(hex(yaesu::set_frequency(yaesu::Target::main, 435123446)) == "43 51 23 45 01");
  CHECK_THROWS_AS(yaesu::set_frequency(yaesu::Target::main, 1100000000), std::invalid_argument);
  CHECK_THROWS_AS(yaesu::set_frequency(yaesu::Target::main, 1300000000), std::invalid_argument);
  CHECK_THROWS_AS(yaesu::set_frequency(yaesu::Target::main, -10), std::invalid_argument);
}

TEST_CASE("Yaesu FT-736: mode opcodes, the mode in P1") {
  CHECK(hex(*yaesu::set_mode(yaesu::Target::sat_tx, Mode::usb)) == "01 00 00 00 27");
  CHECK(hex(*yaesu::set_mode(yaesu::Target::sat_rx, Mode::lsb)) == "00 00 00 00 17");
  CHECK(hex(*yaesu::set_mode(yaesu::Target::main, Mode::cw)) == "02 00 00 00 07");
  CHECK(hex(*yaesu::set_mode(yaesu::Target::sat_rx, Mode::fm)) == "08 00 00 00 17");
  CHECK(hex(*yaesu::set_mode(yaesu::Target::sat_rx, Mode::fm, true)) == "88 00 00 00 17");
  CHECK_FALSE(yaesu::set_mode(yaesu::Target::main, Mode::none));
}

TEST_CASE("Yaesu FT-736: decoding back") {
  using K = yaesu::Decoded::Kind;
  CHECK(yaesu::decode(yaesu::cat_on()).kind == K::cat_on);
  CHECK(yaesu::decode(yaesu::cat_off()).kind == K::cat_off);
  CHECK(yaesu::decode(yaesu::sat_mode_on()).kind == K::sat_on);
  CHECK(yaesu::decode(yaesu::sat_mode_off()).kind == K::sat_off);
  auto d = yaesu::decode({0xC9, 0x61, 0x23, 0x45, 0x01});
  CHECK(d.kind == K::frequency);
  CHECK(d.target == yaesu::Target::main);
  CHECK(d.hz == 1296123450);
  auto t = yaesu::decode({0x14, 0x59, 0x50, 0x00, 0x2E});
  CHECK(t.target == yaesu::Target::sat_tx);
  CHECK(t.hz == 145950000);
  auto m = yaesu::decode({0x88, 0x00, 0x00, 0x00, 0x17});
  CHECK(m.kind == K::mode);
  CHECK(m.target == yaesu::Target::sat_rx);
  CHECK(m.mode_code == 0x88);
  CHECK(m.mode == Mode::fm);
  for (Hz hz : {Hz{0}, Hz{144'000'000}, Hz{999'999'990}, Hz{1'200'000'000}, Hz{1'299'999'990}}) {
    auto back = yaesu::decode(yaesu::set_frequency(yaesu::Target::sat_rx, hz));
    CHECK(back.kind == K::frequency);
    CHECK(back.hz == hz);
  }
}

TEST_CASE("BCD helpers") {
  CHECK(to_hex(bcd_little_endian(1234567890, 5)) == "90 78 56 34 12");
  CHECK(to_hex(bcd_big_endian(12345678, 4)) == "12 34 56 78");
  CHECK(decode_bcd_little_endian(*from_hex("90 78 56 34 12")) == 1234567890u);
  CHECK(decode_bcd_big_endian(*from_hex("12 34 56 78")) == 12345678u);
  CHECK_FALSE(decode_bcd_little_endian(*from_hex("0A")));
}
