// The realtime display's typed tuning (issue 47): S types the spot of a linear transponder, R and T
// the RX and TX offsets, + / - / 0 step the RX offset; all through StationOps, as the page and host
// mode tune. RS-44 a minute before its culmination of 10:58 UTC over the factory station; its shipped
// record: 435.610-435.670 MHz down, 145.935-145.995 MHz up, inverting
// (up = 145.995 MHz - (down - 435.610 MHz)).
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <utility>

#include "fixture.h"
#include "menus/realtime_display.h"
#include "menus/realtime_tuning.h"
#include "radio/doppler.h"
#include "tracker/operations.h"
#include "tracker/station_loop.h"

using namespace tb;

namespace {

struct Rs44 : testing::MenuFixture {
  // Menu 1, RS-44 chosen by its number in the tracking list, then `keys` at the live display and Q.
  explicit Rs44(const std::string& keys) : MenuFixture("", orbit::from_civil(2026, 5, 21, 10, 57, 0)) {
    const auto names = menus::tracking_list_names(*services);
    const auto it = std::find(names.begin(), names.end(), "RS-44");
    REQUIRE(it != names.end());
    term.feed(std::to_string(it - names.begin() + 1) + "\r" + keys + "Q");
    term.timeouts_before_key = 1;
  }
  void run_menu() { menus::menu_1_realtime_tracking(term, *services); }
  radio::Hz down() const { return *radio_sim->frequency(radio::Link::downlink); }
  radio::Hz up() const { return *radio_sim->frequency(radio::Link::uplink); }
  bool said(const std::string& line) const { return term.output().find(line + "\n") != std::string::npos; }
};

}  // namespace

