#include <doctest/doctest.h>
#include "test_paths.h"  // TRAKBOX_SOURCE_DIR, ...

#include <fstream>
#include <sstream>

#include "rotator/adc_model.h"
#include "store/model.h"
#include "store/station_file.h"
#include "store/station_file_model.h"
#include "station_file_problems.h"
#include "support/manual_samples.h"

using namespace tb;
using store::parse_station_file;

namespace {
const char* const kSample = testing::kManualStationFile;

using testing::problems_text;
}  // namespace

TEST_CASE("The manual's sample station file") {
  const auto r = parse_station_file(kSample);
  INFO(problems_text(r));
  REQUIRE(r.ok());
  const store::StationFile& f = *r.file;
  CHECK(f.station.callsign == "WA7GXD");
  CHECK(f.station.lat_deg == 32.259);
  CHECK(f.station.lon_deg == -110.778);
  CHECK(f.station.height_m == 842.0);
  CHECK(f.station.rotor_start == station::RotorStart::south);
  CHECK(f.rotator.az_span == rotator::AxisSpan{3, 1017});
  CHECK(f.rotator.el_span == rotator::AxisSpan{5, 454});
  CHECK(f.rotator.az_dead_band == 5);
  CHECK(f.rotator.el_dead_band == 3);
  CHECK(f.rotator.az_skew == 0);
  CHECK(f.rotator.el_skew == 0);
  CHECK(f.radio.rig == radio::Rig::icom);
  CHECK(f.radio.cat_policy == radio::CatPolicy::aos_only);
  CHECK(f.radio.icom_rx_address == 0x10);
  CHECK(f.radio.icom_tx_address == 0x14);
  CHECK(f.rotator.parking_enabled);
  CHECK(f.rotator.parking == rotator::AzEl{90.0, 0.0});
  CHECK(testing::limits_of(f.rotator) == std::tuple(true, 270.0, 90.0, 0.0, 45.0));
}

TEST_CASE("The shipped data/station.txt is the manual's sample") {
  std::ifstream in(TRAKBOX_SOURCE_DIR "/data/station.txt");
  std::stringstream ss;
  ss << in.rdbuf();
  const auto r = parse_station_file(ss.str());
  REQUIRE(r.ok());
  CHECK(*r.file == *parse_station_file(kSample).file);
}

TEST_CASE("Applying the sample: line 5 in degrees gives the northern half for a South-start rotator") {
  store::Model m = store::factory_defaults();
  m.station.com_baud = 4800;
  const auto r = parse_station_file(kSample);
  REQUIRE(r.ok());
  CHECK(store::apply_station_file(*r.file, m).empty());
  CHECK(m.station.callsign == "WA7GXD");
  CHECK(m.station.com_baud == 4800);  // not in the file
  CHECK(m.rotator.az_span == rotator::AxisSpan{3, 1017});
  CHECK(m.rotator.parking_enabled);
  CHECK(m.rotator.limits_enabled);
  CHECK(m.radio.rig == radio::Rig::icom);
  CHECK(m.radio.icom_rx_address == 0x10);
  // The limits 270 -> 90 clockwise: the northern half, travel 90..270 from the south stop.
  rotator::AdcModel model(m.rotator, m.station.rotor_start);
  const rotator::Range travel = model.az_travel_range();
  CHECK(travel.lo == doctest::Approx(90.0));
  CHECK(travel.hi == doctest::Approx(270.0));
  CHECK(model.el_range().hi == doctest::Approx(45.0));
  // Parking at 90/0 lies inside them.
  const auto park = model.target_for(m.rotator.parking, 180.0);
  CHECK(model.compass_from_travel(park.az_travel) == doctest::Approx(90.0));
}

