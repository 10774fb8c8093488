// A satellite's named modes (issue 59): the freq/mode file's mode= lines, the state document's
// "modes", a state from before modes migrated into one mode with every value and correction kept,
// choosing a mode, and what the reader refuses, naming the field.
#include <doctest/doctest.h>
#include "test_paths.h"  // TRAKBOX_SOURCE_DIR

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "store/model.h"
#include "store/owner.h"
#include "support/shipped_model.h"

using namespace tb;
using namespace tb::store;
using nlohmann::json;

namespace {
using tb::testing::read_file;

// RS-44 worked three ways, AO-07 in one (the 1994 file's line, no mode=): the integration test's
// figures, RS-44's passbands as data/freqmode.txt has them and its FT4 spot as issue 59 gives it.
const char* kModes =
    "RS-44 435.640 145.965 usb lsb cat no down=435.610-435.670 up=145.935-145.995 inv=y mode=SSB\n"
    "RS-44 435.6135 145.9915 cw cw cat no down=435.610-435.670 up=145.935-145.995 inv=y mode=CW\n"
    "RS-44 435.611 145.99361 usb lsb cat no down=435.610-435.670 up=145.935-145.995 inv=y mode=FT4\n"
    "SO-50 436.795 145.850 fm fm cat no tone=67.0 arm=74.4\n";

Model shipped_with(const char* freqmode) {
  const std::string dir = TRAKBOX_SOURCE_DIR "/data/";
  const auto sets = orbit::parse_nasa(read_file(dir + "amateur.tle"), "amateur.tle");
  const auto fm = radio::parse_freqmode(freqmode);
  REQUIRE(fm.ok());
  Model m;
  m.db = make_database(sets.sets, fm.records);
  return m;
}

const Satellite& named(const Model& m, const char* name) { return m.db.satellites[static_cast<std::size_t>(*m.db.find(name))]; }
Satellite& named(Model& m, const char* name) { return m.db.satellites[static_cast<std::size_t>(*m.db.find(name))]; }
}  // namespace

TEST_CASE("mode= lines give a satellite its modes; the first is the default; a mode twice is refused") {
  const Model m = shipped_with(kModes);
  const Satellite& rs = named(m, "RS-44");
  const auto modes = modes_of(rs);
  REQUIRE(modes.size() == 3);
  CHECK(modes[0].name == "SSB");
  CHECK(modes[1].name == "CW");
  CHECK(modes[2].name == "FT4");
  CHECK(chosen_mode(rs) == "SSB");
  CHECK(rs.radio.downlink_hz == 435'640'000);
  CHECK(modes[2].radio.downlink_hz == 435'611'000);
  CHECK(modes[2].radio.uplink_hz == 145'993'610);
  CHECK(modes[2].radio.inverting);
  CHECK(modes[1].radio.downlink_mode == radio::Mode::cw);
  // SO-50's one line: its mode named after its downlink mode, the arming tone kept.
  const auto so = modes_of(named(m, "SO-50"));
  REQUIRE(so.size() == 1);
  CHECK(so[0].name == "FM");
  CHECK(so[0].radio.ctcss_tenths_hz == 670);
  CHECK(so[0].arm_tone_tenths_hz == 744);
  // RS-44 is on the tracking list once.
  CHECK(m.db.selected.size() == 2);

  const auto twice = radio::parse_freqmode(
      "RS-44 435.640 145.965 usb lsb cat no mode=SSB\nRS-44 435.620 145.985 usb lsb cat no mode=ssb\n");
  REQUIRE(twice.problems.size() == 1);
  CHECK(twice.problems[0].message() ==
        "line 2, field 1 (satellite name): found \"RS-44\", expected a mode not already given for RS-44 (it is on line 1)");
  const auto bad = radio::parse_freqmode("RS-44 435.640 145.965 usb lsb cat no mode=S*B\n");
  REQUIRE(bad.problems.size() == 1);
  CHECK(bad.problems[0].expected == "mode=NAME: a mode name holds only letters, digits and - + / . _");
  // Written back as read.
  const auto again = radio::parse_freqmode(radio::write_freqmode(radio::parse_freqmode(kModes).records));
  CHECK(again.records == radio::parse_freqmode(kModes).records);
}

