#include <doctest/doctest.h>
#include "test_paths.h"  // TRAKBOX_SOURCE_DIR, ...

#include "store/database.h"
#include "support/shipped_model.h"

using namespace tb;
using namespace tb::store;

namespace {
using tb::testing::read_file;
// Three sets; the second has its line-1 checksum spoiled (9 instead of 8 at column 69).
const char* kUpload =
    "AO-07\n"
    "1 07530U 74089B   26141.31992461 -.00000054  00000-0 -48931-4 0  9992\n"
    "2 07530 101.9910 154.2858 0012269 180.6108 191.1977 12.53697584357151\n"
    "SO-50\n"
    "1 27607U 02058C   26141.24923057  .00000576  00000-0  85866-4 0  9999\n"
    "2 27607  64.5520 212.3264 0075596 267.4106  91.8345 14.82983020260469\n"
    "RS-44\n"
    "1 44909U 19096E   26141.11069286  .00000018  00000-0  30335-4 0  9995\n"
    "2 44909  82.5230 357.7010 0216952 207.4466 151.5042 12.79748393298881\n";
}  // namespace

TEST_CASE("A kepele upload keeps the good sets and names each bad one with its line") {
  Database old;
  const auto parsed = orbit::parse_nasa(kUpload, "<upload>");
  const ElementsUpload up = build_elements_upload(old, parsed);
  CHECK(up.accepted == std::vector<std::string>{"AO-07", "RS-44"});
  REQUIRE(up.skipped.size() == 1);
  CHECK(up.skipped[0].find("<upload>:5") == 0);
  CHECK(up.skipped[0].find("checksum") != std::string::npos);
  CHECK(up.database.satellites.size() == 2);
  CHECK(up.database.selected == std::vector<int>{0, 1});
  CHECK(up.database.marked == 0);
  CHECK(old.satellites.empty());  // nothing was touched
}

TEST_CASE("Known satellites keep their radio entries across an upload; the database holds 32") {
  Database old;
  old.satellites.push_back({});
  old.satellites[0].elements.name = "RS-44";
  old.satellites[0].radio.downlink_hz = 435640000;
  const auto up = build_elements_upload(old, orbit::parse_nasa(kUpload, "<upload>"));
  CHECK(up.database.satellites[1].radio.downlink_hz == 435640000);

  orbit::ParseResult many;
  for (int i = 0; i < 34; ++i) {
    orbit::Elements e;
    e.name = "SAT-" + std::to_string(i);
    many.sets.push_back(e);
  }
  many.sets.push_back(many.sets[3]);  // a repeated name
  const auto big = build_elements_upload(Database{}, many);
  CHECK(big.database.satellites.size() == 32);
  CHECK(big.database.selected.size() == 15);
  CHECK(big.skipped.size() == 3);
  CHECK(big.skipped[0] == "SAT-32: the database holds 32 satellites, not taken");
  CHECK(big.skipped[2] == "SAT-3: the same name again (names must differ), not taken");
}

TEST_CASE("The freq/mode file updates by name and builds the list in its order") {
  auto up = build_elements_upload(Database{}, orbit::parse_nasa(kUpload, "<upload>"));
  const auto fm = radio::parse_freqmode("RS-44 435.640 145.965 usb lsb cat no\n"
                                        "UO-22 435.120 145.900 fm fm cat no\n"
                                        "AO-07 145.950 432.150 usb lsb mic ma\n");
  REQUIRE(fm.ok());
  const FreqModeUpload r = apply_freqmode(up.database, fm.records);
  CHECK(r.updated == std::vector<std::string>{"Satellite (RS-44) updated and selected as # 1",
                                              "Satellite (AO-07) updated and selected as # 2"});
  REQUIRE(r.skipped.size() == 1);
  CHECK(r.skipped[0] == "line 2: no satellite named (UO-22) in the database, not taken");
  CHECK(up.database.selected == std::vector<int>{1, 0});
  CHECK(up.database.satellites[0].radio.doppler == radio::DopplerControl::mic_click);
  CHECK(up.database.satellites[0].radio.lcd_ma_display);
  // Case matters: "rs-44" is not "RS-44".
  const auto lower = radio::parse_freqmode("rs-44 435.640 145.965 usb lsb cat no\n");
  CHECK(apply_freqmode(up.database, lower.records).updated.empty());
}

TEST_CASE("Menu 3-2 selection rules") {
  Database db;
  for (int i = 0; i < 20; ++i) {
    db.satellites.push_back({});
    db.satellites.back().elements.name = "S" + std::to_string(i);
  }
  CHECK(db.select(4) == 1);
  CHECK(db.select(2) == 2);
  CHECK(db.select(4) == 1);  // already listed
  CHECK(db.select(25) == 0);
  for (int i = 5; i < 20; ++i) db.select(i);
  CHECK(db.selected.size() == 15);
  CHECK(db.select(0) == 0);  // full
  CHECK(db.list_number(2) == 2);
  CHECK(db.listed(2)->name() == "S2");
  CHECK(db.listed(16) == nullptr);
}

TEST_CASE("The shipped default data makes a database") {
  const std::string dir = TRAKBOX_SOURCE_DIR "/data/";
  const auto sets = orbit::parse_nasa(read_file(dir + "amateur.tle"), "amateur.tle");
  CHECK(sets.problems.empty());
  const auto fm = radio::parse_freqmode(read_file(dir + "freqmode.txt"));
  CHECK(fm.ok());
  const Database db = make_database(sets.sets, fm.records);
  CHECK(db.satellites.size() == 20);
  CHECK(db.selected.size() == 14);
  CHECK(db.listed(1)->name() == "AO-07");
  const Satellite* qo = &db.satellites[static_cast<std::size_t>(*db.find("QO-100"))];
  CHECK(qo->radio.downlink_hz == 10489550000);
  CHECK(qo->radio.downlink_offset_hz == -9750000000);
  // The FM repeaters that need a tone open out of the box (issue 47; data/README.md names the sources).
  for (const auto& [name, tenths] : {std::pair{"SO-50", 670}, {"AO-91", 670}, {"ISS", 670}, {"PO-101", 1413}})
    CHECK(db.satellites[static_cast<std::size_t>(*db.find(name))].radio.ctcss_tenths_hz == tenths);
  CHECK(db.satellites[static_cast<std::size_t>(*db.find("AO-27"))].radio.ctcss_tenths_hz == 0);
  // QO-100 for an IC-9700: 10489.550 MHz through a 10057 MHz downconverter is 432.550 MHz at the
  // radio; 2400.050 MHz from 144.050 MHz through a 2256 MHz up-converter.
  const auto if432 = radio::parse_freqmode(read_file(dir + "freqmode-qo100-432.txt"));
  REQUIRE(if432.ok());
  REQUIRE(if432.records.size() == 1);
  const auto& r = if432.records[0];
  CHECK(r.radio.downlink_hz + r.radio.downlink_offset_hz == 432'550'000);
  CHECK(r.radio.uplink_hz + r.radio.uplink_offset_hz == 144'050'000);
  CHECK(r.radio.has_passbands());
}
