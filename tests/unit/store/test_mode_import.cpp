// The readers of the public mode lists and the merge (store/mode_import.h, issue 59 item 3). Each
// sample is written here in the list's own format: Gpredict's .trsp as Gpredict writes it from the
// SatNOGS list (one [group] per transponder, UP_LOW/UP_HIGH/DOWN_LOW/DOWN_HIGH in Hz, MODE,
// INVERT=true), SatPC32's Doppler.SQF (`name,down kHz,up kHz,down mode,up mode,NOR|REV,down
// offset,up offset,comment`) and SubTone.SQF (`name,tone`), OscarWatch's satellite_database.json
// (kHz, rig mode names, NOR/REV, ctcss and ctcss_arm in Hz). Frequencies are those of
// data/freqmode.txt and data/README.md.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>

#include "store/mode_import.h"
#include "store/model.h"

using namespace tb;
using namespace tb::store;

namespace {

Database db_of(std::initializer_list<std::pair<int, const char*>> sats) {
  Database db;
  for (const auto& [number, name] : sats) {
    Satellite s;
    s.elements.catalog_number = number;
    s.elements.name = name;
    db.satellites.push_back(s);
  }
  return db;
}

const char* kTrsp = "[Mode U/V Linear]\nUP_LOW=145935000\nUP_HIGH=145995000\nDOWN_LOW=435610000\n"
                    "DOWN_HIGH=435670000\nMODE=USB\nINVERT=true\n\n[CW beacon]\nDOWN_LOW=435605000\nMODE=CW\n";

const char* kSqf = "RS-44,435640,145965,USB,LSB,REV,0,0,SSB\r\n"
                   "RS-44,435611,145993.61,USB,LSB,REV,0,0,FT4\r\n"
                   "ISS,437800,145990,FM,FM,NOR,0,0,FM\r\n"
                   "AO-7,29450,145900,USB,USB,NOR,0,0,Mode A\r\n";

const char* kOscarWatch = R"JSON([
 {"name":"SO-50","norad_id":"27607","modes":[{"type":"FM VOICE","downlink":436795,"uplink":145850,
   "downlink_mode":"FMN","uplink_mode":"FMN","doppler":"NOR","ctcss":67.0,"ctcss_arm":74.4}]},
 {"name":"AO-91 (Fox-1B)","alternative_names":["AO-91"],"modes":[{"type":"FM","downlink":145960,
   "uplink":435250,"downlink_mode":"FM","uplink_mode":"FM","doppler":"NOR"}]}
])JSON";

radio::SatelliteMode mode_named(const Database& db, std::size_t sat, const char* name) {
  const auto m = find_mode(db.satellites[sat], name);
  REQUIRE(m);
  return *m;
}

}  // namespace

TEST_CASE("Gpredict .trsp: one mode per group, the catalog number from the file's name") {
  const ModeList l = read_mode_list(ListFormat::trsp, kTrsp, "/tmp/x/44909.trsp");
  REQUIRE(l.ok());
  REQUIRE(l.modes.size() == 2);
  const ListedMode& ssb = l.modes[0];
  CHECK(ssb.catalog == 44909);
  CHECK(ssb.line == 1);
  CHECK(ssb.mode.name == "SSB");
  CHECK(ssb.mode.radio.downlink_hz == 435'640'000);
  CHECK(ssb.mode.radio.uplink_hz == 145'965'000);
  CHECK(ssb.mode.radio.downlink_mode == radio::Mode::usb);
  CHECK(ssb.mode.radio.uplink_mode == radio::Mode::lsb);
  CHECK(ssb.mode.radio.inverting);
  CHECK(field_value(ssb.mode, ModeField::passbands) == "435610000-435670000/145935000-145995000");
  CHECK(l.modes[1].mode.name == "CW");
  CHECK(l.modes[1].line == 9);
  CHECK(l.modes[1].mode.radio.downlink_hz == 435'605'000);
  CHECK(l.modes[1].mode.radio.downlink_mode == radio::Mode::cw);
  CHECK(l.modes[1].mode.radio.uplink_hz == 0);

  CHECK(read_mode_list(ListFormat::trsp, kTrsp, "rs44.trsp").error ==
        "rs44.trsp: a Gpredict transponder file is named by the satellite's catalog number, as 44909.trsp");
  CHECK(read_mode_list(ListFormat::trsp, "[A]\nUP_LOW=145.935\n", "44909.trsp").error ==
        "44909.trsp: line 2, UP_LOW: found \"145.935\", expected a frequency in Hz");
  CHECK(read_mode_list(ListFormat::trsp, "[A]\nINVERT=maybe\n", "44909.trsp").error ==
        "44909.trsp: line 2, INVERT: found \"maybe\", expected true or false");
  CHECK(read_mode_list(ListFormat::trsp, "DOWN_LOW=1\n", "44909.trsp").error == "44909.trsp: line 1: DOWN_LOW before any [group]");
}

