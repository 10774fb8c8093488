// The later TrakBox firmware's STATION.DAT (v3.20d-3.50b): seven numbered lines and `;` comments,
// through the same parse_station_file / apply_station_file as the 1994 five-line file. The files in
// tests/data/firmware/ were written from the format description
// (docs/menus/2-3.md and docs/menus/6-7-8.md give the format).
#include <doctest/doctest.h>

#include <tuple>
#include "support/data_files.h"


#include <nlohmann/json.hpp>

#include "rotator/adc_model.h"
#include "store/model.h"
#include "store/station_file.h"
#include "store/station_file_model.h"
#include "station_file_problems.h"
#include "support/manual_samples.h"
#include "support/shipped_model.h"

using namespace tb;
using store::parse_station_file;

namespace {

std::string read_data(const char* name) { return tb::testing::read_test_data(std::string("firmware/") + name); }

using testing::problems_text;

}  // namespace

TEST_CASE("STATION.DAT: the seven lines and what each item sets") {
  const auto r = parse_station_file(read_data("STATION.DAT"));
  INFO(problems_text(r));
  REQUIRE(r.ok());
  const store::StationFile& f = *r.file;
  CHECK(f.later_firmware);
  // 1
  CHECK(f.station.callsign == "JA6FTL");
  CHECK(f.station.lat_deg == 33.59);
  CHECK(f.station.lon_deg == 130.4);
  CHECK(f.station.height_m == 25.0);
  CHECK(f.station.rotor_start == station::RotorStart::north);
  CHECK(f.com_baud_given);
  CHECK(f.station.com_baud == 19200);
  // 2
  CHECK(f.rotator.az_span == rotator::AxisSpan{12, 1010});
  CHECK(f.rotator.el_span == rotator::AxisSpan{8, 500});
  CHECK(f.rotator.el_flip_allowed);
  // 3
  CHECK(f.rotator.az_dead_band == 4);
  CHECK(f.rotator.el_dead_band == 2);
  CHECK(f.rotator.az_skew == -3);
  CHECK(f.rotator.el_skew == 5);
  // 4
  CHECK(f.radio.rig == radio::Rig::yaesu);
  CHECK(f.radio.rig_model == radio::RigModel::yaesu_847);
  CHECK(f.wide_fm_given);
  CHECK(f.radio.ft736_wide_fm);
  CHECK(f.radio.cat_policy == radio::CatPolicy::full_orbit);
  CHECK(f.radio.icom_rx_address == 0x00);
  CHECK(f.cat_baud_given);
  CHECK(f.radio.cat_baud == 4800);
  // 5
  CHECK(f.rotator.parking_enabled);
  CHECK(f.radio.mic_click.park_pulse_width_digit == 2);
  CHECK(f.radio.mic_click.park_pulse_interval_digit == 5);
  CHECK(f.rotator.parking == rotator::AzEl{0.0, 10.0});
  CHECK(f.pass_events.rotor_start_el_deg == -1.5);
  CHECK(f.pass_events.output_on_el_deg == 0.5);
  CHECK(f.pass_events.output_off_el_deg == -0.5);
  // 6
  CHECK(f.radio.parking.enabled);
  CHECK(f.rotator_error_detection);
  CHECK(f.radio.parking.rx_hz == 145'800'000);
  CHECK(f.radio.parking.tx_hz == 435'300'000);
  CHECK(f.radio.parking.rx_mode == radio::Mode::fm);
  CHECK(f.radio.parking.tx_mode == radio::Mode::usb);
  CHECK(f.rotator.stall_s == 45.0);
  // 7: a range through North
  CHECK(testing::limits_of(f.rotator) == std::tuple(true, 270.0, 90.0, 0.0, 80.0));
}

