// The SatNOGS DB transmitter list into the database's freq/mode records (store/satnogs.h). The
// list is written here with the fields the SatNOGS API documents (norad_cat_id, description,
// alive, status, type, uplink/downlink low/high in Hz, mode, invert).
#include <doctest/doctest.h>

#include <string>

#include "store/satnogs.h"

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
  "invert":false,"baud":null,"norad_cat_id":null}
])";

}  // namespace

TEST_CASE("SatNOGS: transceivers, inverting transponders, beacons; dead transmitters and other objects ignored") {
  Database db = db_of({{25544, "ISS"}, {44909, "RS-44"}, {7530, "AO-07"}, {800123456, "NEWSAT"}});
  const SatnogsImport r = import_satnogs(db, kList, false);
  REQUIRE(r.ok());
  CHECK(r.updated == std::vector<std::string>{
                         "ISS: downlink 437.800 FM, uplink 145.990 FM (FM voice)",
                         "RS-44: downlink 435.640 USB, uplink 145.965 LSB (inverting transponder) (Mode U/V linear)",
                         "NEWSAT: downlink 435.790 CW (CW beacon)"});
  CHECK(r.without_transmitter == 1);  // AO-07: its only transmitter is dead
  const radio::SatelliteRadio& iss = db.satellites[0].radio;
  CHECK(iss.downlink_hz == 437'800'000);
  CHECK(iss.uplink_hz == 145'990'000);
  CHECK(iss.downlink_mode == radio::Mode::fm);
  CHECK(iss.uplink_mode == radio::Mode::fm);
  const radio::SatelliteRadio& rs44 = db.satellites[1].radio;
  CHECK(rs44.downlink_hz == 435'640'000);  // the passband's centre
  CHECK(rs44.uplink_hz == 145'965'000);
  CHECK(rs44.uplink_mode == radio::Mode::lsb);
  CHECK(rs44.downlink_mode == radio::Mode::usb);
  // The passband edges, for dial follow; the ISS's FM transceiver has none.
  CHECK(rs44.downlink_low_hz == 435'610'000);
  CHECK(rs44.downlink_high_hz == 435'670'000);
  CHECK(rs44.uplink_low_hz == 145'935'000);
  CHECK(rs44.uplink_high_hz == 145'995'000);
  CHECK(rs44.inverting);
  CHECK_FALSE(iss.has_passbands());
  CHECK_FALSE(db.satellites[2].radio.has_downlink());
  CHECK(db.satellites[3].radio.uplink_mode == radio::Mode::none);
}

TEST_CASE("SatNOGS: a transponder with an uplink edge missing has no passbands to follow") {
  // Found by fuzz_satnogs (a corpus file): uplink_high without uplink_low read the missing edge.
  struct Case {
    const char* uplink;  // the entry's uplink fields
    radio::Hz uplink_hz;
    radio::Mode uplink_mode;
    const char* updated;
  };
  for (const Case& c : {Case{R"("uplink_low":null,"uplink_high":145995000)", 0, radio::Mode::none,
                             "RS-44: downlink 435.640 USB (Mode U/V linear)"},
                        Case{R"("uplink_high":145995000)", 0, radio::Mode::none,
                             "RS-44: downlink 435.640 USB (Mode U/V linear)"},
                        Case{R"("uplink_low":145935000,"uplink_high":null)", 145'935'000, radio::Mode::usb,  // the one edge there is
                             "RS-44: downlink 435.640 USB, uplink 145.935 USB (Mode U/V linear)"}}) {
    CAPTURE(c.uplink);
    Database db = db_of({{44909, "RS-44"}});
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
    CHECK(r.updated == std::vector<std::string>{c.updated});
  }
}

TEST_CASE("SatNOGS: the operator's own records stay unless replace is asked") {
  Database db = db_of({{25544, "ISS"}});
  db.satellites[0].radio.downlink_hz = 145'800'000;
  SatnogsImport r = import_satnogs(db, kList, false);
  CHECK(r.updated.empty());
  CHECK(r.kept == std::vector<std::string>{"ISS"});
  CHECK(db.satellites[0].radio.downlink_hz == 145'800'000);
  r = import_satnogs(db, kList, true);
  CHECK(r.updated.size() == 1);
  CHECK(db.satellites[0].radio.downlink_hz == 437'800'000);
}

TEST_CASE("SatNOGS: a text that is not a transmitter list changes nothing and says so") {
  Database db = db_of({{25544, "ISS"}});
  CHECK(import_satnogs(db, "No GP data found", false).error ==
        "not a SatNOGS transmitter list (expected a JSON array of transmitters)");
  CHECK(import_satnogs(db, "{\"detail\":\"Not found.\"}", false).error ==
        "not a SatNOGS transmitter list (expected a JSON array of transmitters)");
  // A bad entry after a good one: nothing is applied.
  CHECK(import_satnogs(db, R"([{"norad_cat_id":25544,"alive":true,"status":"active","downlink_low":437800000},
                               {"description":"no number"}])", false).error ==
        "transmitter 2: not a transmitter object (no norad_cat_id)");
  CHECK(import_satnogs(db, R"([{"norad_cat_id":"25544"}])", false).error ==
        "transmitter 1: norad_cat_id is not a whole number");
  CHECK_FALSE(db.satellites[0].radio.has_downlink());
}

TEST_CASE("SatNOGS: a description is shown as printable UTF-8, cut at 80 bytes, whatever was downloaded") {
  Database db = db_of({{25544, "ISS"}});
  // An escape sequence (clear screen), a C1 control, an invalid byte, and a paragraph.
  const std::string list = R"([{"description":"FM\u001b[2J voice\u0085 \u00e9)" + std::string("\xff") + R"( )" +
                           std::string(100, 'x') + R"(","alive":true,"status":"active","type":"Transceiver",
    "uplink_low":145990000,"uplink_high":null,"downlink_low":437800000,"downlink_high":null,"mode":"FM",
    "invert":false,"norad_cat_id":25544}])";
  const SatnogsImport r = import_satnogs(db, list, false);
  // An invalid byte makes the list not JSON at all: nothing changes.
  CHECK_FALSE(r.ok());
  const std::string valid = R"([{"description":"FM\u001b[2J voice\u0085 \u00e9 )" + std::string(100, 'x') +
                            R"(","alive":true,"status":"active","type":"Transceiver",
    "uplink_low":145990000,"uplink_high":null,"downlink_low":437800000,"downlink_high":null,"mode":"FM",
    "invert":false,"norad_cat_id":25544}])";
  const SatnogsImport ok = import_satnogs(db, valid, false);
  REQUIRE(ok.ok());
  REQUIRE(ok.updated.size() == 1);
  const std::string& line = ok.updated[0];
  CHECK(line.find('\x1b') == std::string::npos);
  CHECK(line.find("\xc2\x85") == std::string::npos);
  CHECK(line.find("\xc3\xa9") != std::string::npos);   // é is kept
  CHECK(line.rfind("ISS: downlink 437.800 FM, uplink 145.990 FM (FM", 0) == 0);
  // 80 bytes kept; the two control characters each became U+FFFD (3 bytes for 1 and 2).
  CHECK(line.size() == std::string("ISS: downlink 437.800 FM, uplink 145.990 FM ()").size() + 80 + 2 + 1);
}
