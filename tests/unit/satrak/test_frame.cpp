#include <doctest/doctest.h>

#include <random>

#include "rotator/satrak/commands.h"
#include "rotator/satrak/frame.h"

using namespace tb::satrak;

namespace {
Decoded frame(std::string payload) {
  const auto sum = checksum(payload);
  return Decoded{Decoded::Kind::frame, std::move(payload), sum, sum};
}
}  // namespace

TEST_CASE("Checksum: the seed's worked example is 6F") {
  CHECK(checksum("DATETIMEG?=,2016,12,22,15,55,40,10") == 0x6F);
  CHECK(encode("DATETIMEG?=,2016,12,22,15,55,40,10") == "$DATETIMEG?=,2016,12,22,15,55,40,10*6F\r\n");
  CHECK(checksum("") == 0);
  CHECK(encode("") == "$*00\r\n");
}

TEST_CASE("Encoder: upper-case hex, CR LF, and what the seed's commands look like on the wire") {
  // Checksums computed independently (XOR of the payload bytes).
  CHECK(encode("VERSION?") == "$VERSION?*65\r\n");
  CHECK(encode("STATUS?") == "$STATUS?*2B\r\n");
  CHECK(encode("STOP=") == "$STOP=*25\r\n");
  CHECK(encode("GOTO=,125.1,32.6") == "$GOTO=,125.1,32.6*1E\r\n");
  CHECK(encode("MOVE=,OK") == "$MOVE=,OK*04\r\n");
  for (unsigned v = 0; v < 256; ++v) {
    const std::string p(1, static_cast<char>(v));
    const std::string e = encode(p);
    const std::string hex = e.substr(e.size() - 4, 2);
    CHECK(hex.find_first_not_of("0123456789ABCDEF") == std::string::npos);
  }
}

TEST_CASE("Decoder: the seed's examples and round trips") {
  Decoder d;
  CHECK(d.feed("$DATETIMEG?=,2016,12,22,15,55,40,10*6F\r\n") == std::vector{frame("DATETIMEG?=,2016,12,22,15,55,40,10")});
  const char* payloads[] = {"VERSION?", "MOVE=,-3.5,0", "STEP=,+2,0", "GOTO=,74.61,NONE", "STOP=",
                            "STATUS?0,299.49,34.35,0,0,0,0,0,0,0,0,0,0,80.0,35.0,1",
                            "TIME=,16,43,0,17,3,2017", "START_STOP_TIME=,20,30,0,11,8,2017,20,35,0,11,8,2017",
                            "SETTINGS=,1,100,1.0,2.0,60000,1,?,6.0,0,2,3.0", "ANGLE_SETTINGS=0,39049,160.0,36838,40.0",
                            "GPS_SETTINGS=,0,41.02N,29.17E", "SATELLITE=,iridium.txt,IRIDIUM 70 [+],1,1",
                            "SATELLITE_HTTP=, https://62bb0cca7bdbe01d529645e6.mockapi.io/Satellite,1,1,0",
                            "SATELLITE_FTP=, 10.0.1.2,username,password,22,1,1", "TRACK_AUTO_ENABLE =,1",
                            "REDUCTION=,4000,4000", ""};
  for (const char* p : payloads) {
    CAPTURE(p);
    CHECK(d.feed(encode(p)) == std::vector{frame(p)});
  }
  CHECK(d.pending() == 0);
}

TEST_CASE("Decoder: liberal in what it takes") {
  Decoder d;
  SUBCASE("lower-case hex") { CHECK(d.feed("$DATETIMEG?=,2016,12,22,15,55,40,10*6f\r\n").at(0).kind == Decoded::Kind::frame); }
  SUBCASE("LF alone, CR alone") {
    CHECK(d.feed("$STATUS?*2B\n") == std::vector{frame("STATUS?")});
    CHECK(d.feed("$STATUS?*2B\r") == std::vector{frame("STATUS?")});
    CHECK(d.feed("\n").empty());  // the LF after a bare CR is an empty line
  }
  SUBCASE("garbage before the $, blanks after the checksum") {
    CHECK(d.feed("\x01\xff junk $STATUS?*2B  \r\n") == std::vector{frame("STATUS?")});
    CHECK(d.feed("$$STATUS?*2B\r\n") == std::vector{frame("STATUS?")});
  }
  SUBCASE("noise lines without $ produce nothing") {
    CHECK(d.feed("hello\r\n\r\n\n  \n").empty());
    CHECK(d.feed(std::string("\0\0\x80\x81\r\n", 6)).empty());
  }
  SUBCASE("binary bytes inside the payload are checksummed like any other") {
    const std::string p = std::string("X\0\x7f\xfe", 4);
    CHECK(d.feed(encode(p)) == std::vector{frame(p)});
  }
}

