// Menu 3 and 3-1 to 3-4: the manual's transcripts on the shipped satellites, and the model after.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>
#include "test_paths.h"  // TRAKBOX_SOURCE_DIR, ...

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "fixture.h"
#include "tracker/elements_refresh.h"
#include "radio/freqmode.h"

using namespace tb;
using testing::check_shows;
using testing::db_json;
using testing::has;
using testing::count;

namespace {

// '\n' line ends to CR LF, as a terminal program sends them.
std::string crlf(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\n') out += "\r\n";
    else out += c;
  }
  return out;
}

// NASA 3LE text of some satellites of the shipped database (by name), optionally renamed.
std::string nasa_text(const store::Database& db, const std::vector<std::pair<std::string, std::string>>& names) {
  std::string out;
  for (const auto& [name, as] : names) {
    orbit::Elements e = db.satellites[static_cast<std::size_t>(*db.find(name))].elements;
    e.name = as;
    out += orbit::format_nasa(e);
  }
  return out;
}

std::string amsat_text(const store::Database& db, const std::vector<std::string>& names) {
  std::string out = "SB KEPS @ AMSAT $ORBS-141.N\nOrbital Elements 141.AMSAT\n\n";
  for (const auto& name : names) out += orbit::format_amsat(db.satellites[static_cast<std::size_t>(*db.find(name))].elements) + "\n";
  return out + "/EX\n";
}


// Enter on each of the 20 lines of 3-1.
std::string enters(int n) { return std::string(static_cast<std::size_t>(n), '\r'); }

}  // namespace

// ---------------------------------------------------------------------------------------------
// The UPDATE MENU

