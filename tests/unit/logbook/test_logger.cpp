// The logger's texts and decisions (logbook/logger.h) with exact values. The replies are the ones
// Cloudlog's and Wavelog's application/controllers/Api.php write (functions qso and radio): their
// json_encode of the arrays shown there, PHP's escaping of '/' included.
#include <doctest/doctest.h>

#include "logbook/adif.h"
#include "logbook/logger.h"
#include "support/qso_samples.h"

#include <cctype>
#include <string>
#include <vector>

using namespace tb::logbook;

TEST_CASE("--logger takes cloudlog:URL, wavelog:URL or none; a refusal names the option and the fault") {
  const auto c = parse_logger_spec("cloudlog:https://log.example.org/");
  REQUIRE_MESSAGE(c.spec, c.error);
  CHECK(c.spec->kind == LoggerKind::cloudlog);
  CHECK(c.spec->base_url == "https://log.example.org");
  CHECK(radio_url(*c.spec) == "https://log.example.org/index.php/api/radio");
  CHECK(qso_url(*c.spec) == "https://log.example.org/index.php/api/qso");
  CHECK(logger_spec_text(*c.spec) == "cloudlog:https://log.example.org");
  const auto w = parse_logger_spec("wavelog:http://10.0.0.5:8086/wavelog");
  REQUIRE(w.spec);
  CHECK(w.spec->kind == LoggerKind::wavelog);
  CHECK(qso_url(*w.spec) == "http://10.0.0.5:8086/wavelog/index.php/api/qso");
  CHECK(logger_kind_name(w.spec->kind) == "wavelog");
  const auto n = parse_logger_spec("none");
  CHECK(n.none);
  CHECK_FALSE(n.spec);
  CHECK(n.error.empty());
  const auto u = parse_logger_spec("cloudlog:https://op:hunter2@log.example.org");
  REQUIRE(u.spec);
  CHECK(logger_display_url(*u.spec) == "https://op:<redacted>@log.example.org");

  CHECK(parse_logger_spec("qrz:https://x.org").error ==
        "--logger: expected cloudlog:URL, wavelog:URL or none; found 'qrz:https://x.org'");
  CHECK(parse_logger_spec("cloudlog").error ==
        "--logger: cloudlog: the logger's URL is missing (cloudlog:https://log.example.org)");
  CHECK(parse_logger_spec("cloudlog:ftp://log.example.org").error ==
        "--logger: 'ftp://log.example.org' is not an http:// or https:// URL");
  CHECK(parse_logger_spec("wavelog:https://log.example.org/?key=1").error ==
        "--logger: 'https://log.example.org/?key=1': the base URL has no query, fragment, white space or control "
        "characters (the API's paths are added to it)");
  CHECK(parse_logger_spec("cloudlog:https:///x").error == "--logger: 'https:///x' has no host");
  CHECK(parse_logger_spec("cloudlog:http://u:pw@:80").error == "--logger: 'http://u:<redacted>@:80' has no host");
}

TEST_CASE("The radio state's body: the satellite fields only while tracking") {
  RadioState r{true, "RS-44", 145'962'310, 435'648'070, "LSB", "USB"};
  CHECK(radio_body("k3y\"", r) ==
        R"({"key":"k3y\"","radio":"trakbox","frequency":"145962310","mode":"LSB","frequency_rx":"435648070",)"
        R"("mode_rx":"USB","prop_mode":"SAT","sat_name":"RS-44"})");
  r.tracking = false;
  CHECK(radio_body("k", r) ==
        R"({"key":"k","radio":"trakbox","frequency":"145962310","mode":"LSB","frequency_rx":"435648070",)"
        R"("mode_rx":"USB","prop_mode":"","sat_name":""})");
}

TEST_CASE("When the radio state is posted") {
  const RadioState idle{false, "", 145'990'000, 437'800'000, "FM", "FM"};
  RadioState iss{true, "ARISS", 145'990'000, 437'800'000, "FM", "FM"};
  CHECK_FALSE(radio_post_due(std::nullopt, idle, 1000));  // idle from the start: nothing
  CHECK(radio_post_due(std::nullopt, iss, 1000));          // the first state while tracking
  const RadioPosted posted{iss, 1000};
  CHECK_FALSE(radio_post_due(posted, iss, 1001));
  RadioState moved = iss;
  moved.downlink_hz += 1000;  // at the threshold: not yet
  CHECK_FALSE(radio_post_due(posted, moved, 1010));
  moved.downlink_hz += 1;
  CHECK(radio_post_due(posted, moved, 1010));
  moved = iss;
  moved.uplink_hz -= 1001;
  CHECK(radio_post_due(posted, moved, 1010));
  moved = iss;
  moved.mode_rx = "USB";
  CHECK(radio_post_due(posted, moved, 1010));
  moved = iss;
  moved.sat_name = "SO-50";
  CHECK(radio_post_due(posted, moved, 1010));
  CHECK_FALSE(radio_post_due(posted, iss, 1000 + 299));
  CHECK(radio_post_due(posted, iss, 1000 + 300));        // at least every 5 minutes while tracking
  CHECK(radio_post_due(posted, idle, 1002));             // once when tracking ends
  const RadioPosted ended{idle, 1002};
  CHECK_FALSE(radio_post_due(ended, idle, 1003));        // then nothing while idle
  CHECK_FALSE(radio_post_due(ended, idle, 1002 + 3600));
  CHECK(radio_post_due(ended, iss, 5000));               // the next pass
}