TEST_CASE("SatPC32 Doppler.SQF: one mode per line, the comment its name, kHz to Hz exactly") {
  const ModeList l = read_mode_list(ListFormat::sqf, kSqf, "Doppler.SQF");
  REQUIRE(l.ok());
  REQUIRE(l.modes.size() == 4);
  CHECK(l.modes[0].names == std::vector<std::string>{"RS-44"});
  CHECK(l.modes[0].catalog == 0);
  CHECK(l.modes[1].mode.name == "FT4");
  CHECK(l.modes[1].mode.radio.downlink_hz == 435'611'000);
  CHECK(l.modes[1].mode.radio.uplink_hz == 145'993'610);
  CHECK(l.modes[1].mode.radio.inverting);
  CHECK(l.modes[2].mode.name == "FM");
  CHECK(l.modes[2].mode.radio.uplink_mode == radio::Mode::fm);
  CHECK(l.modes[3].mode.name == "Mode-A");
  CHECK_FALSE(l.modes[3].mode.radio.inverting);
  CHECK(read_mode_list(ListFormat::sqf, "RS-44,435640,145965,USB,LSB,REV,0,0,SSB\nRS-44,435.64,145965,USB,LSB,REV,0,0,SSB\n",
                       "Doppler.SQF").error ==
        "Doppler.SQF: line 2, field 2 (downlink): found \"435.64\", expected kHz such as 435640");
  CHECK(read_mode_list(ListFormat::sqf, "RS-44,435640,145965,USB,PKT,REV,0,0,SSB\n", "Doppler.SQF").error ==
        "Doppler.SQF: line 1, field 5 (uplink mode): found \"PKT\", expected USB, LSB, CW or FM");
  CHECK(read_mode_list(ListFormat::sqf, "RS-44,435640,145965,USB,LSB,INV,0,0,SSB\n", "Doppler.SQF").error ==
        "Doppler.SQF: line 1, field 6: found \"INV\", expected NOR or REV");
  CHECK(read_mode_list(ListFormat::sqf, "RS-44,435640\n", "Doppler.SQF").error ==
        "Doppler.SQF: line 1: found 2 fields, expected name,down kHz,up kHz,down mode,up mode,NOR|REV,down offset,"
        "up offset[,comment]");
}

TEST_CASE("SatPC32 SubTone.SQF: the tone goes to the satellite's FM modes with an uplink") {
  const ModeList l = read_mode_list(ListFormat::subtone, "SO-50,67.0\nISS,67\n", "SubTone.SQF");
  REQUIRE(l.ok());
  REQUIRE(l.modes.size() == 2);
  CHECK(l.modes[0].mode.radio.ctcss_tenths_hz == 670);
  CHECK(l.modes[0].fm_uplinks);
  CHECK(read_mode_list(ListFormat::subtone, "SO-50,6.7\n", "SubTone.SQF").error ==
        "SubTone.SQF: line 1, field 2 (tone): found \"6.7\", expected a CTCSS tone from 60.0 to 300.0 Hz");
  // The ISS with FM (uplink) and SSTV (receive only): the tone goes to FM alone.
  Database db = db_of({{25544, "ISS"}});
  REQUIRE(merge_modes(db, read_mode_list(ListFormat::sqf, "ISS,437800,145990,FM,FM,NOR,0,0,FM\n"
                                                         "ISS,145800,0,FM,FM,NOR,0,0,SSTV\n", "Doppler.SQF"), false).added.size() == 2);
  const MergeReport r = merge_modes(db, l, false);
  CHECK(r.updated == std::vector<std::string>{"ISS FM tone: 67.0 Hz from satpc32"});
  CHECK(r.skipped == std::vector<std::string>{"SO-50 (line 1): no such satellite in the database"});
  CHECK(mode_named(db, 0, "SSTV").radio.ctcss_tenths_hz == 0);
}

