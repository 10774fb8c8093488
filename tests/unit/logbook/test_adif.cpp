#include <doctest/doctest.h>

#include "logbook/adif.h"
#include "logbook/qso.h"
#include "logbook/lotw_names.h"
#include "support/qso_samples.h"

using namespace tb::logbook;

namespace {
Qso rs44() { return tb::testing::rs44_qso(); }
Qso iss() { return tb::testing::iss_qso(); }
}  // namespace

TEST_CASE("An RS-44 QSO in ADIF 3.1.4: uplink in BAND/FREQ, TQSL's name, the emission as MODE") {
  const AdifExport e = write_adif({rs44()}, "0.1.0", 1796161460);
  CHECK(e.warnings.empty());
  CHECK(e.text ==
        "trakbox satellite log, ADIF 3.1.4\n"
        "<ADIF_VER:5>3.1.4 <PROGRAMID:7>trakbox <PROGRAMVERSION:5>0.1.0 <CREATED_TIMESTAMP:15>20261201 214420 <EOH>\n"
        "<CALL:4>W1AW <QSO_DATE:8>20261201 <TIME_ON:6>214420 <MODE:3>SSB <BAND:2>2m <FREQ:10>145.965000 "
        "<BAND_RX:4>70cm <FREQ_RX:10>435.640000 <PROP_MODE:3>SAT <SAT_NAME:5>RS-44 <SAT_MODE:3>V/U "
        "<GRIDSQUARE:4>FN31 <MY_GRIDSQUARE:4>DM42 <STATION_CALLSIGN:6>WA7GXD <RST_SENT:2>59 <RST_RCVD:2>57 "
        "<TX_PWR:3>2.5 <COMMENT:17>first <RS-44> QSO <APP_TRAKBOX_SAT:5>RS-44 <APP_TRAKBOX_NORAD:5>44909 "
        "<APP_TRAKBOX_FREQ_TUNED:9>145962310 <APP_TRAKBOX_FREQ_RX_TUNED:9>435648070 <APP_TRAKBOX_SOURCE:3>web <EOR>\n");
}

TEST_CASE("A QSO logged before the station's callsign was set: exported with a warning") {
  const AdifExport e = write_adif({iss()}, "0.1.0", 0);
  REQUIRE(e.warnings.size() == 1);
  CHECK(e.warnings[0] == "QSO 2 (K1JT): no STATION_CALLSIGN (logged before the station's callsign was set); "
                         "TQSL asks which callsign it was made with");
  CHECK(e.text.find("STATION_CALLSIGN") == std::string::npos);
}

TEST_CASE("Export then import is the identity on every field") {
  const AdifExport e = write_adif({rs44(), iss()}, "0.1.0", 0);
  CHECK(e.text.find("<SAT_NAME:5>ARISS") != std::string::npos);
  const AdifRead r = read_adif(e.text);
  REQUIRE_MESSAGE(r.ok(), r.error);
  REQUIRE(r.qsos.size() == 2);
  Qso a = rs44(), b = iss();
  a.id = b.id = 0;  // ids are the logbook's
  CHECK(r.qsos[0] == a);
  CHECK(r.qsos[1] == b);
}

TEST_CASE("An FT4 QSO: MODE MFSK with SUBMODE FT4, read back as it was (issue 59)") {
  Qso q = rs44();
  q.mode = "MFSK";
  q.submode = "FT4";
  const std::string rec = adif_record(q);
  CHECK(rec.find("<MODE:4>MFSK <SUBMODE:3>FT4 <BAND:2>2m") != std::string::npos);
  const AdifRead r = read_adif(rec);
  REQUIRE_MESSAGE(r.ok(), r.error);
  q.id = 0;
  CHECK(r.qsos.at(0) == q);
  CHECK(adif_record(rs44()).find("SUBMODE") == std::string::npos);  // none when there is none
}

TEST_CASE("Satellite mode names as ADIF's MODE and SUBMODE") {
  using P = std::pair<std::string, std::string>;
  CHECK(adif_of_mode_name("FT4") == P{"MFSK", "FT4"});
  CHECK(adif_of_mode_name("ft4") == P{"MFSK", "FT4"});
  CHECK(adif_of_mode_name("PSK31") == P{"PSK", "PSK31"});
  CHECK(adif_of_mode_name("SSB") == P{"SSB", ""});
  CHECK(adif_of_mode_name("FM") == P{"FM", ""});
  CHECK(adif_of_mode_name("SSTV") == P{"SSTV", ""});
  CHECK(adif_of_mode_name("APRS") == P{"PKT", ""});
  CHECK_FALSE(adif_of_mode_name("Mode-A"));
  CHECK_FALSE(adif_of_mode_name("default"));
}