TEST_CASE("Writing a model and reading it back") {
  store::Model m = store::factory_defaults();
  const auto r = parse_station_file(kSample);
  REQUIRE(store::apply_station_file(*r.file, m).empty());
  const std::string text = store::write_station_file(m);
  CHECK(text ==
        "1 WA7GXD 32.259 -110.778 842 S\n2 3 1017 5 454\n3 5 3 0 0\n4 ICOM A 10 14\n5 1 90 0 1 270 90 0 45\n");
  const auto back = parse_station_file(text);
  REQUIRE(back.ok());
  CHECK(*back.file == *r.file);
  // The factory model round-trips too.
  const store::Model d = store::factory_defaults();
  const auto fd = parse_station_file(store::write_station_file(d));
  INFO(problems_text(fd));
  REQUIRE(fd.ok());
  store::Model d2 = d;
  CHECK(store::apply_station_file(*fd.file, d2).empty());
  CHECK(d2.station.callsign == d.station.callsign);
  CHECK(d2.rotator == d.rotator);
  CHECK(d2.radio == d.radio);
}

TEST_CASE("Separators, line ends, blank lines, Ctrl-Z and other spellings") {
  const auto r = parse_station_file(
      "1\twa7gxd\t32.259  -110.778 842 south\n\n2 3 1017 5 454\r3 5 3 -4 +2\n4 kenwood F\n"
      "5 0 0 0 OFF 0 360 0 90\n\x1agarbage after the end");
  INFO(problems_text(r));
  REQUIRE(r.ok());
  CHECK(r.file->station.callsign == "WA7GXD");
  CHECK(r.file->rotator.az_skew == -4);
  CHECK(r.file->rotator.el_skew == 2);
  CHECK(r.file->radio.rig == radio::Rig::kenwood);
  CHECK(r.file->radio.cat_policy == radio::CatPolicy::full_orbit);
  CHECK(!r.file->rotator.limits_enabled);
  // Icom addresses may carry the manual's H.
  const auto h = parse_station_file("1 N0CALL 0 0 0 N\n2 0 1023 0 511\n3 3 1 0 0\n4 I A 2EH 14h\n5 0 0 0 0 0 360 0 90\n");
  REQUIRE(h.ok());
  CHECK(h.file->radio.icom_rx_address == 0x2E);
  CHECK(h.file->radio.icom_tx_address == 0x14);
  CHECK(h.file->station.rotor_start == station::RotorStart::north);
}

TEST_CASE("An error on line 4 is reported with line, item, found and expected") {
  const auto r = parse_station_file(
      "1 WA7GXD 32.259 -110.778 842 S\n2 3 1017 5 454\n3 5 3 0 0\n4 ICOM X 10 1G\n5 1 90 0 1 270 90 0 45\n");
  CHECK(!r.ok());
  CHECK(!r.file);
  REQUIRE(r.problems.size() == 2);
  CHECK(r.problems[0].line == 4);
  CHECK(r.problems[0].field == 3);
  CHECK(r.problems[0].what == "F/A");
  CHECK(r.problems[0].message() == "line 4, item 3 (F/A): found \"X\", expected F (full orbit) or A (AOS only)");
  CHECK(r.problems[1].field == 5);
  CHECK(r.problems[1].what == "Icom TX address");
  CHECK(r.problems[1].found == "1G");
}

TEST_CASE("Every problem of the file, in line order") {
  const auto r = parse_station_file(
      "1 WA7GXD 95 -110.778 842 W\n"   // latitude, rotor start
      "2 3 1030 5 10\n"                // az max > 1023, el max too close to min
      "3 5 3 0\n"                      // elevation skew missing
      "4 ICOM A\n"                     // Icom without addresses
      "5 1 90 0 1 270 1017 0 45 7\n");  // az max in counts, an extra item
  INFO(problems_text(r));
  REQUIRE(r.problems.size() == 8);
  auto at = [&](std::size_t i) { return std::pair{r.problems[i].line, r.problems[i].field}; };
  CHECK(at(0) == std::pair{1, 3});
  CHECK(at(1) == std::pair{1, 6});
  CHECK(at(2) == std::pair{2, 3});
  CHECK(r.problems[2].expected == "ADC counts 0 to 1023");
  CHECK(at(3) == std::pair{2, 5});
  CHECK(r.problems[3].expected.find("at least 15") == 0);
  CHECK(at(4) == std::pair{3, 5});
  CHECK(r.problems[4].found.empty());
  CHECK(r.problems[4].message() ==
        "line 3, item 5 (elevation skew): found nothing, expected a value for elevation skew (line 3 has 5 items)");
  CHECK(at(5) == std::pair{4, 4});
  CHECK(at(6) == std::pair{5, 7});
  CHECK(r.problems[6].expected == "degrees 0 to 360 (line 5 is in degrees, not ADC counts)");
  CHECK(at(7) == std::pair{5, 10});
  CHECK(r.problems[7].what == "extra item");
}