TEST_CASE("Decoder: every malformed form is reported, never passed on as a frame") {
  Decoder d;
  SUBCASE("no *") {
    const auto r = d.feed("$STATUS?\r\n");
    REQUIRE(r.size() == 1);
    CHECK(r[0].kind == Decoded::Kind::malformed);
    CHECK(r[0].payload == "STATUS?");
  }
  SUBCASE("one hex digit, three hex digits") {
    CHECK(d.feed("$STATUS?*0\r\n").at(0).kind == Decoded::Kind::malformed);
    CHECK(d.feed("$STATUS?*2B0\r\n").at(0).kind == Decoded::Kind::malformed);
  }
  SUBCASE("bad hex") {
    const auto r = d.feed("$STATUS?*0G\r\n");
    REQUIRE(r.size() == 1);
    CHECK(r[0].kind == Decoded::Kind::malformed);
    CHECK(r[0].payload == "STATUS?");
  }
  SUBCASE("bad checksum: a distinct result carrying both sums") {
    const auto r = d.feed("$GOTO=,125.1,32.6*1F\r\n");
    REQUIRE(r.size() == 1);
    CHECK(r[0].kind == Decoded::Kind::bad_checksum);
    CHECK(r[0].payload == "GOTO=,125.1,32.6");
    CHECK(r[0].expected == 0x1E);
    CHECK(r[0].found == 0x1F);
  }
  SUBCASE("overlong: reported once, as soon as it overflows, then discarded to the line end") {
    Decoder small(64);
    std::vector<Decoded> out;
    small.feed("$GOTO=,", out);
    for (int i = 0; i < 1000; ++i) small.feed("1234567890", out);  // 10 kB, no line end
    REQUIRE(out.size() == 1);
    CHECK(out[0].kind == Decoded::Kind::overlong);
    CHECK(out[0].payload.rfind("GOTO=,1234", 0) == 0);
    CHECK(small.pending() == 0);  // nothing held while discarding
    small.feed("*00\r\n", out);   // the end of the long line: still discarded
    CHECK(out.size() == 1);
    small.feed(encode("STATUS?"), out);  // the next line is decoded again
    REQUIRE(out.size() == 2);
    CHECK(out[1] == frame("STATUS?"));
  }
  SUBCASE("a line exactly at the bound is fine") {
    Decoder small(16);
    const std::string p = "ABCDEFGHIJKLM";  // $ + 13 + *HH = 17 > 16
    CHECK(small.feed(encode(p)).at(0).kind == Decoded::Kind::overlong);
    const std::string q = "ABCDEFGHIJKL";  // 16
    CHECK(small.feed(encode(q)) == std::vector{frame(q)});
  }
}

TEST_CASE("Decoder: frames split across reads at every position, and several frames in one read") {
  const std::string wire = encode("GOTO=,125.1,32.6") + encode("STATUS?") + "noise\r\n" + encode("TPOS?");
  const std::vector<Decoded> want = {frame("GOTO=,125.1,32.6"), frame("STATUS?"), frame("TPOS?")};
  {
    Decoder d;
    CHECK(d.feed(wire) == want);
  }
  for (std::size_t cut = 0; cut <= wire.size(); ++cut) {
    Decoder d;
    std::vector<Decoded> out;
    d.feed(wire.substr(0, cut), out);
    d.feed(wire.substr(cut), out);
    CAPTURE(cut);
    CHECK(out == want);
  }
  {
    Decoder d;
    std::vector<Decoded> out;
    for (char c : wire) d.feed(std::string_view(&c, 1), out);
    CHECK(out == want);
  }
}

TEST_CASE("Decoder: random garbage never grows memory past the bound or crashes") {
  std::mt19937 rng(7);
  Decoder d(128);
  std::vector<Decoded> out;
  for (int round = 0; round < 2000; ++round) {
    std::string chunk(static_cast<std::size_t>(rng() % 300), '\0');
    for (char& c : chunk) c = static_cast<char>(rng() % 256);
    d.feed(chunk, out);
    CHECK(d.pending() <= 128);
  }
  for (const auto& e : out)
    if (e.kind == Decoded::Kind::frame) CHECK(checksum(e.payload) == e.found);
  // Afterwards a good frame still comes through.
  out.clear();
  d.feed("\r\n" + encode("STATUS?"), out);
  CHECK(out.back() == frame("STATUS?"));
}

