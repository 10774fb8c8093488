// The later TrakBox firmware's FREQ.DAT (v3.20d-3.50b) through the same parser as the 1994 file.
// The files in tests/data/firmware/ were written from the format description
// of the later firmware's files (docs/radio.md, "Two items of the later firmware's files").
#include <doctest/doctest.h>
#include "support/data_files.h"

#include <string>

#include "radio/freqmode.h"

using namespace tb::radio;

namespace {

std::string read_data(const char* name) { return tb::testing::read_test_data(std::string("firmware/") + name); }

std::string problems_text(const FreqModeParse& p) {
  std::string s;
  for (const auto& q : p.problems) s += q.message() + "\n";
  return s;
}

}  // namespace

TEST_CASE("FREQ.DAT: comments, four uplinks, offsets on either link, none, cw, ir/kr") {
  const auto p = parse_freqmode(read_data("FREQ.DAT"));
  INFO(problems_text(p));
  REQUIRE(p.ok());
  REQUIRE(p.records.size() == 8);

  const FreqModeRecord& iss = p.records[0];
  CHECK(iss.line == 6);  // after four comment lines and a blank one
  CHECK(iss.name == "ISS");
  CHECK(iss.radio.downlink_hz == 437'800'000);
  CHECK(iss.radio.uplink_hz == 145'990'000);
  CHECK(iss.radio.alternate_uplinks_hz == std::vector<Hz>{145'825'000, 145'800'000, 437'800'000});
  CHECK(iss.radio.reverse == ReverseAssignment::icom_main_sub);
  CHECK(iss.radio.downlink_mode == Mode::fm);
  CHECK(iss.radio.doppler == DopplerControl::cat);
  CHECK_FALSE(iss.radio.lcd_ma_display);

  const SatelliteRadio& fo29 = p.records[1].radio;
  CHECK(fo29.uplink_hz == 145'950'000);
  CHECK(fo29.alternate_uplinks_hz == std::vector<Hz>{145'960'000, 145'970'000, 145'980'000});
  CHECK(fo29.reverse == ReverseAssignment::kenwood_vfo);
  CHECK(fo29.downlink_mode == Mode::usb);
  CHECK(fo29.uplink_mode == Mode::lsb);

  // QO-100 through an LNB (9750 MHz LO) and a 432 -> 2400 MHz up-converter: offsets on both links.
  const SatelliteRadio& qo = p.records[2].radio;
  CHECK(p.records[2].name == "QO-100");
  CHECK(qo.downlink_hz == 10'489'550'000);
  CHECK(qo.downlink_offset_hz == -9'750'000'000);
  CHECK(qo.downlink_hz + qo.downlink_offset_hz == 739'550'000);
  CHECK(qo.uplink_hz == 2'400'050'000);
  CHECK(qo.uplink_offset_hz == -1'968'000'000);
  CHECK(qo.uplink_hz + qo.uplink_offset_hz == 432'050'000);
  CHECK(qo.alternate_uplinks_hz.empty());
  CHECK(qo.reverse == ReverseAssignment::none);

  // A 1994 seven-field line in the same file.
  const SatelliteRadio& ao7 = p.records[3].radio;
  CHECK(ao7.doppler == DopplerControl::mic_click);
  CHECK(ao7.lcd_ma_display);
  CHECK(ao7.alternate_uplinks_hz.empty());

  // The offset after the last of several uplinks applies to them all: 1268.1 -> 144.1 MHz.
  const SatelliteRadio& ao91 = p.records[4].radio;
  CHECK(ao91.uplink_hz == 1'268'100'000);
  CHECK(ao91.alternate_uplinks_hz == std::vector<Hz>{1'268'200'000});
  CHECK(ao91.uplink_offset_hz == -1'124'000'000);

  const SatelliteRadio& jo97 = p.records[5].radio;  // the comment line before it is skipped
  CHECK(p.records[5].line == 12);
  CHECK(jo97.uplink_hz == 0);
  CHECK_FALSE(jo97.has_uplink());
  CHECK(jo97.uplink_mode == Mode::none);

  CHECK(p.records[6].radio.downlink_mode == Mode::cw);
  CHECK(p.records[7].name == "RS-44");
}

TEST_CASE("FREQ.DAT: every broken line is reported by number with the reason; the others load") {
  const auto p = parse_freqmode(read_data("FREQ_BAD.DAT"));
  REQUIRE(p.records.size() == 2);
  CHECK(p.records[0].name == "ISS");
  CHECK(p.records[1].name == "AO-91");
  CHECK(p.records[1].line == 10);
  REQUIRE(p.problems.size() == 6);
  CHECK(p.problems[0].message() ==
        "line 3, field 3 (uplink frequency): found \"145.950,145.960,145.970,145.980,145.990\", expected a "
        "frequency in MHz such as 145.900, up to 4 separated by commas (no spaces), optionally with a converter "
        "offset after the last as in 1268.100,1268.200/-1124.000");
  CHECK(p.problems[1].line == 4);
  CHECK(p.problems[1].field == 3);
  CHECK(p.problems[1].found == "145.850,");
  CHECK(p.problems[2].message() ==
        "line 5, field 8 (reverse flag): found \"xr\", expected ir (Icom main/sub reversed), kr (Kenwood VFOs "
        "reversed) or nothing");
  CHECK(p.problems[3].message() == "line 6, field 5 (uplink mode): found \"am\", expected usb, lsb, fm, cw or none");
  CHECK(p.problems[4].line == 8);
  CHECK(p.problems[4].field == 0);
  CHECK(p.problems[4].found == "9 fields");
  CHECK(p.problems[5].line == 9);
  CHECK(p.problems[5].field == 3);
  CHECK(p.problems[5].found == "2400.050/");
}

TEST_CASE("The uplink field: one to four channels, one offset after the last") {
  auto u = parse_uplink_field("145.950,145.960,145.970,145.980");
  REQUIRE(u);
  CHECK(u->rf_hz == std::vector<Hz>{145'950'000, 145'960'000, 145'970'000, 145'980'000});
  CHECK(u->offset_hz == 0);
  u = parse_uplink_field("2400.050/-1968.000");
  REQUIRE(u);
  CHECK(u->rf_hz == std::vector<Hz>{2'400'050'000});
  CHECK(u->offset_hz == -1'968'000'000);
  CHECK_FALSE(parse_uplink_field("1,2,3,4,5"));       // five channels
  CHECK_FALSE(parse_uplink_field("145.9,,145.8"));    // an empty channel
  CHECK_FALSE(parse_uplink_field(",145.9"));
  CHECK_FALSE(parse_uplink_field("145.9,-145.8"));    // negative RF
  CHECK_FALSE(parse_uplink_field("145.9/"));          // empty offset
  CHECK_FALSE(parse_uplink_field("145.9,145.8/1/2"));
  CHECK_FALSE(parse_uplink_field(""));
}

TEST_CASE("Comments and blank lines: CR LF, tabs, Ctrl-Z; a ';' inside a line is not a comment") {
  const auto p = parse_freqmode(";c1\r\n\r\n\t; c2\r\nFO-29\t435.850\t145.950,145.960\tusb\tlsb\tcat\tno\tKR\r\n\x1a"
                                "; after the end\nnot read\n");
  INFO(problems_text(p));
  REQUIRE(p.ok());
  REQUIRE(p.records.size() == 1);
  CHECK(p.records[0].line == 4);
  CHECK(p.records[0].radio.reverse == ReverseAssignment::kenwood_vfo);  // case-insensitive like the modes
  const auto q = parse_freqmode("AO-07 145.950 432.150 usb lsb mic ma ;note\n");
  REQUIRE(q.problems.size() == 1);
  CHECK(q.problems[0].field == 8);
  CHECK(q.problems[0].found == ";note");
}

TEST_CASE("The writer gives the later form back: alternatives, offset after the last, ir/kr") {
  const std::string text = read_data("FREQ.DAT");
  const auto p = parse_freqmode(text);
  REQUIRE(p.ok());
  const std::string written = write_freqmode(p.records);
  CHECK(written ==
        "ISS 437.800 145.990,145.825,145.800,437.800 fm fm cat no ir\n"
        "FO-29 435.850 145.950,145.960,145.970,145.980 usb lsb cat no kr\n"
        "QO-100 10489.550/-9750.000 2400.050/-1968.000 usb usb cat no\n"
        "AO-07 145.950 432.150 usb lsb mic ma\n"
        "AO-91 145.960 1268.100,1268.200/-1124.000 fm fm cat no\n"
        "JO-97 145.855 0.000 usb none cat no\n"
        "HO-113 435.165 145.875 cw lsb cat ma\n"
        "RS-44 435.640 145.965 usb lsb cat no\n");
  const auto again = parse_freqmode(written);
  REQUIRE(again.ok());
  REQUIRE(again.records.size() == p.records.size());
  for (std::size_t i = 0; i < p.records.size(); ++i) {
    CHECK(again.records[i].name == p.records[i].name);
    CHECK(again.records[i].radio == p.records[i].radio);
  }
}

TEST_CASE("Alternative uplinks: each step takes the next channel and goes round all of them") {
  SatelliteRadio r;
  r.uplink_hz = 145'935'000;
  r.alternate_uplinks_hz = {145'945'000, 145'955'000};
  CHECK(r.next_uplink());
  CHECK(r.uplink_hz == 145'945'000);
  CHECK(r.alternate_uplinks_hz == std::vector<Hz>{145'955'000, 145'935'000});
  CHECK(r.next_uplink());
  CHECK(r.uplink_hz == 145'955'000);
  CHECK(r.next_uplink());
  CHECK(r.uplink_hz == 145'935'000);  // round again
  SatelliteRadio one;
  one.uplink_hz = 145'990'000;
  CHECK_FALSE(one.next_uplink());
  CHECK(one.uplink_hz == 145'990'000);
}