TEST_CASE("Choosing a mode keeps the working record in its mode; the choice and the modes round-trip") {
  Model m = shipped_with(kModes);
  Satellite& rs = named(m, "RS-44");
  rs.radio.downlink_hz = 435'650'000;  // the operator moved SSB's spot (menu 3-1)
  REQUIRE(choose_mode(rs, "ft4"));     // case aside
  CHECK(rs.mode == "FT4");
  CHECK(rs.radio.downlink_hz == 435'611'000);
  CHECK_FALSE(choose_mode(rs, "PSK31"));
  CHECK(rs.mode == "FT4");

  const Model back = model_from_json(to_json(m));
  const Satellite& b = named(back, "RS-44");
  CHECK(b.mode == "FT4");
  CHECK(b.radio.downlink_hz == 435'611'000);
  CHECK(modes_of(b) == modes_of(rs));
  CHECK(find_mode(b, "SSB")->radio.downlink_hz == 435'650'000);
  CHECK(to_json(back) == to_json(m));
}

TEST_CASE("A state from before modes: each record becomes one mode, every value and correction kept") {
  Model m = shipped_with(
      "RS-44 435.640 145.965,145.975 usb lsb cat no ir down=435.610-435.670 up=145.935-145.995 inv=y\n"
      "SO-50 436.795 145.850 fm fm cat no tone=67.0\n"
      "AO-27 436.795/-400.000 145.850 none none mic ma\n");
  m.radio.corrections = {{"RS-44 USB", 120}, {"SO-50 FM", -300}};
  m.radio.tx_corrections = {{"RS-44 LSB", -250}};
  json old = to_json(m);
  for (auto& s : old["db"]["satellites"]) {  // what a trakbox before issue 59 wrote
    s.erase("modes");
    s.erase("mode");
  }
  const Model back = model_from_json(old);
  for (const char* name : {"RS-44", "SO-50", "AO-27"}) {
    CAPTURE(name);
    const auto modes = modes_of(named(back, name));
    REQUIRE(modes.size() == 1);
    CHECK(modes[0].radio == named(m, name).radio);
    CHECK(named(back, name).radio == named(m, name).radio);
  }
  CHECK(modes_of(named(back, "RS-44"))[0].name == "SSB");
  CHECK(modes_of(named(back, "RS-44"))[0].radio.alternate_uplinks_hz == std::vector<radio::Hz>{145'975'000});
  CHECK(modes_of(named(back, "AO-27"))[0].name == "default");
  CHECK(modes_of(named(back, "AO-27"))[0].radio.downlink_offset_hz == -400'000'000);
  // The corrections: now per mode, the old keys kept beside them.
  CHECK(back.radio.corrections == std::map<std::string, radio::Hz>{
                                      {"RS-44 USB", 120}, {"RS-44 SSB", 120}, {"SO-50 FM", -300}});
  CHECK(back.radio.tx_corrections == std::map<std::string, radio::Hz>{{"RS-44 LSB", -250}, {"RS-44 SSB", -250}});
  // A satellite without any record gets no mode.
  CHECK(modes_of(named(back, "HO-113")).empty());
  CHECK(chosen_mode(named(back, "HO-113")).empty());
}

TEST_CASE("The reader refuses bad modes by name; the owner's edit changes nothing then") {
  const Model m = shipped_with(kModes);
  const json good = to_json(m);
  const std::size_t i = static_cast<std::size_t>(*m.db.find("RS-44"));
  const std::string w = "db.satellites[" + std::to_string(i) + "]";
  json j = good;
  j["db"]["satellites"][i]["mode"] = "PSK31";
  CHECK_THROWS_WITH_AS(model_from_json(j), (w + ".mode: 'PSK31' is not one of the satellite's modes").c_str(),
                       std::runtime_error);
  j = good;
  j["db"]["satellites"][i]["modes"][2]["name"] = "cw";
  CHECK_THROWS_WITH_AS(model_from_json(j), (w + ".modes[2].name: 'cw' is given twice").c_str(), std::runtime_error);
  j = good;
  j["db"]["satellites"][i]["modes"][1]["name"] = "C W";
  CHECK_THROWS_WITH_AS(model_from_json(j),
                       (w + ".modes[1].name: a mode name holds only letters, digits and - + / . _").c_str(),
                       std::runtime_error);

  ModelOwner owner(m);
  const EditResult r = owner.edit(bit(Area::radio_entries), "mode", Origin::web, [&](Model& x) {
    REQUIRE(choose_mode(x.db.satellites[i], "CW"));
    x.db.satellites[i].modes[0].name = "";  // a broken mode beside the good choice: all refused
  });
  CHECK(r.refusal == w + ".modes[0].name: a mode name is empty");
  CHECK(owner.model().db.satellites[i].mode == "SSB");
  const EditResult ok = owner.edit(bit(Area::radio_entries), "mode", Origin::web,
                                   [&](Model& x) { REQUIRE(choose_mode(x.db.satellites[i], "CW")); });
  CHECK(ok.changed);
  CHECK(owner.model().db.satellites[i].radio.downlink_mode == radio::Mode::cw);
}