TEST_CASE("Payload parser: liberal forms of the seed") {
  auto p = [](std::string_view s) { return parse_payload(s); };
  CHECK(p("MOVE=,1,-1") == Command{"MOVE", Kind::request, {"1", "-1"}});
  CHECK(p("STOP=") == Command{"STOP", Kind::request, {}});
  CHECK(p("STOP=,") == Command{"STOP", Kind::request, {}});
  CHECK(p("VERSION?") == Command{"VERSION", Kind::query, {}});
  CHECK(p("ANGLE_SETTINGS=0,39049,160.0,36838,40.0") ==
        Command{"ANGLE_SETTINGS", Kind::request, {"0", "39049", "160.0", "36838", "40.0"}});
  CHECK(p("TRACK_AUTO_ENABLE =,1") == Command{"TRACK_AUTO_ENABLE", Kind::request, {"1"}});
  CHECK(p("SATELLITE_HTTP=, https://x.io/Satellite,1,1,0") ==
        Command{"SATELLITE_HTTP", Kind::request, {"https://x.io/Satellite", "1", "1", "0"}});
  CHECK(p("SATELLITE=,iridium.txt,IRIDIUM 70 [+],1,1") ==
        Command{"SATELLITE", Kind::request, {"iridium.txt", "IRIDIUM 70 [+]", "1", "1"}});
  CHECK(p("STATUS?0,299.49,34.35") == Command{"STATUS", Kind::query, {"0", "299.49", "34.35"}});
  CHECK(p("goto=,1,2") == Command{"GOTO", Kind::request, {"1", "2"}});
  CHECK(p("GOTO=,,5") == Command{"GOTO", Kind::request, {"", "5"}});
  CHECK(p("DATETIMEG?=,2016,12") == Command{"DATETIMEG", Kind::query, {"2016", "12"}});
  CHECK(p("MOVE=,ERR,5") == Command{"MOVE", Kind::request, {"ERR", "5"}});
  CHECK_FALSE(p("STATUS"));
  CHECK_FALSE(p("=,1"));
  CHECK_FALSE(p("GO-TO=,1"));
  CHECK_FALSE(p(std::string_view("\x01\x02?", 3)));
  // Found by fuzzing: blanks inside the word, and words of any length, were taken, and the unit
  // echoed them in its refusals (a tab in a reply, a reply past the peer's line bound).
  CHECK_FALSE(p("STATU\tS?"));
  CHECK_FALSE(p("TRACK AUTO=,1"));
  CHECK(p(std::string(32, 'A') + "?") == Command{std::string(32, 'A'), Kind::query, {}});
  CHECK_FALSE(p(std::string(33, 'A') + "?"));
  CHECK(p("GOTO=,1,2")->head() == "GOTO=");
  CHECK(p("STATUS?")->head() == "STATUS?");
}

TEST_CASE("Replies and field readers") {
  CHECK(reply_ok("MOVE=") == "MOVE=,OK");
  CHECK(reply_error("MOVE=", Error::parameter_count) == "MOVE=,ERR,5");
  CHECK(reply_error("", Error::frame_too_long) == "ERR,3");
  CHECK(reply_values("TPOS?", {"1.00", "2.00"}) == "TPOS?,1.00,2.00");
  CHECK(sanitize_word("ab\x01-c_1") == "ABC_1");
  CHECK(parse_number("+2") == 2.0);
  CHECK(parse_number("-3.5") == -3.5);
  CHECK(parse_number(".5") == 0.5);
  CHECK_FALSE(parse_number("1e3"));
  CHECK_FALSE(parse_number("nan"));
  CHECK_FALSE(parse_number(""));
  CHECK_FALSE(parse_number("1,2"));
  CHECK_FALSE(parse_number("--1"));
  CHECK(parse_integer("+12") == 12);
  CHECK_FALSE(parse_integer("1.5"));
  CHECK(parse_latitude("41.01N") == doctest::Approx(41.01));
  CHECK(parse_latitude("12.5s") == doctest::Approx(-12.5));
  CHECK(parse_latitude("-33.9") == doctest::Approx(-33.9));
  CHECK_FALSE(parse_latitude("91N"));
  CHECK_FALSE(parse_latitude("41E"));
  CHECK_FALSE(parse_latitude("-41N"));
  CHECK(parse_longitude("29.17E") == doctest::Approx(29.17));
  CHECK(parse_longitude("110.778W") == doctest::Approx(-110.778));
  CHECK_FALSE(parse_longitude("181E"));
  CHECK(format_latitude(-12.5) == "12.5000S");
  CHECK(format_longitude(29.17) == "29.1700E");
  CHECK(format_fixed(-0.001, 2) == "0.00");
  CHECK(format_fixed(299.494, 2) == "299.49");
  for (int e = 1; e <= 12; ++e) CHECK(std::string(describe(static_cast<Error>(e))) != "error");
}