TEST_CASE("parse_spot_hz: MHz with up to 6 decimals, whole Hz, or whole MHz under 1 000 000; nothing else") {
  const std::pair<const char*, std::optional<long long>> cases[] = {
      {"435.645", 435'645'000},
      {"435.645001", 435'645'001},
      {"435.", 435'000'000},
      {"435645000", 435'645'000},
      {"10489.750", 10'489'750'000},
      {"437", 437'000'000},  // under 1 000 000: MHz
      {"999999", 999'999'000'000},
      {"1000000", 1'000'000},  // Hz from there on
      {"435.6450001", std::nullopt},  // below 1 Hz
      {"-435.645", std::nullopt},
      {"+435.645", std::nullopt},
      {"4.35e8", std::nullopt},
      {"435 645", std::nullopt},
      {".645", std::nullopt},
      {"0", std::nullopt},
      {"", std::nullopt},
      {"abc", std::nullopt},
  };
  for (const auto& [text, hz] : cases) {
    CAPTURE(text);
    CHECK(menus::parse_spot_hz(text) == hz);
  }
}

TEST_CASE("parse_offset_hz: a signed whole number of Hz") {
  const std::pair<const char*, std::optional<long long>> cases[] = {
      {"-300", -300},
      {"+120", 120},
      {"120", 120},
      {"0", 0},
      {"12.5", std::nullopt},
      {"+-1", std::nullopt},
      {"-", std::nullopt},
      {"1e3", std::nullopt},
      {"1234567890", std::nullopt},
  };
  for (const auto& [text, hz] : cases) {
    CAPTURE(text);
    CHECK(menus::parse_offset_hz(text) == hz);
  }
}

TEST_CASE("Menu 1: S typed moves RS-44's passband +5 kHz; the dials follow by the transponder's rule") {
  Rs44 f("S435.645\r");
  f.run_menu();
  CHECK(f.said("'S' type the spot  'R'/'T' type the RX/TX offset  'L' log a QSO  'M' mode"));
  CHECK(f.said("Spot (downlink, MHz 435.645 or Hz 435645000) > 435.645"));
  CHECK(f.said("spot 435645000 Hz down, 145960000 Hz up"));
  CHECK(f.station->tuner().downlink_spot_hz() == 435'645'000);
  CHECK(f.station->tuner().uplink_spot_hz() == 145'960'000);
  // The dial is at the new spot with its Doppler: within 10 kHz (RS-44's Doppler on 70 cm near
  // culmination is a few kHz), and the uplink the other way.
  const radio::Hz d = f.down(), u = f.up();
  f.station->tuner().set_spot(435'640'000);
  f.run(1.0);
  CHECK(std::llabs((d - f.down()) - 5'000) < 100);
  CHECK(std::llabs((u - f.up()) + 5'000) < 100);
}

TEST_CASE("Menu 1: T and R typed set the TX and RX offsets, kept for RS-44 and its modes; 0 resets") {
  Rs44 f("T-300\rR+120\r");
  f.run_menu();
  CHECK(f.said("TX offset (Hz, e.g. -300; 0 resets) > -300"));
  CHECK(f.station->tuner().xit_hz() == -300);
  CHECK(f.station->tuner().rit_hz() == 120);
  CHECK(f.model.radio.tx_corrections.size() == 1);
  CHECK(f.model.radio.tx_corrections.begin()->second == -300);
  CHECK(f.model.radio.corrections == std::map<std::string, radio::Hz>{{"RS-44 SSB", 120}});
  CHECK(f.saves >= 3);   // each kept at once
  CHECK(f.term.output().find("RX offset +120 Hz, TX offset -300 Hz (RS-44 SSB)") != std::string::npos);

  Rs44 g("T0\r");
  g.model.radio.tx_corrections = f.model.radio.tx_corrections;
  g.station->reconfigure();
  g.run_menu();
  CHECK(g.station->tuner().xit_hz() == 0);
  CHECK(g.model.radio.tx_corrections.empty());
}

TEST_CASE("Menu 1: a typed value out of range or not a number is refused, naming it and the range; nothing changes") {
  Rs44 f("S437.000\rT200000\rTabc\rSx\rS\r");
  f.run_menu();
  CHECK(f.said("spot 437000000 Hz is outside RS-44's downlink passband 435610000-435670000 Hz"));
  CHECK(f.said("TX offset 200000 Hz out of range: expected -100000 to 100000"));
  CHECK(f.said("TX offset unchanged: 'abc' is not a whole number of Hz: expected -100000 to 100000, e.g. -300"));
  CHECK(f.said("Spot unchanged: 'x' is not a frequency: expected MHz such as 435.645 or Hz such as 435645000"));
  CHECK(f.said("Spot unchanged"));
  CHECK(f.station->tuner().downlink_spot_hz() == 435'640'000);
  CHECK(f.station->tuner().xit_hz() == 0);
  CHECK(f.model.radio.tx_corrections.empty());
}

TEST_CASE("Menu 1: M lists the satellite's modes and chooses one (issue 59); a mode it lacks is refused") {
  Rs44 f("Mxyz\rMft4\rM\r");
  f.run_menu();
  // The shipped RS-44: SSB (its default) and FT4 (data/freqmode.txt).
  CHECK(f.said("Mode (SSB FT4) > xyz"));
  CHECK(f.said("RS-44 has no mode 'xyz': its modes are SSB, FT4"));
  CHECK(f.said("RS-44 FT4: 435611000 Hz down, 145993610 Hz up"));
  CHECK(f.said("Mode unchanged"));
  const auto& rs = f.model.db.satellites[static_cast<std::size_t>(*f.model.db.find("RS-44"))];
  CHECK(rs.mode == "FT4");
  CHECK(rs.radio.downlink_hz == 435'611'000);
  CHECK(f.saves >= 1);
}

TEST_CASE("Menu 1: FM has no passband to move: S is refused with the reason") {
  testing::MenuFixture f("", orbit::from_civil(2026, 5, 21, 13, 47, 0));
  const auto names = menus::tracking_list_names(*f.services);
  const auto it = std::find(names.begin(), names.end(), "ISS");
  REQUIRE(it != names.end());
  f.term.feed(std::to_string(it - names.begin() + 1) + "\rS437.800\rQ");
  f.term.timeouts_before_key = 1;
  menus::menu_1_realtime_tracking(f.term, *f.services);
  CHECK(f.term.output().find("ISS has no transponder passband (its freq/mode record gives no down=LOW-HIGH): its "
                             "frequencies are fixed\n") != std::string::npos);
}

TEST_CASE("Menu 1: the typed keys and + ask for the radio: an outside client holding it is asked about (Y/N)") {
  Rs44 f("T-300\rN+NT-300\rY");
  const tracker::Requester logger{tracker::HolderKind::rigctld, "rigctld 127.0.0.1:40000"};
  // The logger takes the radio once the display runs: before the first key.
  bool taken = false;
  const auto tick = f.term.on_wait;
  f.term.on_wait = [&](std::optional<term::Duration> t) {
    tick(t);
    if (!taken && f.station->tuned()) taken = tracker::StationOps(*f.station, logger).take_radio().ok();
  };
  f.run_menu();
  REQUIRE(taken);
  const std::string& out = f.term.output();
  const std::string question = "rigctld 127.0.0.1:40000 holds it now. Take it back [Y/N] ? ";
  std::size_t asked = 0;
  for (auto p = out.find(question); p != std::string::npos; p = out.find(question, p + 1)) ++asked;
  CHECK(asked == 3);   // T (N), + (N), T (Y)
  CHECK(f.station->tuner().rit_hz() == 0);             // + said N: nothing
  CHECK(f.station->tuner().xit_hz() == -300);           // the last T said Y
  CHECK(f.station->control().holder(tracker::Resource::radio).kind != tracker::HolderKind::rigctld);
}

TEST_CASE("Full screen: what a typed key said stays in the live block under the radio line until the next key") {
  Rs44 f("S437\r");
  f.term.set_full_screen(true);
  f.term.timeouts_before_key = 3;   // three updates after the refusal before Q
  f.run_menu();
  const std::string refusal = "spot 437000000 Hz is outside RS-44's downlink passband 435610000-435670000 Hz";
  const std::string& out = f.term.output();
  std::size_t shown = 0;
  for (auto p = out.find("| dial follow\n" + refusal + "\n"); p != std::string::npos;
       p = out.find("| dial follow\n" + refusal + "\n", p + 1))
    ++shown;
  CHECK(shown >= 3);   // each update's live block, right under the radio line
  CHECK(f.station->tuner().downlink_spot_hz() == 435'640'000);
}