TEST_CASE("The QSO's body: one ADIF record, no header") {
  const Qso q = tb::testing::rs44_qso();
  const std::string record =
      "<CALL:4>W1AW <QSO_DATE:8>20261201 <TIME_ON:6>214420 <MODE:3>SSB <BAND:2>2m <FREQ:10>145.965000 "
      "<BAND_RX:4>70cm <FREQ_RX:10>435.640000 <PROP_MODE:3>SAT <SAT_NAME:5>RS-44 <SAT_MODE:3>V/U "
      "<GRIDSQUARE:4>FN31 <MY_GRIDSQUARE:4>DM42 <STATION_CALLSIGN:6>WA7GXD <RST_SENT:2>59 <RST_RCVD:2>57 "
      "<TX_PWR:3>2.5 <COMMENT:17>first <RS-44> QSO <APP_TRAKBOX_SAT:5>RS-44 <APP_TRAKBOX_NORAD:5>44909 "
      "<APP_TRAKBOX_FREQ_TUNED:9>145962310 <APP_TRAKBOX_FREQ_RX_TUNED:9>435648070 <APP_TRAKBOX_SOURCE:3>web <EOR>\n";
  CHECK(adif_record(q) == record);
  std::string sent = record.substr(0, record.size() - 1);  // what a logger gets: no '<' or '>' in the note
  sent.replace(sent.find("first <RS-44> QSO"), 17, "first (RS-44) QSO");
  CHECK(qso_body("k3y", 2, q) == R"({"key":"k3y","station_profile_id":"2","type":"adif","string":")" + sent +
                                     R"(\n"})");
}

TEST_CASE("Cloudlog's api/qso replies: imported_count counts the records stored") {
  const auto cl = LoggerKind::cloudlog;
  CHECK(judge_qso_reply(cl, 201, R"({"status":"created","type":"adif","string":"<CALL:4>W1AW <EOR>","imported_count":1,"messages":[]})")
            .accepted);
  // The record already there (an upload whose answer was lost): the logger has it.
  const auto dup = judge_qso_reply(
      cl, 201, R"({"status":"created","type":"adif","string":"","imported_count":0,"messages":["Date\/Time: 2026-12-01 21:44:20 Callsign: W1AW Band: 2m  Duplicate<br>"]})");
  CHECK(dup.accepted);
  CHECK(dup.duplicate);
  CHECK(dup.message == "Date/Time: 2026-12-01 21:44:20 Callsign: W1AW Band: 2m Duplicate");
  // Refused by the import: a 201 that stored nothing.
  const auto wrong = judge_qso_reply(
      cl, 201, R"({"status":"created","type":"adif","string":"","imported_count":0,"messages":["Wrong station callsign <b>\"WA7GXD\"<\/b> while importing QSO with W1AW for <b>N0CALL<\/b> : SKIPPED"]})");
  CHECK_FALSE(wrong.accepted);
  CHECK(wrong.message == "Wrong station callsign \"WA7GXD\" while importing QSO with W1AW for N0CALL : SKIPPED");
  const auto none = judge_qso_reply(cl, 201, R"({"status":"created","type":"adif","string":"","imported_count":0,"messages":[]})");
  CHECK_FALSE(none.accepted);
  CHECK(none.message == "the logger stored no record (imported_count 0)");
  // An old Cloudlog's 201 without a count proves nothing; nor does Wavelog's shape to Cloudlog.
  CHECK(judge_qso_reply(cl, 201, R"({"status":"created","type":"adif","string":"x"})").message ==
        "HTTP 201 without imported_count: not the logger's API reply");
  CHECK_FALSE(judge_qso_reply(cl, 201, R"({"status":"created","type":"adif","string":"","adif_count":1,"adif_errors":0,"messages":[""]})")
                  .accepted);
  // The refusals before any record is read.
  CHECK(judge_qso_reply(cl, 401, R"({"status":"failed","reason":"missing api key"})").message == "HTTP 401: missing api key");
  CHECK(judge_qso_reply(cl, 401, R"({"status":"failed","reason":"station id does not belong to the API key owner."})")
            .message == "HTTP 401: station id does not belong to the API key owner.");
  CHECK(judge_qso_reply(cl, 200, R"({"status":"failed","reason":"wrong JSON"})").message == "HTTP 200: wrong JSON");
  CHECK(judge_qso_reply(cl, 200, "").message == "HTTP 200: an empty reply");
  CHECK(judge_qso_reply(cl, 500, "<html><body>Internal Server Error</body></html>").message ==
        "HTTP 500: not the logger's API reply: Internal Server Error");
}