TEST_CASE("Line numbers come first and in order; missing and extra lines") {
  SUBCASE("out of order") {
    const auto r = parse_station_file("1 A 0 0 0 S\n3 5 3 0 0\n2 3 1017 5 454\n4 NONE A\n5 0 0 0 0 0 360 0 90\n");
    REQUIRE(r.problems.size() == 2);
    CHECK(r.problems[0].line == 2);
    CHECK(r.problems[0].field == 1);
    CHECK(r.problems[0].found == "3");
    CHECK(r.problems[0].expected.find("line number 2 here") == 0);
    CHECK(r.problems[1].line == 3);
  }
  SUBCASE("no line numbers") {
    const auto r = parse_station_file("WA7GXD 32.259 -110.778 842 S\n");
    REQUIRE(r.problems.size() == 5);  // the number, then lines 2 to 5 missing
    CHECK(r.problems[0].message() ==
          "line 1, item 1 (line number): found \"WA7GXD\", expected the line number 1 first (lines 1 to 5, in order)");
    CHECK(r.problems[1].line == 0);
    CHECK(r.problems[1].message().find("line 2 (ADC span") != std::string::npos);
  }
  SUBCASE("a line missing, the file short") {
    const auto r = parse_station_file("1 A 0 0 0 S\n2 3 1017 5 454\n3 5 3 0 0\n");
    REQUIRE(r.problems.size() == 2);
    CHECK(r.problems[0].expected.find("line 4 (CAT rig") == 0);
    CHECK(r.problems[1].expected.find("line 5 (parking") == 0);
  }
  SUBCASE("six lines") {
    const auto r = parse_station_file(std::string(kSample) + "6 1 2 3\n");
    REQUIRE(r.problems.size() == 1);
    CHECK(r.problems[0].line == 6);
    CHECK(r.problems[0].expected == "nothing more: the station file has five lines");
  }
  SUBCASE("a line twice") {
    const auto r = parse_station_file("1 A 0 0 0 S\n1 A 0 0 0 S\n");
    CHECK(r.problems[0].line == 2);
    CHECK(r.problems[0].expected.find("line number 2 here") == 0);
    CHECK(r.problems[1].expected.find("each line once") == 0);
  }
  SUBCASE("empty") {
    const auto r = parse_station_file("\x1a");
    CHECK(r.problems.size() == 5);
  }
}

