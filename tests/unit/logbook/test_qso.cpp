#include <doctest/doctest.h>

#include "logbook/qso.h"

using namespace tb::logbook;

// Times: Python's calendar.timegm of the same civil dates.
TEST_CASE("UTC times: civil dates both ways, the accepted spellings, and refusals") {
  CHECK(parse_utc("2026-12-01") == 1796083200);
  CHECK(parse_utc("2026-12-01T21:44:20Z") == 1796161460);
  CHECK(parse_utc("2026-12-01 21:44:20") == 1796161460);
  CHECK(parse_utc("2026-12-01T21:44") == 1796161440);
  CHECK(parse_utc("2000-02-29") == 951782400);
  CHECK(parse_utc("1970-01-01") == 0);
  CHECK_FALSE(parse_utc("2026-02-29"));
  CHECK_FALSE(parse_utc("2026-13-01"));
  CHECK_FALSE(parse_utc("2026-12-01T24:00"));
  CHECK_FALSE(parse_utc("yesterday"));
  CHECK(utc_text(1796161460) == "2026-12-01 21:44:20");
  CHECK(utc_text(951782400) == "2000-02-29 00:00:00");
}

TEST_CASE("Callsigns: letters, digits and '/' with a letter and a digit; the refusal names the field") {
  CHECK_FALSE(check_callsign("call", "W1AW"));
  CHECK_FALSE(check_callsign("call", "VE3/W1AW/P"));
  CHECK_FALSE(check_callsign("call", "4X4XM"));
  CHECK(check_callsign("call", "") == "call: a callsign is needed");
  CHECK(check_callsign("call", "W1 AW") == "call: 'W1 AW' is not a callsign (letters, digits and '/' only)");
  CHECK(check_callsign("call", "W1AW/") == "call: 'W1AW/' is not a callsign (a '/' only between parts)");
  CHECK(check_callsign("station_call", "ABCD") == "station_call: 'ABCD' is not a callsign (it needs a letter and a digit)");
  CHECK(check_callsign("call", "W1") == "call: 'W1' is not a callsign (3 to 20 characters)");
}

TEST_CASE("Grids: Maidenhead of 2, 4, 6 or 8 characters") {
  CHECK_FALSE(check_grid("grid", "FN31"));
  CHECK_FALSE(check_grid("grid", "fn31PR"));
  CHECK_FALSE(check_grid("grid", "DM42ob12"));
  CHECK(check_grid("grid", "FN3").has_value());
  CHECK(check_grid("grid", "SN31").has_value());    // field letters stop at R
  CHECK(check_grid("grid", "FN31py").has_value());  // subsquare letters stop at X
  const auto e = check_grid("my_grid", "12AB");
  REQUIRE(e);
  CHECK(e->rfind("my_grid: '12AB' is not a Maidenhead locator", 0) == 0);
  Qso q;
  q.call = " w1aw ";
  q.grid = "fn31PR";
  q.uplink_hz = 145'965'000;
  q.downlink_hz = 435'640'000;
  q.mode = "ssb";
  const Qso n = normalized(q);
  CHECK(n.call == "W1AW");
  CHECK(n.grid == "FN31pr");
  CHECK(n.mode == "SSB");
  CHECK(n.band == "2m");
  CHECK(n.band_rx == "70cm");
}

TEST_CASE("Bands and the satellite mode from ADIF's band table") {
  CHECK(band_of(145'965'000) == "2m");
  CHECK(band_of(435'640'000) == "70cm");
  CHECK(band_of(2'400'050'000) == "13cm");
  CHECK(band_of(10'489'550'000) == "3cm");
  CHECK(band_of(148'000'001).empty());
  CHECK(band_edges("70cm") == std::pair<std::int64_t, std::int64_t>{420'000'000, 450'000'000});
  CHECK_FALSE(band_edges("11m"));
  CHECK(sat_mode(435'640'000, 145'965'000) == "U/V");
  CHECK(sat_mode(145'850'000, 436'795'000) == "V/U");
  CHECK(sat_mode(2'400'050'000, 10'489'550'000) == "S/X");
  CHECK(sat_mode(7'000'000, 145'000'000).empty());
  CHECK(adif_mode("usb") == "SSB");
  CHECK(adif_mode("lsb") == "SSB");
  CHECK(adif_mode("fm") == "FM");
  CHECK(adif_mode("cwr") == "CW");
}

TEST_CASE("A record's check names the first bad field") {
  Qso q;
  q.call = "W1AW";
  q.mode = "FM";
  CHECK_FALSE(check_qso(q));
  q.mode = "SAT";
  CHECK(check_qso(q) == "mode: the emission (FM, SSB, CW), not SAT");
  q.mode = "FM";
  q.rst_sent = "60";
  CHECK(check_qso(q) == "rst_sent: '60' is not a report (RS like 59 or RST like 599)");
  q.rst_sent = "599";
  q.note = "caf\xc3\xa9";
  CHECK(check_qso(q) == "note: printable ASCII only (ADIF's text fields)");
  q.note.clear();
  q.band = "11m";
  CHECK(check_qso(q) == "band: '11m' is not an ADIF band");
  q.band.clear();
  q.uplink_hz = -1;
  CHECK(check_qso(q) == "uplink_hz: a frequency 0 to 300 GHz in Hz");
  CHECK(source_from_name("WEB") == Source::web);
  CHECK_FALSE(source_from_name("sat"));
}

// Issue 56 item 11: the mode took any text ("<eor>" included) to the logger. ADIF 3.1.4's Mode
// enumeration (the MODE field's values; USB, FT4, C4FM are SUBMODEs of SSB, MFSK, DIGITALVOICE).
TEST_CASE("The mode is one of ADIF's modes; a refusal names the field, a submode its mode") {
  for (const char* m : {"FM", "SSB", "CW", "AM", "FT8", "MFSK", "PSK", "RTTY", "SSTV", "DIGITALVOICE", "PKT", "JT65"})
    CHECK_MESSAGE(is_adif_mode(m), m);
  CHECK_FALSE(check_mode(""));
  CHECK(check_mode("FT4") == "mode: 'FT4' is a submode in ADIF; log it as MFSK");
  CHECK(check_mode("C4FM") == "mode: 'C4FM' is a submode in ADIF; log it as DIGITALVOICE");
  CHECK(check_mode("<EOR>") ==
        "mode: '<EOR>' is not one of ADIF's modes (FM, SSB, CW, AM, FT8, MFSK, PSK, RTTY, SSTV, DIGITALVOICE, ...)");
  Qso q;
  q.call = "W1AW";
  q.mode = "fm<eor><call:5>EVIL1";
  q = normalized(q);
  CHECK(check_qso(q) == "mode: 'FM<EOR><CALL:5>EVIL1' is not one of ADIF's modes (FM, SSB, CW, AM, FT8, MFSK, PSK, "
                        "RTTY, SSTV, DIGITALVOICE, ...)");
  q.mode = "usb";  // the radio's names are mapped
  CHECK(normalized(q).mode == "SSB");
  CHECK_FALSE(check_qso(normalized(q)));
}