TEST_CASE("STATION.DAT applied to the model, written back, and kept by the state document") {
  store::Model m = store::factory_defaults();
  const auto r = parse_station_file(read_data("STATION.DAT"));
  REQUIRE(r.ok());
  REQUIRE(store::apply_station_file(*r.file, m).empty());
  CHECK(m.station.com_baud == 19200);
  CHECK(m.rotator.el_flip_allowed);
  CHECK(m.radio.rig_model == radio::RigModel::yaesu_847);
  CHECK(m.radio.ft736_wide_fm);
  CHECK(m.radio.cat_baud == 4800);
  CHECK(m.radio.parking == radio::RadioParking{true, 145'800'000, 435'300'000, radio::Mode::fm, radio::Mode::usb});
  CHECK(m.pass_events == store::PassEvents{-1.5, 0.5, -0.5});
  CHECK(m.rotator_error_detection);
  CHECK(m.rotator.stall_s == 45.0);
  CHECK(m.rotator.az_limit_min == 270.0);
  CHECK(m.rotator.az_limit_max == 90.0);

  const std::string written = store::write_station_file_later(m);
  CHECK(written ==
        "; STATION.DAT of the later TrakBox firmware, written by trakbox\n"
        "1 JA6FTL 33.590 130.400 25 N 19200\n"
        "2 12 1010 8 500 F\n"
        "3 4 2 -3 5\n"
        "4 YAESUw847 FULL 00 00 4800\n"
        "5 125 0 10 -1.5 0.5 -0.5\n"
        "6 11 145.800 435.300 fm usb 45\n"
        "7 1 270 90 0 80\n");
  const auto back = parse_station_file(written);
  INFO(problems_text(back));
  REQUIRE(back.ok());
  CHECK(*back.file == *r.file);

  const store::Model restored = store::model_from_json(store::to_json(m));
  CHECK(std::tie(restored.station, restored.rotator, restored.radio, restored.pass_events,
                 restored.rotator_error_detection) ==
        std::tie(m.station, m.rotator, m.radio, m.pass_events, m.rotator_error_detection));
}

TEST_CASE("A state document written before the new fields still loads, with their defaults") {
  store::Model m = store::factory_defaults();
  nlohmann::json j = store::to_json(m);
  j.erase("pass_events");
  j.erase("rotator_error_detection");
  for (const char* k : {"rig_model", "cat_baud", "parking"}) j["radio"].erase(k);
  j["radio"]["mic_click"].erase("park_pulse_width_digit");
  j["radio"]["mic_click"].erase("park_pulse_interval_digit");
  const store::Model old = store::model_from_json(j);
  CHECK(old.radio == m.radio);
  CHECK(old.pass_events == store::PassEvents{});
  CHECK(old.rotator_error_detection);
  // And a bad value in a new field is refused by name.
  j["radio"]["cat_baud"] = 300;
  CHECK_THROWS_WITH(store::model_from_json(j), doctest::Contains("radio.cat_baud"));
}

TEST_CASE("STATION.DAT: every problem by upload line and item, nothing applied") {
  const auto r = parse_station_file(read_data("STATION_BAD.DAT"));
  CHECK(!r.file);
  INFO(problems_text(r));
  REQUIRE(r.problems.size() == 8);
  CHECK(r.problems[0].message() ==
        "line 2, item 7 (COM baud): found \"38400\", expected a speed in baud: 1200, 2400, 4800, 9600 or 19200");
  CHECK(r.problems[1].message() == "line 3, item 6 (flip mode): found \"X\", expected F (flip mode) or nothing");
  CHECK(r.problems[2].line == 5);
  CHECK(r.problems[2].field == 2);
  CHECK(r.problems[2].expected.find("KENWOOD711") != std::string::npos);
  CHECK(r.problems[3].line == 6);
  CHECK(r.problems[3].what == "antenna parking ON/OFF");
  CHECK(r.problems[4].message() ==
        "line 7, item 2 (radio parking/rotator error flags): found \"12\", expected two digits 0 or 1: radio "
        "parking, then rotator-error detection (e.g. 11)");
  CHECK(r.problems[5].message() == "line 7, item 6 (TX park mode): found \"am\", expected usb, lsb, fm, cw or none");
  CHECK(r.problems[6].message() == "line 7, item 7 (rotator error timeout): found \"0\", expected seconds 1 to 600");
  CHECK(r.problems[7].line == 8);
  CHECK(r.problems[7].field == 4);
  CHECK(r.problems[7].what == "azimuth maximum");
}

