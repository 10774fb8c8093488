// The settings table (store/settings.h) and its one door (store/owner.h), tested from the table
// itself: for every setting, a value at each end of its range is taken by the owner, written and
// read back by the state reader unchanged; a value just outside is refused by the owner, by the
// typed form and by the state reader with the same sentence, and nothing changes.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "store/model.h"
#include "store/owner.h"
#include "store/settings.h"

using namespace tb::store;
using nlohmann::json;

namespace {

// The state document with one setting's value replaced, as an edited file would hold it.
json document_with(const Setting& s, const json& v) {
  json doc = to_json(factory_defaults());
  std::string ptr = "/" + std::string(s.key);
  for (char& c : ptr)
    if (c == '.') c = '/';
  doc[json::json_pointer(ptr)] = v;
  return doc;
}

std::string reader_refusal(const json& doc) {
  try {
    (void)model_from_json(doc);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

bool numeric(const Setting& s) {
  return (s.type == SettingType::number || s.type == SettingType::integer) && s.choices.empty();
}

// A value just outside the range: a tenth of a unit for numbers, one for whole numbers.
json just_outside(const Setting& s, bool below) {
  const double step = s.type == SettingType::integer ? 1.0 : std::max(0.1, (s.hi - s.lo) * 1e-3);
  const double v = below ? s.lo - step : s.hi + step;
  return s.type == SettingType::integer ? json(static_cast<long long>(v)) : json(v);
}

json end_value(const Setting& s, bool low) {
  const double v = low ? s.lo : s.hi;
  return s.type == SettingType::integer ? json(static_cast<long long>(v)) : json(v);
}

}  // namespace

TEST_CASE("every setting is declared once, with a key the state document has, a help line and its range") {
  const json doc = to_json(factory_defaults());
  for (const Setting& s : settings()) {
    CAPTURE(s.key);
    CHECK(find_setting(s.key) == &s);
    CHECK(!s.help.empty());
    std::string ptr = "/" + std::string(s.key);
    for (char& c : ptr)
      if (c == '.') c = '/';
    CHECK(doc.contains(json::json_pointer(ptr)));
    // The factory value is within its own rule.
    CHECK_FALSE(refusal(s, s.get(factory_defaults())));
    if (numeric(s)) CHECK(s.lo < s.hi);
  }
}

TEST_CASE("both ends of every range are taken, saved and read back; just outside is refused with one sentence") {
  for (const Setting& s : settings()) {
    if (!numeric(s)) continue;
    CAPTURE(s.key);
    for (const bool low : {true, false}) {
      ModelOwner owner;
      const json end = end_value(s, low);
      // rotator::validate's cross-checks (limits, travel) may refuse an end that the field takes
      // alone; the reader and the owner agree whichever it is.
      const EditResult r = owner.set_json(s.key, end, Origin::socket);
      const std::string reader = reader_refusal(document_with(s, end));
      CHECK(r.ok() == reader.empty());
      if (r.ok()) {
        CHECK(s.get(owner.model()) == end);
        const Model back = model_from_json(to_json(owner.model()));
        CHECK(s.get(back) == end);
      }

      const json out = just_outside(s, low);
      ModelOwner fresh;
      const Model before = fresh.model();
      const EditResult refused = fresh.set_json(s.key, out, Origin::socket);
      REQUIRE_FALSE(refused.ok());
      CHECK(to_json(fresh.model()) == to_json(before));
      // The same sentence from the reader of an edited state file and from the typed form.
      CHECK(reader_refusal(document_with(s, out)) == *refused.refusal);
      const ParsedSetting typed = parse_setting(s, out.dump());
      CHECK_FALSE(typed.value);
      CHECK(typed.error == *refused.refusal);
      CHECK(refused.refusal->find(range_text(s)) != std::string::npos);
    }
  }
}

TEST_CASE("the station's height: 12000 m is refused naming the range, 9000 m is kept") {
  ModelOwner owner;
  const EditResult r = owner.set_position(48.85, 2.35, 12000, Origin::command_line);
  REQUIRE_FALSE(r.ok());
  CHECK(*r.refusal == "station.height_m: 12000 is outside -500 .. 9000 m");
  CHECK(owner.model().station.lat_deg == factory_defaults().station.lat_deg);
  CHECK(owner.set_position(48.85, 2.35, 9000, Origin::command_line).ok());
  CHECK(model_from_json(to_json(owner.model())).station.height_m == 9000);
}

TEST_CASE("choices, switches and text: typed forms, refusals naming the choices") {
  ModelOwner owner;
  CHECK(owner.set_typed("station.rotor_start", "North", Origin::socket).ok());
  CHECK(owner.model().station.rotor_start == tb::station::RotorStart::north);
  const EditResult bad = owner.set_typed("station.rotor_start", "east", Origin::socket);
  REQUIRE_FALSE(bad.ok());
  CHECK(*bad.refusal == "station.rotor_start: 'east' is not one of north or south");
  CHECK(owner.set_typed("rotor_control", "yes", Origin::socket).ok());
  CHECK(owner.model().rotor_control);
  CHECK(owner.set_typed("sharing.exclusive", "rotctld", Origin::socket).ok());
  CHECK(owner.model().sharing.exclusive == "rotctld");
  CHECK(owner.set_typed("sharing.exclusive", "none", Origin::socket).ok());
  CHECK(owner.model().sharing.exclusive.empty());
  CHECK(*owner.set_typed("station.com_baud", "5000", Origin::socket).refusal ==
        "station.com_baud: 5000 is not one of 1200, 2400, 4800, 9600 or 19200");
  CHECK(*owner.set_typed("station.callsign", "TOOLONGCALLSIGN", Origin::socket).refusal ==
        "station.callsign: longer than 10 characters");
  CHECK(*owner.set_typed("gps.threshold_m", "lots", Origin::socket).refusal ==
        "gps.threshold_m: 'lots' is not a number (1 .. 100000 m)");
  CHECK(*owner.set_typed("no.such", "1", Origin::socket).refusal ==
        "no.such: no such setting (trakbox settings lists them)");
}

TEST_CASE("radio.record and radio.record_satellites (issue 59): typed, kept, refused naming the value") {
  ModelOwner owner;
  CHECK(owner.model().radio.record == tb::radio::Record::off);   // the factory setting
  CHECK(owner.set_typed("radio.record", "Audio", Origin::socket).ok());
  CHECK(owner.model().radio.record == tb::radio::Record::audio);
  CHECK(*owner.set_typed("radio.record", "video", Origin::socket).refusal ==
        "radio.record: 'video' is not one of off, audio or iq");
  CHECK(owner.model().radio.record == tb::radio::Record::audio);   // kept
  CHECK(owner.set_typed("radio.record_satellites", "SO-50, ISS", Origin::socket).ok());
  CHECK(owner.model().radio.record_satellites == "SO-50, ISS");
  CHECK(*owner.set_typed("radio.record_satellites", "SO-50,,ISS", Origin::socket).refusal ==
        "radio.record_satellites: 'SO-50,,ISS': expected satellite names separated by commas (an empty name found)");
  CHECK(owner.model().radio.record_satellites == "SO-50, ISS");
  CHECK(owner.set_typed("radio.record_satellites", "none", Origin::socket).ok());
  CHECK(owner.model().radio.record_satellites.empty());
}

TEST_CASE("the owner announces each change once, with its areas and versions; no change, no notice") {
  ModelOwner owner;
  std::vector<Notice> told;
  owner.listen([&](const Notice& n) { told.push_back(n); });
  CHECK(owner.set_position(48.85, 2.35, 35, Origin::web).changed);
  REQUIRE(told.size() == 1);
  CHECK(told[0].changes(Area::position));
  CHECK(owner.version(Area::position) == 1);
  CHECK_FALSE(owner.set_position(48.85, 2.35, 35, Origin::web).changed);  // the same place
  CHECK(told.size() == 1);
  CHECK(owner.set("rotator.az_skew", 12, Origin::menus).changed);
  REQUIRE(told.size() == 2);
  CHECK(told[1].changes(Area::rotator));
  CHECK_FALSE(told[1].changes(Area::position));
  CHECK(owner.origin_of("rotator.az_skew") == Origin::menus);
  CHECK(owner.origin_of("rotator.el_skew") == Origin::defaults);
  CHECK(owner.reset("rotator.az_skew", Origin::socket).changed);
  CHECK(owner.model().rotator.az_skew == 0);
  CHECK(owner.origin_of("rotator.az_skew") == Origin::defaults);
}

TEST_CASE("a general edit the reader would refuse changes nothing and says the reader's sentence") {
  ModelOwner owner;
  const EditResult r = owner.edit(bit(Area::rotator), "rotator limits", Origin::menus, [](Model& m) {
    m.rotator.az_span = {500, 505};  // narrower than the narrowest span
  });
  REQUIRE_FALSE(r.ok());
  CHECK(r.refusal->rfind("rotator", 0) == 0);
  CHECK(owner.model().rotator.az_span.min == 0);
  CHECK(owner.version(Area::rotator) == 0);
}

TEST_CASE("a listener's own edit is announced after the one in progress") {
  ModelOwner owner;
  std::vector<std::string> order;
  owner.listen([&](const Notice& n) {
    order.push_back(n.what);
    if (n.what == "station position") (void)owner.set("rotor_control", true, Origin::station);
  });
  CHECK(owner.set_position(10, 20, 30, Origin::gps).ok());
  REQUIRE(order.size() == 2);
  CHECK(order[0] == "station position");
  CHECK(order[1] == "rotor_control");
}

TEST_CASE("the sky calibration: offsets and their record saved and read back; older files read; bad records refused") {
  Model m = factory_defaults();
  m.rotator.az_offset_deg = -2.0;
  m.rotator.el_offset_deg = 1.0;
  m.rotator.sky = {"sun", "2026-03-20T09:00:00Z", 0.5, -0.25, "moon", "2026-03-19T21:00:00Z"};
  const json doc = to_json(m);
  CHECK(model_from_json(doc).rotator == m.rotator);
  // A state file from before issue 58: no offsets, no record.
  json old = doc;
  old["rotator"].erase("az_offset_deg");
  old["rotator"].erase("el_offset_deg");
  old["rotator"].erase("sky_calibration");
  const Model read = model_from_json(old);
  CHECK(read.rotator.az_offset_deg == 0.0);
  CHECK(read.rotator.sky.source.empty());
  json bad = doc;
  bad["rotator"]["sky_calibration"]["source"] = "venus";
  CHECK(reader_refusal(bad) == "rotator.sky_calibration.source: 'venus': expected sun, moon, sun scan or nothing");
  bad = doc;
  bad["rotator"]["sky_calibration"]["time"] = "yesterday";
  CHECK(reader_refusal(bad) == "rotator.sky_calibration.time: 'yesterday' is not an ISO 8601 UTC time");
}