TEST_CASE("OscarWatch satellite_database.json: kHz, rig modes, NOR/REV, both tones; matched by number or name") {
  const ModeList l = read_mode_list(ListFormat::oscarwatch, kOscarWatch, "satellite_database.json");
  REQUIRE(l.ok());
  REQUIRE(l.modes.size() == 2);
  const ListedMode& so50 = l.modes[0];
  CHECK(so50.catalog == 27607);
  CHECK(so50.mode.name == "FM");
  CHECK(so50.mode.radio.downlink_hz == 436'795'000);
  CHECK(so50.mode.radio.uplink_hz == 145'850'000);
  CHECK(so50.mode.radio.ctcss_tenths_hz == 670);
  CHECK(so50.mode.arm_tone_tenths_hz == 744);
  CHECK((so50.given & field_bit(ModeField::arm)) != 0);
  CHECK((l.modes[1].given & field_bit(ModeField::tone)) == 0);  // no tone given: a gap, not "none"
  Database db = db_of({{27607, "SO-50"}, {43017, "AO-91"}});
  const MergeReport r = merge_modes(db, l, false);
  CHECK(r.added == std::vector<std::string>{"SO-50 FM: added from oscarwatch (436.795 MHz FM, up 145.850 MHz FM)",
                                            "AO-91 FM: added from oscarwatch (145.960 MHz FM, up 435.250 MHz FM)"});
  CHECK(mode_named(db, 0, "FM").sources.at("arm") == radio::FieldSource{"oscarwatch", "744", "", ""});
  CHECK(read_mode_list(ListFormat::oscarwatch,
                       R"([{"name":"SO-50","modes":[{"type":"FM","downlink":436795,"downlink_mode":"FM","ctcss":6.7}]}])",
                       "satellite_database.json").error ==
        "satellite_database.json: satellites[0] (SO-50), modes[0].ctcss: expected a CTCSS tone from 60.0 to 300.0 Hz");
  CHECK(read_mode_list(ListFormat::oscarwatch, R"({"nothing":1})", "satellite_database.json").error ==
        "satellite_database.json: not an OscarWatch satellite database (expected a JSON list of satellites, each with name and modes)");
}