TEST_CASE("Edge values of each line") {
  auto file = [](std::string l2, std::string l3, std::string l5) {
    return "1 A 0 0 0 S\n" + l2 + "\n" + l3 + "\n4 YAESU A\n" + l5 + "\n";
  };
  CHECK(parse_station_file(file("2 0 1023 0 1023", "3 0 0 -512 512", "5 1 360 90 1 0 360 90 90")).ok());
  CHECK(parse_station_file(file("2 0 10 0 10", "3 100 100 0 0", "5 0 0 0 0 0 360 0 0")).ok());
  CHECK(!parse_station_file(file("2 0 9 0 10", "3 0 0 0 0", "5 0 0 0 0 0 360 0 90")).ok());     // span 9 wide
  CHECK(!parse_station_file(file("2 -1 1023 0 511", "3 0 0 0 0", "5 0 0 0 0 0 360 0 90")).ok()); // below 0
  CHECK(!parse_station_file(file("2 0 1023 0 511", "3 101 0 0 0", "5 0 0 0 0 0 360 0 90")).ok()); // dead band
  CHECK(!parse_station_file(file("2 0 1023 0 511", "3 0 0 513 0", "5 0 0 0 0 0 360 0 90")).ok()); // skew
  CHECK(!parse_station_file(file("2 0 1023 0 511", "3 0 0 0 0", "5 2 0 0 0 0 360 0 90")).ok());   // flag
  CHECK(!parse_station_file(file("2 0 1023 0 511", "3 0 0 0 0", "5 0 0 91 0 0 360 0 90")).ok());  // park el
  CHECK(!parse_station_file(file("2 0 1023 0 511", "3 0 0 0 0", "5 0 0 0 1 90 90 0 90")).ok());   // same az
  CHECK(!parse_station_file(file("2 0 1023 0 511", "3 0 0 0 0", "5 0 0 0 1 0 360 50 40")).ok());  // el max < min
  CHECK(!parse_station_file(file("2 0 1023 0 511", "3 1.5 0 0 0", "5 0 0 0 0 0 360 0 90")).ok()); // not whole
  // Icom addresses: E0 is the controller's own.
  CHECK(!parse_station_file("1 A 0 0 0 S\n2 0 1023 0 511\n3 0 0 0 0\n4 ICOM A E0 10\n5 0 0 0 0 0 360 0 90\n").ok());
  CHECK(parse_station_file("1 A 0 0 0 S\n2 0 1023 0 511\n3 0 0 0 0\n4 ICOM A DF 00\n5 0 0 0 0 0 360 0 90\n").ok());
  // A callsign of 11 characters.
  CHECK(!parse_station_file("1 ABCDEFGHIJK 0 0 0 S\n2 0 1023 0 511\n3 0 0 0 0\n4 N A\n5 0 0 0 0 0 360 0 90\n").ok());
}

TEST_CASE("apply refuses what rotator::validate refuses and leaves the model alone") {
  // Skew that pushes the whole elevation span outside the ADC leaves nowhere to go.
  const auto r = parse_station_file("1 A 0 0 0 S\n2 0 1023 1000 1023\n3 0 0 0 512\n4 N A\n5 0 0 0 0 0 360 0 90\n");
  REQUIRE(r.ok());
  store::Model m = store::factory_defaults();
  const store::Model before = m;
  const auto problems = store::apply_station_file(*r.file, m);
  CHECK(!problems.empty());
  CHECK(m.rotator == before.rotator);
  CHECK(m.station.callsign == before.station.callsign);
}

TEST_CASE("An Icom address with a sign is refused, not wrapped into the address byte") {
  // Found by fuzzing: from_chars took the '-', so "-4" became FC (the CI-V jam code), which the file
  // written back and the state document then refused.
  const auto r = parse_station_file("1 A 0 0 0 S\n2 0 1023 0 511\n3 0 0 0 0\n4 ICOM A 10 -4\n5 0 0 0 0 0 360 0 90\n");
  CHECK(!r.ok());
  CHECK(!r.file);
  REQUIRE(r.problems.size() == 1);
  CHECK(r.problems[0].message() ==
        "line 4, item 5 (Icom TX address): found \"-4\", expected a CI-V address in hex, 00 to DF (e.g. 10 for an "
        "IC-275, 14 for an IC-475; E0 is TrakBox's own)");
  CHECK(!parse_station_file("1 A 0 0 0 S\n2 0 1023 0 511\n3 0 0 0 0\n4 ICOM A -0 10\n5 0 0 0 0 0 360 0 90\n").ok());
  CHECK(!parse_station_file("1 A 0 0 0 S\n2 0 1023 0 511\n3 0 0 0 0\n4 ICOM A +1 10\n5 0 0 0 0 0 360 0 90\n").ok());
}
