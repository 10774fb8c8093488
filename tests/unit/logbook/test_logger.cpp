// The logger's texts and decisions (logbook/logger.h) with exact values. The replies are the ones
// Cloudlog's and Wavelog's application/controllers/Api.php write (functions qso and radio): their
// json_encode of the arrays shown there, PHP's escaping of '/' included.
#include <doctest/doctest.h>

#include "logbook/adif.h"
#include "logbook/logger.h"
#include "support/qso_samples.h"

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
  CHECK(qso_body("k3y", 2, q) == R"({"key":"k3y","station_profile_id":"2","type":"adif","string":")" +
                                     record.substr(0, record.size() - 1) + R"(\n"})");
}

TEST_CASE("api/qso's replies as Cloudlog and Wavelog write them") {
  // Cloudlog, one record stored.
  CHECK(judge_qso_reply(201, R"({"status":"created","type":"adif","string":"<CALL:4>W1AW <EOR>","imported_count":1,"messages":[]})")
            .accepted);
  // Wavelog: the count of records read, messages [""] (its import's errors are not returned).
  CHECK(judge_qso_reply(201, R"({"status":"created","type":"adif","string":"","imported_count":1,"messages":[""]})")
            .accepted);
  // Cloudlog, the record already there (an upload whose answer was lost): the logger has it.
  const auto dup = judge_qso_reply(
      201, R"({"status":"created","type":"adif","string":"","imported_count":0,"messages":["Date\/Time: 2026-12-01 21:44:20 Callsign: W1AW Band: 2m  Duplicate<br>"]})");
  CHECK(dup.accepted);
  CHECK(dup.duplicate);
  CHECK(dup.message == "Date/Time: 2026-12-01 21:44:20 Callsign: W1AW Band: 2m Duplicate");
  // Cloudlog, refused by the import: a 201 that stored nothing.
  const auto wrong = judge_qso_reply(
      201, R"({"status":"created","type":"adif","string":"","imported_count":0,"messages":["Wrong station callsign <b>\"WA7GXD\"<\/b> while importing QSO with W1AW for <b>N0CALL<\/b> : SKIPPED"]})");
  CHECK_FALSE(wrong.accepted);
  CHECK(wrong.message == "Wrong station callsign \"WA7GXD\" while importing QSO with W1AW for N0CALL : SKIPPED");
  const auto none = judge_qso_reply(201, R"({"status":"created","type":"adif","string":"","imported_count":0,"messages":[]})");
  CHECK_FALSE(none.accepted);
  CHECK(none.message == "the logger stored no record (imported_count 0)");
  // An old Cloudlog's 201 without a count proves nothing.
  CHECK(judge_qso_reply(201, R"({"status":"created","type":"adif","string":"x"})").message ==
        "HTTP 201 without imported_count: not the logger's API reply");
  // The refusals before any record is read.
  CHECK(judge_qso_reply(401, R"({"status":"failed","reason":"missing api key"})").message == "HTTP 401: missing api key");
  CHECK(judge_qso_reply(401, R"({"status":"failed","reason":"station id does not belong to the API key owner."})")
            .message == "HTTP 401: station id does not belong to the API key owner.");
  CHECK(judge_qso_reply(200, R"({"status":"failed","reason":"wrong JSON"})").message == "HTTP 200: wrong JSON");
  CHECK(judge_qso_reply(200, "").message == "HTTP 200: an empty reply");
  CHECK(judge_qso_reply(500, "<html><body>Internal Server Error</body></html>").message ==
        "HTTP 500: not the logger's API reply: Internal Server Error");
}

TEST_CASE("api/radio's replies") {
  CHECK(judge_radio_reply(200, R"({"status":"success"})").accepted);
  CHECK(judge_radio_reply(401, R"({"status":"failed","reason":"missing api key"})").message == "HTTP 401: missing api key");
  CHECK(judge_radio_reply(404, R"({"status":"failed","reason":"missing radio element in payload"})").message ==
        "HTTP 404: missing radio element in payload");
  CHECK_FALSE(judge_radio_reply(200, "").accepted);
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