TEST_CASE("Merge: matched by name, else by frequency; the freq/mode file's values kept, a list's updated") {
  // The shipped RS-44 and AO-07 lines: each field's source is the freq/mode file.
  const auto fm = radio::parse_freqmode(
      "AO-07 145.950 432.150 usb lsb cat no down=145.925-145.975 up=432.125-432.175 inv=y mode=Mode-B\n"
      "AO-07 29.450 145.900 usb usb cat no down=29.400-29.500 up=145.850-145.950 inv=n mode=Mode-A\n"
      "RS-44 435.640 145.965 usb lsb cat no down=435.610-435.670 up=145.935-145.995 inv=y mode=SSB\n");
  REQUIRE(fm.ok());
  orbit::Elements ao7, rs44;
  ao7.name = "AO-07", ao7.catalog_number = 7530;
  rs44.name = "RS-44", rs44.catalog_number = 44909;
  ao7.mean_motion_rev_per_day = 12.54, rs44.mean_motion_rev_per_day = 12.8;  // the state reader's checks
  Database db = make_database({ao7, rs44}, fm.records);
  CHECK(field_source(mode_named(db, 1, "SSB"), ModeField::downlink) == "freqmode");

  // SatPC32: RS-44 SSB agrees, FT4 is new; "AO-7" is AO-07 and its "Mode A" the Mode-A it has.
  MergeReport r = merge_modes(db, read_mode_list(ListFormat::sqf, kSqf, "Doppler.SQF"), false);
  CHECK(r.added == std::vector<std::string>{"RS-44 FT4: added from satpc32 (435.611 MHz USB, up 145.99361 MHz LSB)"});
  CHECK(r.conflicts.empty());
  CHECK(r.unchanged == 2);
  CHECK(r.skipped == std::vector<std::string>{"ISS (line 3): no such satellite in the database"});

  // Gpredict: the transponder's group is RS-44's SSB (same name); the CW beacon, below the
  // passband, a new mode.
  r = merge_modes(db, read_mode_list(ListFormat::trsp, kTrsp, "44909.trsp"), false);
  CHECK(r.added == std::vector<std::string>{"RS-44 CW: added from gpredict (435.605 MHz CW)"});
  CHECK(r.unchanged == 1);

  // The operator moves the SSB spot; a list that differs keeps it and says so, each time; a list's
  // own value (the CW beacon's) is updated by the next list.
  Satellite& s = db.satellites[1];
  REQUIRE(choose_mode(s, "SSB"));
  s.radio.downlink_hz = 435'650'000;
  const char* moved = "[Mode U/V Linear]\nUP_LOW=145935000\nUP_HIGH=145995000\nDOWN_LOW=435610000\n"
                      "DOWN_HIGH=435670000\nMODE=USB\nINVERT=true\n[CW beacon]\nDOWN_LOW=435606000\nMODE=CW\n";
  r = merge_modes(db, read_mode_list(ListFormat::trsp, moved, "44909.trsp"), false);
  CHECK(r.conflicts ==
        std::vector<std::string>{"RS-44 SSB downlink: kept your 435.650 MHz (operator); gpredict says 435.640 MHz"});
  CHECK(r.updated ==
        std::vector<std::string>{"RS-44 CW downlink: 435.606 MHz from gpredict (was 435.605 MHz, gpredict)"});
  CHECK(s.radio.downlink_hz == 435'650'000);
  CHECK(r.changed);
  const auto diff = diff_lines(db);
  CHECK(std::find(diff.begin(), diff.end(),
                  "RS-44 SSB downlink 435.650 MHz (operator); gpredict says 435.640 MHz") != diff.end());
  CHECK(std::find(diff.begin(), diff.end(), "RS-44 SSB uplink 145.965 MHz (freq/mode file)") != diff.end());
  CHECK(std::find(diff.begin(), diff.end(), "RS-44 CW downlink 435.606 MHz (gpredict)") != diff.end());

  // The sources and the conflict live in the state document and read back.
  Model m;
  m.db = db;
  const Model back = model_from_json(to_json(m));
  CHECK(diff_lines(back.db) == diff);
}

TEST_CASE("Formats guessed from the name and the content") {
  CHECK(guess_list_format("", "/x/44909.trsp") == ListFormat::trsp);
  CHECK(guess_list_format("", "Doppler.SQF") == ListFormat::sqf);
  CHECK(guess_list_format("", "SubTone.SQF") == ListFormat::subtone);
  CHECK(guess_list_format(R"([{"uuid":"a","norad_cat_id":1}])", "list.json") == ListFormat::satnogs);
  CHECK(guess_list_format(kOscarWatch, "satellite_database.json") == ListFormat::oscarwatch);
  CHECK_FALSE(guess_list_format("hello", "notes.txt"));
}

