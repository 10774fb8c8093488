#include <doctest/doctest.h>

#include <string>

#include "radio/freqmode.h"

using namespace tb::radio;

namespace {

// The manual's sample (menu 3-3), one record per line as the text describes; the printed manual
// lost the line ends.
const char* kManualSample =
    "UO-22A 435.120 145.900 fm fm cat no\n"
    "UO-22B 435.120 145.975 fm fm cat no\n"
    "KO-23A 435.176 145.850 fm fm cat no\n"
    "AO-21 145.987 435.016 fm fm mic no\n"
    "AO-13B 145.900 435.500 usb lsb mic ma\n"
    "AO-16 437.025 145.940 usb fm mic no\n"
    "DO-17 145.825 435.000 fm none cat no\n"
    "WO-18 435.075 145.000 usb none cat no\n"
    "LO-19 437.125 145.840 usb fm mic no\n"
    "FO-20A 435.910 145.850 usb fm cat no\n"
    "FO-20B 435.910 145.870 usb fm cat no\n"
    "AO-13L 435.850 144.500 usb lsb mic ma\n"
    "AO-13S 2400.730/-2256.000 435.620 usb lsb mic ma\n"
    "AO-10 145.900 435.100 usb lsb mic ma\n"
    "STS-47 145.550 435.000 fm fm cat no\n"
    "KO-23B 435.176 145.900 fm fm cat no\n";

// As printed (OCR flattened it onto one line).
const char* kManualSampleFlattened =
    "UO-22A 435.120 145.900 fm fm cat no UO-22B 435.120 145.975 fm fm cat no KO-23A 435.176 "
    "145.850 fm fm cat no AO-21 145.987 435.016 fm fm mic no AO-13B 145.900 435.500 usb lsb mic "
    "ma AO-16 437.025 145.940 usb fm mic no DO-17 145.825 435.000 fm none cat no WO-18 435.075 "
    "145.000 usb none cat no LO-19 437.125 145.840 usb fm mic no FO-20A 435.910 145.850 usb fm "
    "cat no FO-20B 435.910 145.870 usb fm cat no AO-13L 435.850 144.500 usb lsb mic ma AO-13S "
    "2400.730/-2256.000 435.620 usb lsb mic ma AO-10 145.900 435.100 usb lsb mic ma STS-47 "
    "145.550 435.000 fm fm cat no KO-23B 435.176 145.900 fm fm cat no";

}  // namespace