TEST_CASE("Optional items left out; the other rig names; addresses and baud on line 4") {
  const char* text =
      "1 W1AW 41.714 -72.727 30 S\n2 0 1023 0 511\n3 3 1 0 0\n4 KENWOOD711 AOS\n"
      "5 0 0 0 -2.0 -2.0 -2.0\n6 00 0 0 none none 3\n7 0 0 360 0 90\n";
  const auto r = parse_station_file(text);
  INFO(problems_text(r));
  REQUIRE(r.ok());
  CHECK(r.file->later_firmware);
  CHECK_FALSE(r.file->com_baud_given);
  CHECK_FALSE(r.file->rotator.el_flip_allowed);
  CHECK(r.file->radio.rig == radio::Rig::kenwood);
  CHECK(r.file->radio.rig_model == radio::RigModel::kenwood_711);
  CHECK_FALSE(r.file->wide_fm_given);
  CHECK(r.file->radio.mic_click.park_pulse_width_digit == -1);
  CHECK_FALSE(r.file->rotator_error_detection);
  // Applying keeps what the file does not say: the COM and CAT speeds, the wide-FM filter.
  store::Model m = store::factory_defaults();
  m.station.com_baud = 4800;
  m.radio.cat_baud = 1200;
  m.radio.ft736_wide_fm = true;
  REQUIRE(store::apply_station_file(*r.file, m).empty());
  CHECK(m.station.com_baud == 4800);
  CHECK(m.radio.cat_baud == 1200);
  CHECK(m.radio.ft736_wide_fm);
  CHECK_FALSE(m.rotator_error_detection);

  auto line4 = [](const std::string& l4) {
    return parse_station_file("1 A 0 0 0 S\n2 0 1023 0 511\n3 3 1 0 0\n" + l4 +
                              "\n5 0 0 0 -2 -2 -2\n6 00 0 0 none none 3\n7 0 0 360 0 90\n");
  };
  const auto icom = line4("4 ICOM FULL 2E 60 19200");
  REQUIRE(icom.ok());
  CHECK(icom.file->radio.icom_rx_address == 0x2E);
  CHECK(icom.file->radio.icom_tx_address == 0x60);
  CHECK(icom.file->radio.cat_baud == 19200);
  const auto kbaud = line4("4 KENWOOD A 9600");  // no addresses, the baud after F/A
  REQUIRE(kbaud.ok());
  CHECK(kbaud.file->radio.cat_baud == 9600);
  const auto bad_baud = line4("4 KENWOOD A 300");
  REQUIRE(bad_baud.problems.size() == 1);
  CHECK(bad_baud.problems[0].what == "CAT baud");
  CHECK(line4("4 YAESU_736 A").file->radio.rig_model == radio::RigModel::yaesu_736);
  CHECK_FALSE(line4("4 YAESU_736 A").file->radio.ft736_wide_fm);
  CHECK(line4("4 YAESUw736 A").file->radio.ft736_wide_fm);
  CHECK(line4("4 yaesu_o A").file->radio.rig_model == radio::RigModel::yaesu_other);
  CHECK(!line4("4 ICOM A").ok());  // Icom still needs its addresses
}

TEST_CASE("The form is told by line 5; a seven-line file missing lines says which") {
  // Line 5 with 6 items: the later form, so lines 6 and 7 are missing.
  const auto r = parse_station_file("1 A 0 0 0 S\n2 0 1023 0 511\n3 3 1 0 0\n4 N A\n5 0 0 0 -2 -2 -2\n");
  REQUIRE(r.problems.size() == 2);
  CHECK(r.problems[0].expected.find("line 6 (parking/error flags") == 0);
  CHECK(r.problems[1].expected.find("line 7 (limit on/off") == 0);
  // An eighth line.
  const auto e = parse_station_file(read_data("STATION.DAT") + "8 1 2 3\n");
  REQUIRE(e.problems.size() == 1);
  CHECK(e.problems[0].expected == "nothing more: the later firmware's station file has seven lines");
  // The 1994 file with comments still reads as the 1994 file.
  const auto old = parse_station_file(std::string("; the manual's sample\n") + testing::kManualStationFile);
  REQUIRE(old.ok());
  CHECK_FALSE(old.file->later_firmware);
  CHECK(old.file->radio.rig == radio::Rig::icom);
}

TEST_CASE("A 1994 file does not touch what only the later file sets, but its span means 0..90: flip goes off") {
  store::Model m = store::factory_defaults();
  m.rotator.el_flip_allowed = true;
  m.rotator.stall_s = 7.0;
  m.pass_events.rotor_start_el_deg = 3.0;
  m.radio.parking.enabled = true;
  const auto r = parse_station_file(testing::kManualStationFile);
  REQUIRE(r.ok());
  REQUIRE(store::apply_station_file(*r.file, m).empty());
  // Flip mode says what line 2's elevation span means (0..180); a 1994 file's span is 0..90.
  CHECK_FALSE(m.rotator.el_flip_allowed);
  CHECK(m.rotator.stall_s == 7.0);
  CHECK(m.pass_events.rotor_start_el_deg == 3.0);
  CHECK(m.radio.parking.enabled);
}