TEST_CASE("Merge by frequency: transponders by their passbands; a spot inside a passband is a mode of its own") {
  const auto fm = radio::parse_freqmode(
      "AO-07 145.950 432.150 usb lsb cat no down=145.925-145.975 up=432.125-432.175 inv=y mode=Mode-B\n"
      "AO-07 29.450 145.900 usb usb cat no down=29.400-29.500 up=145.850-145.950 inv=n mode=Mode-A\n"
      "RS-44 435.640 145.965 usb lsb cat no down=435.610-435.670 up=145.935-145.995 inv=y mode=SSB\n");
  REQUIRE(fm.ok());
  orbit::Elements ao7, rs44;
  ao7.name = "AO-07", ao7.catalog_number = 7530;
  rs44.name = "RS-44", rs44.catalog_number = 44909;
  Database db = make_database({ao7, rs44}, fm.records);
  // SatNOGS names both AO-07 transponders "SSB" (the second "SSB-2"): each is the mode whose passbands it overlaps.
  const char* satnogs = R"([
   {"uuid":"m1","description":"Mode A transponder","alive":true,"status":"active","type":"Transponder",
    "uplink_low":145850000,"uplink_high":145950000,"downlink_low":29400000,"downlink_high":29500000,
    "mode":"USB","invert":false,"norad_cat_id":7530},
   {"uuid":"m2","description":"Mode B transponder","alive":true,"status":"active","type":"Transponder",
    "uplink_low":432125000,"uplink_high":432175000,"downlink_low":145925000,"downlink_high":145975000,
    "mode":"USB","invert":true,"norad_cat_id":7530}])";
  MergeReport r = merge_modes(db, read_mode_list(ListFormat::satnogs, satnogs, "transmitters.json"), false);
  CHECK(r.added.empty());
  CHECK(r.unchanged == 2);
  // SatPC32's FT4 alone: inside RS-44's SSB passband, but its own mode.
  r = merge_modes(db, read_mode_list(ListFormat::sqf, "RS-44,435611,145993.61,USB,LSB,REV,0,0,FT4\n", "Doppler.SQF"), false);
  CHECK(r.added == std::vector<std::string>{"RS-44 FT4: added from satpc32 (435.611 MHz USB, up 145.99361 MHz LSB)"});
  CHECK(r.conflicts.empty());
}

TEST_CASE("Names: a list's modes of one satellite made distinct within 16 characters; at most 16 modes") {
  std::string list = "[";
  for (int i = 0; i < 20; ++i)
    list += std::string(i ? "," : "") + R"({"uuid":"u)" + std::to_string(i) +
            R"(","description":"telemetry","alive":true,"status":"active","type":"Transmitter","downlink_low":)" +
            std::to_string(435'000'000 + i * 20'000) + R"(,"mode":"GMSK9k6abcdefghij","norad_cat_id":44909})";
  list += "]";
  const ModeList l = read_mode_list(ListFormat::satnogs, list, "transmitters.json");
  REQUIRE(l.ok());
  REQUIRE(l.modes.size() == 20);
  CHECK(l.modes[0].mode.name == "GMSK9k6abcdefghi");   // the modulation cut to 16
  CHECK(l.modes[1].mode.name == "GMSK9k6abcdefg-2");
  CHECK(l.modes[19].mode.name == "GMSK9k6abcdef-20");
  Database db = db_of({{44909, "RS-44"}});
  const MergeReport r = merge_modes(db, l, false);
  CHECK(r.added.size() == radio::kMaxModes);
  CHECK(r.skipped.size() == 4);
  CHECK(r.skipped[0] == "RS-44 GMSK9k6abcdef-17: not added, the satellite has 16 modes");
}

TEST_CASE("A receive-only entry is a gap for the uplink, not \"no uplink\"") {
  const auto fm = radio::parse_freqmode("ISS 437.800 145.990 fm fm cat no tone=67.0 mode=FM\n");
  REQUIRE(fm.ok());
  orbit::Elements iss;
  iss.name = "ISS", iss.catalog_number = 25544;
  Database db = make_database({iss}, fm.records);
  // A transmitter whose description names FM, at the repeater's downlink, without an uplink.
  const MergeReport r = merge_modes(db, read_mode_list(ListFormat::satnogs, R"([{"uuid":"d","description":"FM downlink",
    "alive":true,"status":"active","type":"Transmitter","downlink_low":437800000,"mode":"FM","norad_cat_id":25544}])",
                                                       "transmitters.json"), false);
  CHECK(r.conflicts.empty());
  CHECK(r.unchanged == 1);
  CHECK(db.satellites[0].radio.uplink_hz == 145'990'000);
}