TEST_CASE("A satellite without a LoTW name: a warning and no SAT_NAME, never a guessed one") {
  Qso q = iss();
  q.sat_name = "CSS";
  q.lotw_name.clear();
  q.norad = 48274;
  q.station_call = "JA6XYZ";
  const AdifExport e = write_adif({q}, "0.1.0", 0);
  REQUIRE(e.warnings.size() == 1);
  CHECK(e.warnings[0] == "QSO 2 (K1JT, CSS): no LoTW name for NORAD 48274; SAT_NAME left out, LoTW will not match it as a satellite QSO");
  CHECK(e.text.find("SAT_NAME") == std::string::npos);
  CHECK(e.text.find("<PROP_MODE:3>SAT") != std::string::npos);
}

TEST_CASE("Field lengths count bytes; text between fields is ignored; no header when the file begins with '<'") {
  const AdifRead r = read_adif(
      "<call:5>G4XYZ junk <QSO_DATE:8:D>20261201 <TIME_ON:4>2144 <MODE:2>FM <FREQ:7>145.990 <FREQ_RX:7>437.800\n"
      "<PROP_MODE:3>SAT <SAT_NAME:5>ARISS <eor>");
  REQUIRE_MESSAGE(r.ok(), r.error);
  REQUIRE(r.qsos.size() == 1);
  CHECK(r.qsos[0].call == "G4XYZ");
  CHECK(r.qsos[0].time_on == 1796161440);
  CHECK(r.qsos[0].uplink_hz == 145'990'000);
  CHECK(r.qsos[0].downlink_hz == 437'800'000);
  CHECK(r.qsos[0].band == "2m");
  CHECK(r.qsos[0].sat_name == "ARISS");
  CHECK(r.qsos[0].source == Source::import);
  CHECK(parse_mhz_hz("145.9650000") == 145'965'000);
  CHECK_FALSE(parse_mhz_hz("145.9650001"));
  CHECK(mhz_text(10'489'550'000) == "10489.550000");
}

TEST_CASE("Every refusal names the record and the field; nothing is returned from a bad file") {
  const std::string good = "<CALL:4>W1AW <QSO_DATE:8>20261201 <TIME_ON:6>214420 <PROP_MODE:3>SAT <EOR>\n";
  CHECK(read_adif(good).ok());
  const auto err = [&](const std::string& second) {
    const AdifRead r = read_adif(good + second);
    CHECK(r.qsos.empty());
    return r.error;
  };
  CHECK(err("<CALL:4>W1AW <QSO_DATE:8>20261301 <TIME_ON:6>214420 <PROP_MODE:3>SAT <EOR>") ==
        "record 2: QSO_DATE: '20261301' is not a date (YYYYMMDD)");
  CHECK(err("<CALL:4>W1AW <QSO_DATE:8>20261201 <TIME_ON:6>256000 <PROP_MODE:3>SAT <EOR>") ==
        "record 2: TIME_ON: '256000' is not a time (HHMM or HHMMSS)");
  CHECK(err("<CALL:5>W1 AW <QSO_DATE:8>20261201 <TIME_ON:6>214420 <PROP_MODE:3>SAT <EOR>") ==
        "record 2: CALL: 'W1 AW' is not a callsign (letters, digits and '/' only)");
  CHECK(err("<CALL:4>W1AW <QSO_DATE:8>20261201 <TIME_ON:6>214420 <PROP_MODE:3>SAT <MODE:3>SAT <EOR>") ==
        "record 2: MODE: the emission (FM, SSB, CW), not SAT");
  CHECK(err("<CALL:4>W1AW <QSO_DATE:8>20261201 <TIME_ON:6>214420 <PROP_MODE:3>SAT <BAND:4>70cm <FREQ:7>145.990 <EOR>") ==
        "record 2: BAND: 70cm does not hold 145.990000 MHz");
  CHECK(err("<CALL:4>W1AW <CALL:4>K1JT <EOR>") == "record 2: CALL: the field appears twice");
  CHECK(err("<CALL:40>W1AW <EOR>") == "record 2: CALL: its length 40 runs past the end of the file");
  CHECK(err("<CALL:4>W1AW <QSO_DATE:8>20261201 <TIME_ON:6>214420 <PROP_MODE:3>SAT <GRIDSQUARE:4>ZZ99 <EOR>")
            .rfind("record 2: GRIDSQUARE: 'ZZ99' is not a Maidenhead locator", 0) == 0);
  CHECK(err("<CALL:4>W1AW <QSO_DATE:8>20261201 <TIME_ON:6>214420 <PROP_MODE:3>SAT") == "record 2: no <EOR> after its fields");
  CHECK(err("<CALL:4>W1AW <QSO_DATE:8>20261201 <TIME_ON:6>214420 <SAT_NAME:2>\xc3\xa9 <EOR>") ==
        "record 2: SAT_NAME: printable ASCII only (an .adi file's text fields)");
  CHECK(read_adif("a header without its end").error == "header: no <EOH> (a file that does not begin with '<' has a header)");
}

TEST_CASE("Records that are not satellite QSOs are skipped and listed, the satellite ones kept") {
  // A general logger's export: an HF QSO (PROP_MODE absent, no SAT_NAME), a sporadic-E one
  // (PROP_MODE ES, even with a bad time: a skipped record is not judged), and one via RS-44.
  const AdifRead r = read_adif(
      "exported by a general logger <ADIF_VER:5>3.1.4 <EOH>\n"
      "<CALL:5>DL1AB <QSO_DATE:8>20261201 <TIME_ON:4>1200 <BAND:3>20m <FREQ:6>14.074 <MODE:3>FT8 <EOR>\n"
      "<CALL:4>k1jt <QSO_DATE:8>20261201 <TIME_ON:4>9999 <PROP_MODE:2>es <EOR>\n"
      "<CALL:4>W1AW <QSO_DATE:8>20261201 <TIME_ON:6>214420 <PROP_MODE:3>SAT <SAT_NAME:5>RS-44 <EOR>\n"
      "<CALL:4>N0CC <QSO_DATE:8>20261201 <TIME_ON:6>214420 <SAT_NAME:5>AO-91 <EOR>\n");
  REQUIRE_MESSAGE(r.ok(), r.error);
  REQUIRE(r.qsos.size() == 2);
  CHECK(r.qsos[0].call == "W1AW");
  CHECK(r.qsos[1].lotw_name == "AO-91");
  REQUIRE(r.skipped.size() == 2);
  CHECK(r.skipped[0].record == 1);
  CHECK(r.skipped[0].call == "DL1AB");
  CHECK(r.skipped[0].why == "neither PROP_MODE SAT nor SAT_NAME");
  CHECK(r.skipped[1].record == 2);
  CHECK(r.skipped[1].call == "K1JT");
  CHECK(r.skipped[1].why == "PROP_MODE ES, not SAT");
  // A satellite record's refusal still refuses the whole file, counted among all the records.
  const AdifRead bad = read_adif("<CALL:5>DL1AB <EOR>\n<CALL:4>W1AW <QSO_DATE:8>20261301 <TIME_ON:4>1200 <PROP_MODE:3>SAT <EOR>");
  CHECK(bad.error == "record 2: QSO_DATE: '20261301' is not a date (YYYYMMDD)");
  CHECK(bad.qsos.empty());
}

TEST_CASE("The shipped NORAD to LoTW table parses and names RS-44, ISS and GreenCube as TQSL does") {
  const LotwNames t = parse_lotw_names("# comment\n44909 RS-44 # Radio Sputnik 44\n\n25544 ARISS\n53106 IO-117\n");
  REQUIRE(t.error.empty());
  CHECK(t.name(44909) == "RS-44");
  CHECK(t.name(25544) == "ARISS");
  CHECK(t.name(53106) == "IO-117");
  CHECK(t.name(48274).empty());
  CHECK(parse_lotw_names("44909 RS-44\n44909 RS-45\n").error == "line 2: NORAD 44909 is named twice");
  CHECK(parse_lotw_names("RS-44 44909\n").error == "line 1: 'RS-44' is not a NORAD number");
  CHECK(parse_lotw_names("44909 RS 44\n").error == "line 1: the name is one word (TQSL's spelling)");
}

#include "test_paths.h"

TEST_CASE("data/lotw-satellites.txt: every shipped name is in TQSL's list spelling") {
  const LotwNames t = load_lotw_names(std::string(TRAKBOX_SOURCE_DIR) + "/data/lotw-satellites.txt");
  REQUIRE_MESSAGE(t.error.empty(), t.error);
  CHECK(t.by_norad.size() == 15);
  CHECK(t.name(44909) == "RS-44");
  CHECK(t.name(25544) == "ARISS");
  CHECK(t.name(7530) == "AO-7");
  CHECK(t.name(43700) == "QO-100");
}