TEST_CASE("FREQ.DAT's alternative uplinks and ir/kr flag live in the database and the state document") {
  store::Model m = testing::shipped_model();
  const auto fm = radio::parse_freqmode(read_data("FREQ.DAT"));
  REQUIRE(fm.ok());
  store::Database db = m.db;
  const store::FreqModeUpload up = store::apply_freqmode(db, fm.records);
  CHECK(up.skipped.empty());
  REQUIRE(up.updated.size() == 8);
  m.db = db;
  const auto iss = m.db.find("ISS");
  REQUIRE(iss);
  const radio::SatelliteRadio& r = m.db.satellites[static_cast<std::size_t>(*iss)].radio;
  CHECK(r.alternate_uplinks_hz == std::vector<radio::Hz>{145'825'000, 145'800'000, 437'800'000});
  CHECK(r.reverse == radio::ReverseAssignment::icom_main_sub);

  nlohmann::json j = store::to_json(m);
  const store::Model back = store::model_from_json(j);
  CHECK(back.db.satellites.size() == m.db.satellites.size());
  for (std::size_t i = 0; i < m.db.satellites.size(); ++i) CHECK(back.db.satellites[i].radio == m.db.satellites[i].radio);

  // Written before these fields (and so before the satellites' modes, issue 59): the entries load
  // with no alternatives and no reversal.
  for (auto& s : j["db"]["satellites"]) {
    s["radio"].erase("alternate_uplinks_hz");
    s["radio"].erase("reverse");
    s.erase("modes");
    s.erase("mode");
  }
  const store::Model old = store::model_from_json(j);
  const radio::SatelliteRadio& o = old.db.satellites[static_cast<std::size_t>(*iss)].radio;
  CHECK(o.alternate_uplinks_hz.empty());
  CHECK(o.reverse == radio::ReverseAssignment::none);
  CHECK(o.uplink_hz == 145'990'000);

  // Four alternatives are one too many, and the message names the field.
  j["db"]["satellites"][0]["radio"]["alternate_uplinks_hz"] = {1, 2, 3, 4};
  CHECK_THROWS_WITH(store::model_from_json(j), doctest::Contains("db.satellites[0].radio.alternate_uplinks_hz"));
}

TEST_CASE("rotator.cross_limit_sector: stored, optional (older states load as barriers), type-checked") {
  store::Model m = store::factory_defaults();
  m.rotator.limits_enabled = true;
  m.rotator.az_limit_min = 10;
  m.rotator.az_limit_max = 350;
  m.rotator.cross_limit_sector = true;
  nlohmann::json j = store::to_json(m);
  CHECK(j["rotator"]["cross_limit_sector"] == true);
  CHECK(store::model_from_json(j).rotator.cross_limit_sector);
  j["rotator"].erase("cross_limit_sector");
  CHECK_FALSE(store::model_from_json(j).rotator.cross_limit_sector);
  j["rotator"]["cross_limit_sector"] = "yes";
  CHECK_THROWS_WITH(store::model_from_json(j), doctest::Contains("rotator.cross_limit_sector"));
}

// Flip mode (v3.30a, "If you select flip operation, you must calibrate the EL rotor at 0 and 180
// degree point"): line 2's elevation span is 0..180 degrees. The firmware's own example and a span
// like JA6FTL's (25-981, whose 180 degrees lay at count 1937 when the span was read as 0..90) apply.
TEST_CASE("STATION.DAT in flip mode: the elevation span is 0..180 degrees and the file applies") {
  struct Case {
    const char* file;
    rotator::AxisSpan el;
    double count_at_90;
  };
  for (const Case& k : {Case{"STATION_FLIP.DAT", {2, 917}, 459.5}, Case{"STATION_JA6FTL.DAT", {25, 981}, 503.0}}) {
    const std::string file = k.file;
    CAPTURE(file);
    const auto r = parse_station_file(read_data(k.file));
    INFO(problems_text(r));
    REQUIRE(r.ok());
    store::Model m = store::factory_defaults();
    const auto refused = store::apply_station_file(*r.file, m);
    CHECK(refused.empty());
    REQUIRE(m.rotator.el_flip_allowed);
    REQUIRE(m.rotator.el_span == k.el);
    CHECK(m.rotator.el_top_deg() == 180.0);
    // The model: 0 deg at the minimum, 180 at the maximum, 90 half-way (without line 3's skew and
    // line 7's limits, el 0..80).
    m.rotator.el_skew = 0;
    m.rotator.limits_enabled = false;
    const rotator::AdcModel a(m.rotator, m.station.rotor_start);
    CHECK(a.el_from_counts(k.el.min) == 0.0);
    CHECK(a.el_from_counts(k.el.max) == doctest::Approx(180.0));
    CHECK(a.counts_from_el(90.0) == doctest::Approx(k.count_at_90));
    CHECK(a.deg_per_count(rotator::Axis::el) == doctest::Approx(180.0 / (k.el.max - k.el.min)));
    CHECK(a.el_range().hi == doctest::Approx(180.0));
    CHECK(a.counts_range(rotator::Axis::el).hi == doctest::Approx(k.el.max));
  }
}