TEST_CASE("Menu 3 shows the UPDATE MENU; Q returns; other answers ask again") {
  testing::MenuFixture f("9\rQ\r");
  menus::menu_3_update_elements(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(has(out, "======= UPDATE MENU =======\n"
                 "1. EDIT: View/Edit satellite Element by hand\n"
                 "2. SELECT: Select Satellite for list.\n"
                 "3. UPDATE: Clear database & read new Element\n"
                 "4. MULTI TRACK: Configure multi tracking sat\n"
                 "5. REFRESH: Element sources and schedule\n"
                 " Select: 9\n Select: Q\n"));
  CHECK(count(out, "UPDATE MENU") == 1);
}

// ---------------------------------------------------------------------------------------------
// 3-1 Edit

TEST_CASE("Menu 3-1: the manual's transcript — pick #7, Enter on every line keeps everything") {
  testing::MenuFixture f("1\r7\r" + enters(20) + "q\r");
  const std::string before = db_json(f.model);
  menus::menu_3_update_elements(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(has(out, " Select: 1\n     *** Select object satellite ***\n 1.*AO-07"));
  CHECK(!has(out, "17. AO-123"));  // the tracking list (up to 15), as the manual, not the whole database
  CHECK(has(out, "     Select :7\n====== Satellite data ======\n"));
  CHECK(has(out, "Satellite       : AO-73        \n"));
  CHECK(has(out, "Epoch Year Y0   : 26           Y0:\n"));
  CHECK(has(out, "Epoch Time T0   : 140.67569056 T0:\n"));
  CHECK(has(out, "Epoch Rev K0    : "));
  CHECK(has(out, "Mean Anomaly M0 : "));
  CHECK(has(out, "Mean Motion N0  : "));
  CHECK(has(out, "Inclination I0  : "));
  CHECK(has(out, "Eccentricity E0 : "));
  CHECK(has(out, "Arg perigee W0  : "));
  CHECK(has(out, "R.A.A.N. O0     : "));
  CHECK(has(out, "Decay N1        : "));
  CHECK(has(out, "Drag term B*    : "));
  CHECK(has(out, "Downlink Frq.F1 : 145.950      F1:\n"));
  CHECK(has(out, "Offset for F1   : 0.000        F1OFFSET:\n"));
  CHECK(has(out, "Uplink Frq.F2   : 435.140      F2:\n"));
  CHECK(has(out, "Offset for F2   : 0.000        F2OFFSET:\n"));
  CHECK(has(out, "Downlink mode   : USB          \n"));
  CHECK(has(out, "Uplink mode     : LSB          \n"));
  CHECK(has(out, "Doppler correct.: CAT          \n"));
  CHECK(has(out, "LCD MA display  : No           \n"));
  CHECK(has(out, "Satellite (AO-73) updated."));
  // In the manual's order.
  const char* order[] = {"Satellite       :", "Epoch Year Y0", "Epoch Time T0", "Epoch Rev K0", "Mean Anomaly M0",
                         "Mean Motion N0",    "Inclination I0", "Eccentricity E0", "Arg perigee W0", "R.A.A.N. O0",
                         "Decay N1",          "Drag term B*",   "Downlink Frq.F1", "Offset for F1", "Uplink Frq.F2",
                         "Offset for F2",     "Downlink mode",  "Uplink mode",     "Doppler correct.", "LCD MA display"};
  std::size_t at = 0;
  for (const char* label : order) {
    const auto p = out.find(label, at);
    CHECK_MESSAGE(p != std::string::npos, label);
    if (p != std::string::npos) at = p;
  }
  CHECK(db_json(f.model) == before);  // Enter kept every value exactly
  CHECK(count(out, "UPDATE MENU") == 2);  // back at the menu-3 list afterwards
}

TEST_CASE("Menu 3-1: an element and a frequency changed; bad values are refused with the reason") {
  testing::MenuFixture f;
  const int iss = *f.model.db.find("ISS");
  const auto old = f.model.db.satellites[static_cast<std::size_t>(iss)];
  f.term.feed("4\r");                            // ISS
  f.term.feed("\r\r\r\r");                       // name, Y0, T0, K0
  f.term.feed("abc\r10.5\r");                    // M0: not a number, then 10.5
  f.term.feed("\r51.7\r");                       // N0, I0
  f.term.feed("1.5\r0.0005\r");                  // E0: out of range, then fine
  f.term.feed("\r360\r\r");                      // W0; O0: 360 refused, then kept
  f.term.feed("\r\r");                           // N1, B*
  f.term.feed("437.850\r\r\r\r");                // F1, F1 offset, F2, F2 offset
  f.term.feed("usb\rcw\r\r");                    // downlink mode; uplink: CW refused, kept
  f.term.feed("mic\ry\r");                       // Doppler, LCD MA
  menus::menu_3_1_edit(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(has(out, "Mean Anomaly M0 : "));
  CHECK(has(out, "  'abc' is not a number\n"));
  CHECK(has(out, "  1.5 is out of range: expected 0 to 0.9999999\n"));
  CHECK(has(out, "  360 is out of range: expected 0 to less than 360 deg\n"));
  CHECK(has(out, "  'cw': expected FM, LSB, USB or None\n"));
  CHECK(has(out, "Downlink Frq.F1 : 437.800      F1:437.850\n"));
  CHECK(count(out, "Mean Anomaly M0 :") == 2);
  CHECK(count(out, "Uplink mode     :") == 2);

  const auto& now = f.model.db.satellites[static_cast<std::size_t>(iss)];
  CHECK(now.elements.mean_anomaly_deg == 10.5);
  CHECK(now.elements.inclination_deg == 51.7);
  CHECK(now.elements.eccentricity == 0.0005);
  CHECK(now.elements.raan_deg == old.elements.raan_deg);
  CHECK(now.elements.epoch_day == old.elements.epoch_day);
  CHECK(now.elements.mean_motion_rev_per_day == old.elements.mean_motion_rev_per_day);
  CHECK(now.elements.bstar == old.elements.bstar);
  CHECK(now.radio.downlink_hz == 437850000);
  CHECK(now.radio.uplink_hz == old.radio.uplink_hz);
  CHECK(now.radio.downlink_mode == radio::Mode::usb);
  CHECK(now.radio.uplink_mode == old.radio.uplink_mode);
  CHECK(now.radio.doppler == radio::DopplerControl::mic_click);
  CHECK(now.radio.lcd_ma_display);
  CHECK(f.saves == 1);
  // The tracker computes from the edited elements at once.
  const orbit::Sgp4* p = f.tracker.propagator(iss);
  REQUIRE(p != nullptr);
  CHECK(p->elements().inclination_deg == 51.7);
}

TEST_CASE("Menu 3-1: a converter offset, names that must differ, a year and day checked together") {
  testing::MenuFixture f;
  f.term.feed("\r");                                    // Enter: the marked one (#1 AO-07)
  f.term.feed("ISS\rAO-7\r");                           // a name already used, then a new one
  f.term.feed("2025\r");                                // Y0 as four digits
  f.term.feed("366.5\r365.25\r");                       // 2025 has 365 days
  f.term.feed(enters(9));                               // K0 .. B*
  f.term.feed("2400.730\r-2500\r-2256.000\r");          // F1 and its offset (must leave > 0)
  f.term.feed("abc\r\r\r");                             // F2: not a frequency, then kept; F2 offset
  f.term.feed("\r\rcat-ish\rCAT\rmaybe\rNo\r");
  menus::menu_3_1_edit(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(has(out, "  satellite #4 is already called ISS (names must differ)\n"));
  CHECK(has(out, "is not a day of 2025: expected 1 to less than 366"));
  CHECK(has(out, "  the radio would be tuned to -99.270 MHz: the offset must leave more than 0\n"));
  CHECK(has(out, "  'abc' is not a frequency in MHz"));
  CHECK(has(out, "  'cat-ish': expected CAT or Mic-click (C or M)\n"));
  CHECK(has(out, "  'maybe': expected Yes or No\n"));
  const auto& s = f.model.db.satellites[0];
  CHECK(s.name() == "AO-7");
  CHECK(s.elements.epoch_year == 2025);
  CHECK(s.elements.epoch_day == 365.25);
  CHECK(s.radio.downlink_hz == 2400730000);
  CHECK(s.radio.downlink_offset_hz == -2256000000);
  CHECK(s.radio.doppler == radio::DopplerControl::cat);
  CHECK_FALSE(s.radio.lcd_ma_display);
}

TEST_CASE("Menu 3-1: the edit is stored only after the last line; Q at the list changes nothing") {
  testing::MenuFixture f("4\r\r\r\r\r\r\r50\r");  // input ends in the middle
  const std::string before = db_json(f.model);
  CHECK_THROWS_AS(menus::menu_3_1_edit(f.term, *f.services), menus::InputClosed);
  CHECK(db_json(f.model) == before);
  CHECK(f.saves == 0);

  testing::MenuFixture g("Q\r");
  menus::menu_3_1_edit(g.term, *g.services);
  CHECK(db_json(g.model) == before);
  CHECK_FALSE(has(g.term.output(), "Satellite data"));
}

// ---------------------------------------------------------------------------------------------
// 3-2 Select

TEST_CASE("Menu 3-2: the manual's transcript — Y, then numbers build the list in order") {
  testing::MenuFixture f("2\rY\r1\r11\r1\r99\rQ\rq\r");
  menus::menu_3_update_elements(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(has(out, " Select: 2\nAre you sure ? [Y/N] ? Y\n 1. AO-07"));
  CHECK(has(out, "17. AO-123     18. CAS-2T     19. SONATE-2   20. TEVEL2-1\n"));
  CHECK(has(out, "     Select :1\nSatellite (AO-07) selected as #1\n 1.*AO-07"));
  CHECK(has(out, "     Select :11\nSatellite (JO-97) selected as #2\n"));
  CHECK(has(out, "11.*JO-97"));
  CHECK(has(out, "Satellite (AO-07) is already selected as #1\n"));
  CHECK(has(out, "  Enter 1 to 20, or Q (or Enter) to finish\n"));
  CHECK(has(out, "Tracking list: 2 satellite(s) selected.\n"));
  CHECK(f.model.db.selected == std::vector<int>{0, 10});
  // The '*' stays where the list showed it last: on JO-97, #2 (the manual's "the asterisk (*) mark
  // indicates the satellite last selected"); menu 1 offers it on Enter.
  CHECK(f.model.db.marked == 1);
  CHECK(f.saves == 1);
  testing::MenuFixture g("Q\r");
  g.model.db = f.model.db;
  menus::menu_1_realtime_tracking(g.term, *g.services);
  CHECK(has(g.term.output(), " 1. AO-07       2.*JO-97\n"));
}

TEST_CASE("Menu 3-2: at most 15; Enter ends; N and an empty choice keep the old list") {
  std::string keys = "Y";
  for (int n = 1; n <= 16; ++n) keys += std::to_string(n) + "\r";
  testing::MenuFixture f(keys);
  menus::menu_3_2_select(f.term, *f.services);
  CHECK(has(f.term.output(), "Satellite (CSS) selected as #15\nThe tracking list is full (15 satellites).\n"));
  REQUIRE(f.model.db.selected.size() == 15);
  for (int k = 0; k < 15; ++k) CHECK(f.model.db.selected[static_cast<std::size_t>(k)] == k);

  testing::MenuFixture g("Y3\r\r");
  menus::menu_3_2_select(g.term, *g.services);
  CHECK(g.model.db.selected == std::vector<int>{2});

  testing::MenuFixture h("N");
  const auto old = h.model.db.selected;
  menus::menu_3_2_select(h.term, *h.services);
  CHECK(h.model.db.selected == old);
  CHECK_FALSE(has(h.term.output(), "AO-07"));

  testing::MenuFixture k("Y\rQ\r");
  menus::menu_3_2_select(k.term, *k.services);
  CHECK(k.model.db.selected == old);
  CHECK(has(k.term.output(), "No satellite selected: the tracking list is unchanged."));
  CHECK(k.saves == 0);
}

TEST_CASE("Menu 3-2: the satellite followed alone stops being followed when it leaves the list") {
  testing::MenuFixture f("Y2\r3\rQ\r");
  f.tracker.track_single(0);  // AO-07
  f.station->tick();
  menus::menu_3_2_select(f.term, *f.services);
  CHECK(f.model.db.selected == std::vector<int>{1, 2});
  CHECK(f.model.db.marked == 1);  // #2, the one selected last
  CHECK(f.tracker.mode() == tracker::Mode::off);
  CHECK(has(f.term.output(), "Tracking stopped"));

  testing::MenuFixture g("Y1\rQ\r");
  g.tracker.track_single(0);
  g.station->tick();
  menus::menu_3_2_select(g.term, *g.services);
  CHECK(g.tracker.mode() == tracker::Mode::single);  // still listed: tracking goes on
}

// ---------------------------------------------------------------------------------------------
// 3-3 Update

TEST_CASE("Menu 3-3: the manual's transcript — the shipped NASA file and freq/mode file") {
  const std::string dir = TRAKBOX_SOURCE_DIR "/data/";
  const std::string tle = testing::read_file(dir + "amateur.tle");
  const std::string fm = testing::read_file(dir + "freqmode.txt");
  testing::MenuFixture f;
  const std::string shipped = db_json(f.model);
  f.model.db = store::Database{};  // an empty TrakBox
  f.model.db.multi_count = 2;
  f.tracker.track_single(0);
  f.term.feed("3\rY\rN" + crlf(tle) + "\x1a" + crlf(fm) + "\x1a" + "Q\r");
  menus::menu_3_update_elements(f.term, *f.services);
  const std::string& out = f.term.output();
  check_shows(out, {
      " Select: 3\nStored data in memory will be lost.\nAre you sure ? [Y/N] ? Y\n",
      "File format NASA/AMSAT (N/A) : N\nUpload Kepeledata file. (EOF:ctrl+Z)\n",
      // Echoed as received, line by line.
      "AO-07\n1 07530U 74089B   26141.31992461 -.00000054  00000-0 -48931-4 0  9992\n",
      "NASA>#1 AO-07\nNASA>#2 AO-27\nNASA>#3 FO-29\nNASA>#4 ISS\n",
      "NASA>#20 TEVEL2-1\n20 satellite(s) accepted, 0 record(s) skipped.\n",
      "Upload freq/mode data file. (EOF:ctrl+Z)\nAO-07 145.950 432.150 usb lsb cat no "
      "down=145.925-145.975 up=432.125-432.175 inv=y mode=Mode-B\n",
      "Satellite (AO-07) updated and selected as # 1\n",
      "Satellite (QO-100) updated and selected as # 10\n",
      "Satellite (IO-117) updated and selected as # 14\n",
      "     *** Satellite database ***\n 1.*AO-07",
      "Tracking stopped",
  });
  CHECK(count(out, "UPDATE MENU") == 2);  // the menu-3 list again
  CHECK(db_json(f.model) == shipped);
  CHECK(f.tracker.mode() == tracker::Mode::off);
  CHECK(f.saves == 2);  // after each step
}

TEST_CASE("Menu 3-3: a NASA set with a bad checksum is reported with its line and skipped") {
  testing::MenuFixture f;
  std::string text = nasa_text(f.model.db, {{"AO-07", "AO-07"}, {"SO-50", "SO-50"}, {"RS-44", "RS-44"}});
  // Line 5 is SO-50's line 1: spoil its checksum (column 69).
  std::istringstream in(text);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  const char good = lines[4][68];
  lines[4][68] = good == '9' ? '0' : static_cast<char>(good + 1);
  text.clear();
  for (const auto& l : lines) text += l + "\n";
  f.term.feed(std::string("YN") + crlf(text) + "\x1a\x1a");
  menus::menu_3_3_upload(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(has(out, "NASA>#1 AO-07\nNASA>#2 RS-44\n"));
  CHECK(has(out, std::string("Line 5 skipped: checksum (column 69): found '") + lines[4][68] +
                     "', expected checksum " + good + "\n"));
  CHECK(has(out, "2 satellite(s) accepted, 1 record(s) skipped.\n"));
  REQUIRE(f.model.db.satellites.size() == 2);
  CHECK(f.model.db.satellites[1].name() == "RS-44");
  // No freq/mode file: known names keep their radio entries; the list is the first ones.
  CHECK(f.model.db.satellites[1].radio.downlink_hz == 435640000);
  CHECK(f.model.db.selected == std::vector<int>{0, 1});
  CHECK(has(out, "No freq/mode data: known satellites kept their frequencies; the tracking list is the first 2 "
                   "satellite(s) of the database.\n"));
}

TEST_CASE("Menu 3-3: an AMSAT upload written with format_amsat; a damaged AMSAT checksum is skipped") {
  testing::MenuFixture f;
  std::string text = amsat_text(f.model.db, {"AO-07", "FO-29", "HO-113"});
  // Spoil FO-29's checksum line.
  const auto fo = text.find("Satellite: FO-29");
  const auto cs = text.find("Checksum:", fo);
  const auto value = text.find_first_not_of(' ', cs + 9);
  text[value] = text[value] == '9' ? '1' : static_cast<char>(text[value] + 1);
  f.term.feed("Y\rA" + crlf(text) + "\x1a" + "\x1a");
  menus::menu_3_3_upload(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(has(out, "File format NASA/AMSAT (N/A) : A\n"));
  CHECK(has(out, "Satellite: HO-113\n"));  // echoed
  CHECK(has(out, "AMSAT>#1 AO-07\nAMSAT>#2 HO-113\n"));
  CHECK(has(out, "skipped: Checksum (column "));
  CHECK(has(out, "2 satellite(s) accepted, 1 record(s) skipped.\n"));
  REQUIRE(f.model.db.satellites.size() == 2);
  CHECK(f.model.db.satellites[0].elements.source == orbit::ElementFormat::amsat);
  CHECK(f.model.db.satellites[0].elements.inclination_deg ==
        testing::shipped_model().db.satellites[0].elements.inclination_deg);
  CHECK(f.model.db.satellites[0].radio.downlink_hz == 145950000);
}

TEST_CASE("Menu 3-3: an upload cut off before Ctrl-Z, or with nothing usable, leaves the database as it was") {
  testing::MenuFixture f;
  const std::string before = db_json(f.model);
  const std::string text = nasa_text(f.model.db, {{"AO-07", "AO-07"}, {"ISS", "ISS"}});
  f.term.feed("YN" + crlf(text));  // no Ctrl-Z: the line dropped
  f.tracker.track_single(0);
  f.saves = 0;  // (the choice of what to track is stored: not the menu's doing)
  CHECK_THROWS_AS(menus::menu_3_3_upload(f.term, *f.services), menus::InputClosed);
  CHECK(has(f.term.output(), "Upload ended before Ctrl-Z: the stored database is unchanged.\n"));
  CHECK(db_json(f.model) == before);
  CHECK(f.tracker.mode() == tracker::Mode::single);
  CHECK(f.saves == 0);

  testing::MenuFixture g("YNhello there\r\n\x1a" "Q\r");
  menus::menu_3_3_upload(g.term, *g.services);
  CHECK(has(g.term.output(), "0 satellite(s) accepted, 0 record(s) skipped.\n"
                             "No NASA element set found in the upload: the stored database is unchanged.\n"));
  CHECK_FALSE(has(g.term.output(), "freq/mode"));
  CHECK(db_json(g.model) == before);

  testing::MenuFixture h("YA\x1a");  // Ctrl-Z at once
  menus::menu_3_3_upload(h.term, *h.services);
  CHECK(has(h.term.output(), "No satellite data accepted: the stored database is unchanged.\n"));
  CHECK(db_json(h.model) == before);

  testing::MenuFixture k("N");
  menus::menu_3_3_upload(k.term, *k.services);
  CHECK(db_json(k.model) == before);
  CHECK_FALSE(has(k.term.output(), "File format"));
}

TEST_CASE("Menu 3-3: the freq/mode file — a converter offset, case-sensitive names, a bad field") {
  testing::MenuFixture f;
  const std::string text = nasa_text(f.model.db, {{"AO-07", "AO-07"}, {"RS-44", "AO-13S"}, {"ISS", "ISS"}});
  const std::string fm =
      "AO-13S 2400.730/-2256.000 435.620 usb lsb mic ma\n"
      "ao-07 145.950 432.150 usb lsb cat no\n"
      "ISS 43x.1 145.990 fm fm cat no\n"
      "AO-07 145.950 432.150 usb lsb cat no\n";
  f.term.feed("YN" + crlf(text) + "\x1a" + crlf(fm) + "\x1a");
  menus::menu_3_3_upload(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(has(out, "NASA>#1 AO-07\nNASA>#2 AO-13S\nNASA>#3 ISS\n"));
  CHECK(has(out, "AO-13S 2400.730/-2256.000 435.620 usb lsb mic ma\n"));  // echoed
  CHECK(has(out, "Satellite (AO-13S) updated and selected as # 1\n"));
  CHECK(has(out, "Satellite (AO-07) updated and selected as # 2\n"));
  CHECK(has(out, "Skipped line 3, field 2 (downlink frequency): found \"43x.1\", expected"));
  CHECK(has(out, "Skipped line 2: no satellite named (ao-07) in the database, not taken\n"));
  CHECK(has(out, "2 satellite(s) updated and selected, 2 record(s) skipped.\n"));
  const auto& db = f.model.db;
  const auto& ao13 = db.satellites[static_cast<std::size_t>(*db.find("AO-13S"))].radio;
  CHECK(ao13.downlink_hz == 2400730000);
  CHECK(ao13.downlink_offset_hz == -2256000000);
  CHECK(ao13.uplink_hz == 435620000);
  CHECK(ao13.uplink_offset_hz == 0);
  CHECK(ao13.downlink_mode == radio::Mode::usb);
  CHECK(ao13.uplink_mode == radio::Mode::lsb);
  CHECK(ao13.doppler == radio::DopplerControl::mic_click);
  CHECK(ao13.lcd_ma_display);
  CHECK(db.selected == std::vector<int>{1, 0});
  CHECK(db.marked == 0);
  // ISS's bad line was not applied: it keeps the entry it had before the upload.
  CHECK(db.satellites[2].radio.downlink_hz == 437800000);
  CHECK(has(out, "     *** Satellite database ***\n 1. AO-07       2.*AO-13S      3. ISS\n"));
}

TEST_CASE("Menu 3-3: a freq/mode upload cut off keeps the new elements and applies no freq/mode data") {
  testing::MenuFixture f;
  const std::string text = nasa_text(f.model.db, {{"AO-07", "AO-07"}, {"RS-44", "AO-13S"}});
  f.term.feed("YN" + crlf(text) + "\x1a" + "AO-13S 2400.730/-2256.000 435.620 usb lsb mic ma\r\n");
  CHECK_THROWS_AS(menus::menu_3_3_upload(f.term, *f.services), menus::InputClosed);
  CHECK(has(f.term.output(),
            "Upload ended before Ctrl-Z: no freq/mode data applied (the new element data is stored).\n"));
  REQUIRE(f.model.db.satellites.size() == 2);
  CHECK(f.model.db.satellites[1].radio.downlink_hz == 0);
  CHECK(f.model.db.selected == std::vector<int>{0, 1});
  CHECK(f.saves == 1);
}

// ---------------------------------------------------------------------------------------------
// 3-4 Multi Track

TEST_CASE("Menu 3-4: the manual's transcript, and the bounds 2 to 5") {
  testing::MenuFixture f("4\r3\rQ\r");
  menus::menu_3_update_elements(f.term, *f.services);
  CHECK(has(f.term.output(), " Select: 4\nHow many satellites configure for multi tracking mode ? (2-5) 3\n"
                             "The first 3 satellites of the tracking list will be multi-tracked.\n"));
  CHECK(f.model.db.multi_count == 3);
  CHECK(f.saves == 1);

  testing::MenuFixture g("1\r6\rtwo\r5\r");
  menus::menu_3_4_multi_track(g.term, *g.services);
  CHECK(count(g.term.output(), ": enter a number from 2 to 5\n") == 3);
  CHECK(g.model.db.multi_count == 5);

  testing::MenuFixture h("2\r");
  menus::menu_3_4_multi_track(h.term, *h.services);
  CHECK(h.model.db.multi_count == 2);

  testing::MenuFixture k("\r");
  k.model.db.multi_count = 4;
  menus::menu_3_4_multi_track(k.term, *k.services);
  CHECK(k.model.db.multi_count == 4);
  CHECK(has(k.term.output(), "Multi tracking: 4 satellites (unchanged)"));
  CHECK(k.saves == 0);

  testing::MenuFixture m("5\r");
  m.model.db.selected = {0, 1};
  menus::menu_3_4_multi_track(m.term, *m.services);
  CHECK(has(m.term.output(), "Note: the tracking list holds 2 satellite(s); select more with menu 3-2."));
}

TEST_CASE("Menu 3-3: lines may end in CR, LF or CR LF; each is echoed once") {
  testing::MenuFixture f;
  std::string text = nasa_text(f.model.db, {{"AO-07", "AO-07"}, {"ISS", "ISS"}});
  // AO-07's three lines end in CR alone, ISS's in LF alone.
  const auto iss = text.find("ISS\n");
  for (std::size_t k = 0; k < iss; ++k)
    if (text[k] == '\n') text[k] = '\r';
  f.term.feed("YN" + text + "\x1a" + "ISS 437.800 145.990 fm fm cat no\r\n\r\nAO-07 145.950 432.150 usb lsb cat no\r\x1a");
  menus::menu_3_3_upload(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(has(out, "NASA>#1 AO-07\nNASA>#2 ISS\n2 satellite(s) accepted, 0 record(s) skipped.\n"));
  CHECK(count(out, "1 25544U") == 1);
  CHECK(has(out, "Satellite (ISS) updated and selected as # 1\nSatellite (AO-07) updated and selected as # 2\n"));
  CHECK(f.model.db.selected == std::vector<int>{1, 0});
}

TEST_CASE("Menu 3-1 numbers the tracking list, not the database: #1 is the first satellite selected") {
  testing::MenuFixture f("1\r1\rNEWNAME\r" + enters(19) + "q\r");
  auto& db = f.model.db;
  REQUIRE(db.satellites.size() > 16);
  db.selected = {16, 3};
  db.marked = 1;
  const std::string first = db.satellites[16].name(), second = db.satellites[3].name();
  menus::menu_3_update_elements(f.term, *f.services);
  const std::string& out = f.term.output();
  CHECK(has(out, " 1. " + first));
  CHECK(has(out, " 2.*" + second));
  CHECK(db.satellites[16].name() == "NEWNAME");
  CHECK(db.satellites[3].name() == second);
}

TEST_CASE("Menu 3-1 with an empty tracking list offers the whole database") {
  testing::MenuFixture f("1\r17\r" + enters(20) + "q\r");
  f.model.db.selected.clear();
  f.model.db.marked = -1;
  menus::menu_3_update_elements(f.term, *f.services);
  CHECK(has(f.term.output(), "17. AO-123"));
  CHECK(has(f.term.output(), "Satellite (AO-123) updated."));
}

TEST_CASE("Menu 3-3: O takes OMM in every encoding (numbers beyond a TLE's too), and refuses NASA text for it") {
  for (const char* file : {"n800123456.json", "n800123456-spacetrack.json", "n800123456.xml", "n800123456.csv",
                           "n800123456.kvn"}) {
    CAPTURE(file);
    testing::MenuFixture f;
    const std::string omm = testing::read_file(std::string(TRAKBOX_SOURCE_DIR) + "/tests/data/omm/" + file);
    f.term.feed("Y\rO" + crlf(omm) + "\x1a" + "\x1a");
    menus::menu_3_3_upload(f.term, *f.services);
    const std::string& out = f.term.output();
    CHECK(has(out, "(or O: OMM - JSON, XML, CSV or KVN, detected)\nFile format NASA/AMSAT (N/A) : O"));
    CHECK(has(out, "3 satellite(s) accepted, 0 record(s) skipped."));
    REQUIRE(f.model.db.satellites.size() == 3);
    CHECK(f.model.db.satellites[0].elements.catalog_number == 800123456);
    CHECK(f.model.db.satellites[0].elements.source != orbit::ElementFormat::nasa);
    // The state keeps the nine-digit number.
    CHECK(store::model_from_json(store::to_json(f.model)).db.satellites[0].elements.catalog_number == 800123456);
  }
  testing::MenuFixture f;
  const std::string before = db_json(f.model);
  f.term.feed("Y\rO" + crlf(nasa_text(f.model.db, {{"AO-07", "AO-07"}})) + "\x1a");
  menus::menu_3_3_upload(f.term, *f.services);
  CHECK(has(f.term.output(), "expected OMM (JSON, XML, CSV or KVN); answer N or A for NASA or AMSAT text"));
  CHECK(has(f.term.output(), "the stored database is unchanged"));
  CHECK(db_json(f.model) == before);
}