// Recorded from Wavelog 2.0.5 (commit 4342ff10, Api.php qso()), PHP's json_encode escaping '/'.
TEST_CASE("Wavelog's api/qso replies: 201 with adif_errors 0 is stored, a 400 duplicate is done") {
  const auto wl = LoggerKind::wavelog;
  const auto stored = judge_qso_reply(
      wl, 201, R"({"status":"created","type":"adif","string":"","adif_count":1,"adif_errors":0,"messages":[""]})");
  CHECK(stored.accepted);
  CHECK_FALSE(stored.duplicate);
  CHECK(stored.message.empty());
  const auto dup = judge_qso_reply(
      wl, 400,
      R"({"status":"abort","type":"adif","string":"","adif_count":1,"adif_errors":1,"messages":["","Date\/Time: 2026-05-21 23:20:11 Callsign: DL1ABC Band: 2m Duplicate for WA7GXD<br>"]})");
  CHECK(dup.accepted);
  CHECK(dup.duplicate);
  CHECK(dup.message == "Date/Time: 2026-05-21 23:20:11 Callsign: DL1ABC Band: 2m Duplicate for WA7GXD");
  // A 400 that is not a duplicate (a refused record) is a problem, in the logger's words.
  const auto bad = judge_qso_reply(
      wl, 400,
      R"({"status":"abort","type":"adif","string":"","adif_count":1,"adif_errors":1,"messages":["","Station callsign <b>WA7GXD<\/b> does not match"]})");
  CHECK_FALSE(bad.accepted);
  CHECK(bad.message == "HTTP 400: Station callsign WA7GXD does not match");
  // A duplicate among two refusals of one record is not enough.
  CHECK_FALSE(judge_qso_reply(wl, 400,
                              R"({"status":"abort","adif_count":1,"adif_errors":1,"messages":["","x Duplicate for A","other"]})")
                  .accepted);
  CHECK(judge_qso_reply(wl, 201, R"({"status":"created","adif_count":0,"adif_errors":0,"messages":[""]})").message ==
        "the logger read 0 record(s) with 0 error(s)");
  CHECK(judge_qso_reply(wl, 201, R"({"status":"created","type":"adif","string":""})").message ==
        "HTTP 201 without adif_count and adif_errors: not Wavelog's API reply");
  // A Wavelog that answers as Cloudlog did (imported_count) is read by Cloudlog's rule.
  CHECK(judge_qso_reply(wl, 201, R"({"status":"created","type":"adif","string":"","imported_count":1,"messages":[""]})")
            .accepted);
  CHECK(judge_qso_reply(wl, 401, R"({"status":"failed","reason":"missing api key"})").message == "HTTP 401: missing api key");
  CHECK(judge_qso_reply(wl, 200, R"({"status":"failed","reason":"wrong JSON"})").message == "HTTP 200: wrong JSON");
}

TEST_CASE("api/radio's replies: success with 200 (Cloudlog) or 201") {
  CHECK(judge_radio_reply(200, R"({"status":"success"})").accepted);
  CHECK(judge_radio_reply(201, R"({"status":"success"})").accepted);
  CHECK_FALSE(judge_radio_reply(302, R"({"status":"success"})").accepted);
  CHECK(judge_radio_reply(401, R"({"status":"failed","reason":"missing api key"})").message == "HTTP 401: missing api key");
  CHECK(judge_radio_reply(404, R"({"status":"failed","reason":"missing radio element in payload"})").message ==
        "HTTP 404: missing radio element in payload");
  CHECK_FALSE(judge_radio_reply(200, "").accepted);
}

