// The SatNOGS DB transmitter list into the database's modes (store/satnogs.h, the one SatNOGS
// importer, through store/mode_import.h). The list is written here with the fields the SatNOGS API
// documents (uuid, description, alive, type, uplink/downlink low/high in Hz, mode, invert, baud,
// norad_cat_id, status).
#include <doctest/doctest.h>

#include <string>

#include "store/satnogs.h"

using namespace tb;
using namespace tb::store;

namespace {

Database satnogs_db_of(std::initializer_list<std::pair<int, const char*>> sats) {
  Database db;
  for (const auto& [number, name] : sats) {
    Satellite s;
    s.elements.catalog_number = number;
    s.elements.name = name;
    db.satellites.push_back(s);
  }
  return db;
}

const char* kList = R"([
 {"uuid":"a","description":"FM voice","alive":true,"status":"active","type":"Transceiver",
  "uplink_low":145990000,"uplink_high":null,"downlink_low":437800000,"downlink_high":null,"mode":"FM",
  "invert":false,"baud":null,"norad_cat_id":25544},
 {"uuid":"b","description":"APRS","alive":true,"status":"active","type":"Transmitter",
  "uplink_low":null,"uplink_high":null,"downlink_low":145825000,"downlink_high":null,"mode":"AFSK",
  "invert":false,"baud":1200,"norad_cat_id":25544},
 {"uuid":"c","description":"Mode U/V linear","alive":true,"status":"active","type":"Transponder",
  "uplink_low":145935000,"uplink_high":145995000,"downlink_low":435610000,"downlink_high":435670000,
  "mode":"SSB","invert":true,"baud":null,"norad_cat_id":44909},
 {"uuid":"d","description":"old beacon","alive":false,"status":"active","type":"Transmitter",
  "uplink_low":null,"uplink_high":null,"downlink_low":145970000,"downlink_high":null,"mode":"CW",
  "invert":false,"baud":null,"norad_cat_id":7530},
 {"uuid":"e","description":"CW beacon","alive":true,"status":"active","type":"Transmitter",
  "uplink_low":null,"uplink_high":null,"downlink_low":435790000,"downlink_high":null,"mode":"CW",
  "invert":false,"baud":null,"norad_cat_id":800123456},
 {"uuid":"f","description":"unknown object","alive":true,"status":"active","type":"Transmitter",
  "uplink_low":null,"uplink_high":null,"downlink_low":437000000,"downlink_high":null,"mode":"FM",
  "invert":false,"baud":null,"norad_cat_id":null},
 {"uuid":"g","description":"Mode V/U FM, switched off","alive":true,"status":"inactive","type":"Transceiver",
  "uplink_low":145850000,"uplink_high":null,"downlink_low":436795000,"downlink_high":null,"mode":"FM",
  "invert":false,"baud":null,"norad_cat_id":25544}
])";

}  // namespace

TEST_CASE("SatNOGS: every alive, active transmitter a mode; dead, inactive and other objects not offered") {
  Database db = satnogs_db_of({{25544, "ISS"}, {44909, "RS-44"}, {7530, "AO-07"}, {800123456, "NEWSAT"}});
  const SatnogsImport r = import_satnogs(db, kList, false);
  REQUIRE(r.ok());
  CHECK(r.lines == std::vector<std::string>{
                       "ISS FM: added from satnogs (437.800 MHz FM, up 145.990 MHz FM)",
                       "ISS APRS: added from satnogs (145.825 MHz FM)",
                       "RS-44 SSB: added from satnogs (435.640 MHz USB, up 145.965 MHz LSB)",
                       "NEWSAT CW: added from satnogs (435.790 MHz CW)",
                       "4 added, 0 updated, 0 conflicts (yours kept), 0 unchanged; 2 transmitters not alive or "
                       "not active, not offered"});
  CHECK(r.without_transmitter == 1);  // AO-07: its only transmitter is dead
  const Satellite& iss = db.satellites[0];
  REQUIRE(modes_of(iss).size() == 2);  // FM and APRS; the inactive FM transceiver (uuid g) is not one
  CHECK(iss.mode == "FM");
  CHECK(iss.radio.downlink_hz == 437'800'000);
  CHECK(iss.radio.uplink_hz == 145'990'000);
  CHECK(iss.radio.downlink_mode == radio::Mode::fm);
  const auto aprs = find_mode(iss, "APRS");
  REQUIRE(aprs);
  CHECK(aprs->radio.downlink_hz == 145'825'000);
  CHECK(aprs->radio.uplink_mode == radio::Mode::none);
  CHECK(aprs->sources.at("downlink") == radio::FieldSource{"satnogs", "145825000", "", ""});
  const radio::SatelliteRadio& rs44 = db.satellites[1].radio;
  CHECK(rs44.downlink_hz == 435'640'000);  // the passband's centre
  CHECK(rs44.uplink_hz == 145'965'000);
  CHECK(rs44.uplink_mode == radio::Mode::lsb);
  CHECK(rs44.downlink_mode == radio::Mode::usb);
  CHECK(rs44.downlink_low_hz == 435'610'000);
  CHECK(rs44.downlink_high_hz == 435'670'000);
  CHECK(rs44.uplink_low_hz == 145'935'000);
  CHECK(rs44.uplink_high_hz == 145'995'000);
  CHECK(rs44.inverting);
  CHECK(modes_of(db.satellites[2]).empty());
  CHECK(db.satellites[3].radio.uplink_mode == radio::Mode::none);
}