TEST_CASE("Decimal MHz to Hz exactly") {
  CHECK(parse_mhz("435.120") == 435'120'000);
  CHECK(parse_mhz("435.12345") == 435'123'450);
  CHECK(parse_mhz("435.123456") == 435'123'456);
  CHECK(parse_mhz("145.9") == 145'900'000);
  CHECK(parse_mhz("145") == 145'000'000);
  CHECK(parse_mhz("-2256.000") == -2'256'000'000);
  CHECK(parse_mhz("+0.5") == 500'000);
  CHECK(parse_mhz(".5") == 500'000);
  CHECK(parse_mhz("10368.1000000") == 10'368'100'000);   // zeros past 1 Hz are fine
  // 0.1 + 0.2 style surprises cannot happen: every digit is taken as written.
  CHECK(parse_mhz("145.979999") == 145'979'999);
  CHECK(parse_mhz("2400.730") == 2'400'730'000);
  CHECK_FALSE(parse_mhz("145.9999999"));   // finer than 1 Hz
  CHECK_FALSE(parse_mhz(""));
  CHECK_FALSE(parse_mhz("."));
  CHECK_FALSE(parse_mhz("-"));
  CHECK_FALSE(parse_mhz("14x.9"));
  CHECK_FALSE(parse_mhz("1.2.3"));
  CHECK_FALSE(parse_mhz("12345678.0"));
}

TEST_CASE("Frequency field with a converter offset") {
  auto f = parse_frequency_field("2400.730/-2256.000");
  REQUIRE(f);
  CHECK(f->rf_hz == 2'400'730'000);
  CHECK(f->offset_hz == -2'256'000'000);
  CHECK(f->rf_hz + f->offset_hz == 144'730'000);
  auto g = parse_frequency_field("435.620");
  REQUIRE(g);
  CHECK(g->offset_hz == 0);
  CHECK(parse_frequency_field("1268.000/+116.0")->offset_hz == 116'000'000);
  CHECK_FALSE(parse_frequency_field("-435.0"));
  CHECK_FALSE(parse_frequency_field("2400.730/"));
  CHECK_FALSE(parse_frequency_field("/-2256"));
  CHECK_FALSE(parse_frequency_field("2400.730/-2256/1"));
}

TEST_CASE("The manual's sample file: all 16 records") {
  auto p = parse_freqmode(kManualSample);
  CHECK(p.ok());
  REQUIRE(p.records.size() == 16);
  CHECK(p.records[0].name == "UO-22A");
  CHECK(p.records[0].line == 1);
  CHECK(p.records[0].radio.downlink_hz == 435'120'000);
  CHECK(p.records[0].radio.uplink_hz == 145'900'000);
  CHECK(p.records[0].radio.downlink_mode == Mode::fm);
  CHECK(p.records[0].radio.doppler == DopplerControl::cat);
  CHECK_FALSE(p.records[0].radio.lcd_ma_display);

  const auto& ao21 = p.records[3];
  CHECK(ao21.name == "AO-21");
  CHECK(ao21.radio.downlink_hz == 145'987'000);
  CHECK(ao21.radio.uplink_hz == 435'016'000);
  CHECK(ao21.radio.doppler == DopplerControl::mic_click);

  const auto& do17 = p.records[6];
  CHECK(do17.radio.uplink_mode == Mode::none);
  CHECK(do17.radio.uplink_hz == 435'000'000);   // the manual's dummy value

  const auto& ao13s = p.records[12];
  CHECK(ao13s.name == "AO-13S");
  CHECK(ao13s.line == 13);
  CHECK(ao13s.radio.downlink_hz == 2'400'730'000);
  CHECK(ao13s.radio.downlink_offset_hz == -2'256'000'000);
  CHECK(ao13s.radio.uplink_hz == 435'620'000);
  CHECK(ao13s.radio.uplink_offset_hz == 0);
  CHECK(ao13s.radio.downlink_mode == Mode::usb);
  CHECK(ao13s.radio.uplink_mode == Mode::lsb);
  CHECK(ao13s.radio.doppler == DopplerControl::mic_click);
  CHECK(ao13s.radio.lcd_ma_display);

  CHECK(p.records[15].name == "KO-23B");
  int mic = 0, ma = 0;
  for (const auto& r : p.records) {
    mic += r.radio.doppler == DopplerControl::mic_click;
    ma += r.radio.lcd_ma_display;
  }
  CHECK(mic == 7);
  CHECK(ma == 4);
}

TEST_CASE("The sample as printed on one line is reported, not guessed at") {
  auto p = parse_freqmode(kManualSampleFlattened);
  CHECK(p.records.empty());
  REQUIRE(p.problems.size() == 1);
  CHECK(p.problems[0].line == 1);
  CHECK(p.problems[0].field == 0);
  CHECK(p.problems[0].found == "112 fields");
  CHECK(p.problems[0].expected.find("16 records") != std::string::npos);
}

TEST_CASE("CR, LF and CR LF line ends; Ctrl-Z ends the upload; blank lines skipped") {
  auto p = parse_freqmode("A 1 2 fm fm cat no\r\rB 3 4 usb lsb mic ma\r\nC 5 6 none none cat no\n"
                          "\x1a" "garbage after the end");
  CHECK(p.ok());
  REQUIRE(p.records.size() == 3);
  CHECK(p.records[1].name == "B");
  CHECK(p.records[1].line == 3);
  CHECK(p.records[2].line == 4);
  auto tabs = parse_freqmode("  AO-10\t145.900  435.100 USB LSB MIC MA  \n");
  CHECK(tabs.ok());
  CHECK(tabs.records.at(0).radio.downlink_mode == Mode::usb);
}

TEST_CASE("Problems name the line, the field, what was found and what is expected") {
  const char* text =
      "UO-22A 435.120 145.900 fm fm cat no\n"
      "KO-23A 435,176 145.850 fm fm cat no\n"      // comma
      "AO-21 145.987 435.016 fm am mic no\n"       // AM is not a file mode
      "AO-16 437.025 145.940 usb fm click no\n"    // doppler
      "LO-19 437.125 145.840 usb fm mic yes\n"     // phase
      "FO-20 435.910 145.850 usb fm cat\n"         // six fields
      "UO-22A 435.120 145.975 fm fm cat no\n"      // name again
      "AO-13S 2400.730/-2256.0000001 435.620 am lsb mic ma\n";  // two problems
  auto p = parse_freqmode(text);
  REQUIRE(p.records.size() == 1);   // only the good line
  CHECK(p.records[0].name == "UO-22A");
  REQUIRE(p.problems.size() == 8);
  CHECK(p.problems[0].line == 2);
  CHECK(p.problems[0].field == 2);
  CHECK(p.problems[0].found == "435,176");
  CHECK(p.problems[0].message() ==
        "line 2, field 2 (downlink frequency): found \"435,176\", expected a frequency in MHz such "
        "as 435.120, optionally with a converter offset as in 2400.730/-2256.000");
  CHECK(p.problems[1].line == 3);
  CHECK(p.problems[1].field == 5);
  CHECK(p.problems[1].expected == "usb, lsb, fm, cw or none");  // cw: the later firmware's FREQ.DAT
  CHECK(p.problems[2].field == 6);
  CHECK(p.problems[2].expected == "cat or mic");
  CHECK(p.problems[3].field == 7);
  CHECK(p.problems[3].expected == "ma or no");
  CHECK(p.problems[4].line == 6);
  CHECK(p.problems[4].field == 0);
  CHECK(p.problems[4].found == "6 fields");
  CHECK(p.problems[5].line == 7);
  CHECK(p.problems[5].field == 1);
  CHECK(p.problems[5].expected.find("line 1") != std::string::npos);
  CHECK(p.problems[6].line == 8);
  CHECK(p.problems[6].field == 2);
  CHECK(p.problems[7].field == 4);
  CHECK(p.problems[7].found == "am");
}

TEST_CASE("Names are case-sensitive") {
  auto p = parse_freqmode("ao-13 145.9 435.5 usb lsb mic ma\nAO-13 145.9 435.5 usb lsb mic ma\n");
  CHECK(p.ok());
  CHECK(p.records.size() == 2);
}

TEST_CASE("Writer: formats MHz exactly and reads back to the same records") {
  CHECK(format_mhz(435'120'000) == "435.120");
  CHECK(format_mhz(435'123'450) == "435.12345");
  CHECK(format_mhz(435'123'456) == "435.123456");
  CHECK(format_mhz(-2'256'000'000) == "-2256.000");
  CHECK(format_mhz(0) == "0.000");
  CHECK(format_frequency_field(2'400'730'000, -2'256'000'000) == "2400.730/-2256.000");
  auto p = parse_freqmode(kManualSample);
  REQUIRE(p.ok());
  const std::string written = write_freqmode(p.records);
  CHECK(written == kManualSample);   // the sample is already in canonical form
  auto again = parse_freqmode(written);
  CHECK(again.records == p.records);
  FreqModeRecord r{0, "X-1", {}, {}, 0};
  r.radio.downlink_hz = 10'368'123'456;
  r.radio.downlink_offset_hz = -10'224'000'000;
  r.radio.uplink_mode = Mode::fm;
  CHECK(format_freqmode_line(r) == "X-1 10368.123456/-10224.000 0.000 none fm cat no");
}