// Issue 56 item 1: 201 {"messages":[[[[...]]]]} 100,000 deep (200 kB) ended the station with
// SIGSEGV (no bound, then a recursive copy of "messages"); a "reason" nested as deep on a 500 too.
TEST_CASE("A reply nested 100,000 deep is refused by the nesting bound, not a crash") {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  for (const auto kind : {LoggerKind::cloudlog, LoggerKind::wavelog}) {
    const auto v = judge_qso_reply(kind, 201, R"({"status":"created","imported_count":1,"messages":)" + deep + "}");
    CHECK_FALSE(v.accepted);
    CHECK(v.message == "HTTP 201: not the logger's API reply: JSON nested deeper than 64 levels");
  }
  std::string objects;
  for (int i = 0; i < 100000; ++i) objects += R"({"a":)";
  objects += "1" + std::string(100000, '}');
  CHECK(judge_qso_reply(LoggerKind::cloudlog, 500, R"({"status":"failed","reason":)" + objects + "}").message ==
        "HTTP 500: not the logger's API reply: JSON nested deeper than 64 levels");
  CHECK(judge_radio_reply(200, R"({"status":)" + deep + "}").message ==
        "HTTP 200: not the logger's API reply: JSON nested deeper than 64 levels");
  // Within the bound, members that are not what they should be are read by reference and refused.
  CHECK(judge_qso_reply(LoggerKind::cloudlog, 201, R"({"status":"created","imported_count":1,"messages":[[1],{"a":2}]})")
            .message == "(a message that is not text); (a message that is not text)");
}

// Issue 56 item 9: a reply quoting the key put it verbatim in trakbox.log, stderr and status.
TEST_CASE("The key quoted in a reply is redacted, in any case, before the text is cut") {
  const std::string key = "cl64f0a1b2c3d4e5KEY";
  const auto v = judge_qso_reply(LoggerKind::cloudlog, 401, R"({"status":"failed","reason":"the key 'cl64f0a1b2c3d4e5KEY' is not valid"})",
                                 key);
  CHECK(v.message == "HTTP 401: the key '<redacted>' is not valid");
  CHECK(judge_radio_reply(401, R"({"status":"failed","reason":"bad key CL64F0A1B2C3D4E5key"})", key).message ==
        "HTTP 401: bad key <redacted>");
  // Not JSON, the key at the place where the text is cut: no piece of it stays.
  const std::string html = "<p>" + std::string(110, 'x') + " " + key + "</p>";
  const auto h = judge_qso_reply(LoggerKind::wavelog, 403, html, key);
  CHECK(h.message.find("cl64") == std::string::npos);
  CHECK(h.message == "HTTP 403: not the logger's API reply: " + std::string(110, 'x') + " <redac...");
  const auto w = judge_qso_reply(LoggerKind::wavelog, 400,
                                 R"({"status":"abort","adif_count":1,"adif_errors":1,"messages":["","key cl64f0a1b2c3d4e5KEY refused"]})", key);
  CHECK(w.message == "HTTP 400: key <redacted> refused");
}

// Issue 56 item 11: Adif_parser.php splits on <eor> whatever the lengths say, so a note holding
// "<eor><call:5>EVIL1" made a second record at the logger.
TEST_CASE("What goes to a logger is one record: no '<' or '>' in any text field") {
  Qso q = tb::testing::rs44_qso();
  q.note = "hi <eor><call:5>EVIL1 <eor>";
  q.sat_name = "RS<44>";
  std::vector<std::string> changed;
  const std::string body = qso_body("k", 1, q, &changed);
  CHECK(changed == std::vector<std::string>{"APP_TRAKBOX_SAT", "COMMENT"});
  CHECK(body.find("<COMMENT:27>hi (eor)(call:5)EVIL1 (eor) ") != std::string::npos);
  CHECK(body.find("<APP_TRAKBOX_SAT:6>RS(44) ") != std::string::npos);
  // Split as the logger's parser splits: one record before the one <EOR>.
  std::string lower = body;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  CHECK(lower.find("<eor>") == lower.rfind("<eor>"));
  CHECK(lower.find("evil1") < lower.find("<eor>"));
  // The stored QSO keeps what was typed; only what is sent changes.
  CHECK(for_logger(q).note == "hi (eor)(call:5)EVIL1 (eor)");
  CHECK(q.note == "hi <eor><call:5>EVIL1 <eor>");
}

TEST_CASE("The retry backoff: 30 s doubling to 30 minutes") {
  CHECK(upload_backoff_s(1) == 30);
  CHECK(upload_backoff_s(2) == 60);
  CHECK(upload_backoff_s(3) == 120);
  CHECK(upload_backoff_s(6) == 960);
  CHECK(upload_backoff_s(7) == 1800);
  CHECK(upload_backoff_s(8) == 1800);
  CHECK(upload_backoff_s(1000) == 1800);
  CHECK(upload_backoff_s(0) == 30);
}