TEST_CASE("SatNOGS: a transponder with an uplink edge missing has no passbands to follow") {
  // Found by fuzz_satnogs (a corpus file): uplink_high without uplink_low read the missing edge.
  struct Case {
    const char* uplink;  // the entry's uplink fields
    radio::Hz uplink_hz;
    radio::Mode uplink_mode;
  };
  for (const Case& c : {Case{R"("uplink_low":null,"uplink_high":145995000)", 0, radio::Mode::none},
                        Case{R"("uplink_high":145995000)", 0, radio::Mode::none},
                        Case{R"("uplink_low":145935000,"uplink_high":null)", 145'935'000, radio::Mode::usb}}) {
    CAPTURE(c.uplink);
    Database db = satnogs_db_of({{44909, "RS-44"}});
    const std::string list = std::string(R"([{"description":"Mode U/V linear","alive":true,"status":"active",
      "type":"Transponder",)") + c.uplink +
                             R"(,"downlink_low":435610000,"downlink_high":435670000,"mode":"SSB","invert":true,
      "norad_cat_id":44909}])";
    const SatnogsImport r = import_satnogs(db, list, false);
    REQUIRE(r.ok());
    const radio::SatelliteRadio& rs44 = db.satellites[0].radio;
    CHECK_FALSE(rs44.has_passbands());
    CHECK_FALSE(rs44.inverting);
    CHECK(rs44.downlink_hz == 435'640'000);
    CHECK(rs44.downlink_mode == radio::Mode::usb);
    CHECK(rs44.uplink_hz == c.uplink_hz);
    CHECK(rs44.uplink_mode == c.uplink_mode);
  }
}

TEST_CASE("SatNOGS: the operator's values stay and the conflict is said, unless replace is asked") {
  Database db = satnogs_db_of({{25544, "ISS"}});
  db.satellites[0].radio.downlink_hz = 437'805'000;  // the operator's record, from before sources
  db.satellites[0].radio.uplink_hz = 145'990'000;
  db.satellites[0].radio.downlink_mode = db.satellites[0].radio.uplink_mode = radio::Mode::fm;
  SatnogsImport r = import_satnogs(db, kList, false);
  REQUIRE(r.ok());
  CHECK(r.report.conflicts ==
        std::vector<std::string>{"ISS FM downlink: kept your 437.805 MHz (operator); satnogs says 437.800 MHz"});
  CHECK(r.report.added == std::vector<std::string>{"ISS APRS: added from satnogs (145.825 MHz FM)"});
  CHECK(db.satellites[0].radio.downlink_hz == 437'805'000);
  // Asked again: the same conflict, said again; nothing else changes.
  r = import_satnogs(db, kList, false);
  CHECK(r.report.conflicts.size() == 1);
  CHECK(r.report.unchanged == 1);  // APRS
  r = import_satnogs(db, kList, true);
  CHECK(r.report.updated ==
        std::vector<std::string>{"ISS FM downlink: 437.800 MHz from satnogs (was 437.805 MHz, operator)"});
  CHECK(db.satellites[0].radio.downlink_hz == 437'800'000);
}

TEST_CASE("SatNOGS: a text that is not a transmitter list changes nothing and says where") {
  Database db = satnogs_db_of({{25544, "ISS"}});
  CHECK(import_satnogs(db, "No GP data found", false).error ==
        "SatNOGS list: not a SatNOGS transmitter list (expected a JSON array of transmitters)");
  CHECK(import_satnogs(db, "{\"detail\":\"Not found.\"}", false).error ==
        "SatNOGS list: not a SatNOGS transmitter list (expected a JSON array of transmitters)");
  // A bad entry after a good one: nothing is applied.
  CHECK(import_satnogs(db, R"([{"norad_cat_id":25544,"alive":true,"status":"active","downlink_low":437800000},
                               {"description":"no number"}])", false).error ==
        "SatNOGS list: transmitter 2: not a transmitter object (no norad_cat_id)");
  CHECK(import_satnogs(db, R"([{"uuid":"x1","norad_cat_id":"25544"}])", false).error ==
        "SatNOGS list: transmitter 1 (x1), field norad_cat_id: expected a catalog number");
  CHECK(import_satnogs(db, R"([{"uuid":"x2","norad_cat_id":25544,"downlink_low":"437.8"}])", false).error ==
        "SatNOGS list: transmitter 1 (x2), field downlink_low: expected a frequency in Hz or null");
  CHECK(modes_of(db.satellites[0]).empty());
}
