// The radio registry (radio/registry.h) and the --radio parser that reads it: every entry's form
// parses, defaults come from the table, bad specs say what is wrong, Hamlib models go by name too.
#include <doctest/doctest.h>

#include <set>

#include "radio/factory.h"
#include "radio/hamlib/hamlib_models.h"
#include "radio/registry.h"

using namespace tb::radio;

TEST_CASE("registry: names are unique, every model has a factory and a sane description") {
  std::set<std::string_view> names;
  for (const RadioModel& m : radio_models()) {
    CAPTURE(m.name);
    CHECK(names.insert(m.name).second);
    CHECK(static_cast<bool>(m.make));
    CHECK(!m.label.empty());
    CHECK((m.caps.links == 1 || m.caps.links == 2));
    CHECK(m.caps.step_hz > 0);
    CHECK((m.satmode == SatCommand::none || m.caps.satellite_mode));
    // A model named in the table is found by its name, and its spec form starts with it.
    CHECK(find_radio_model(m.name) == &m);
    CHECK(spec_form(m).rfind(std::string(m.name), 0) == 0);
  }
  for (const char* n : {"ic9700", "ic9100", "ic910h", "ic821h", "ic275", "ic970", "ic705", "ts2000", "ts790", "ft847",
                        "ft817", "ft818", "ft736", "ic905", "ic7300", "ic7100", "ic706mkiig", "ft857", "ft897",
                        "ft991", "ftx1", "ft710", "ftdx10", "icom", "kenwood", "yaesu", "cat", "hamlib", "rigctld", "sim"})
    CHECK_MESSAGE(find_radio_model(n) != nullptr, n);
  CHECK(find_radio_model("simulated") == find_radio_model("sim"));
  CHECK(find_radio_model("IC9700") == find_radio_model("ic9700"));   // any case, as Hamlib names are (issue 47)
}

TEST_CASE("registry: the satellite rigs' defaults") {
  const RadioModel& ic9700 = *find_radio_model("ic9700");
  CHECK(ic9700.civ_address == 0xA2);              // docs/radio.md, Hamlib ic9700.c
  CHECK(ic9700.satmode == SatCommand::icom_16_5a);
  CHECK(ic9700.main_link == Link::downlink);      // satellite mode: Main receives, Sub transmits
  CHECK(ic9700.hamlib_model == 3081);
  CHECK(ic9700.caps.links == 2);
  CHECK(ic9700.caps.reads);
  CHECK(ic9700.caps.ctcss);
  CHECK(ic9700.caps.reads_tx_1c03);                 // 1C 03: the IC-9700 only
  for (const char* other : {"ic9100", "ic910h", "ic705"}) CHECK_FALSE(find_radio_model(other)->caps.reads_tx_1c03);
  CHECK(find_radio_model("ic9100")->civ_address == 0x7C);
  CHECK(find_radio_model("ic910h")->civ_address == 0x60);
  CHECK(find_radio_model("ic910h")->satmode == SatCommand::icom_1a_07);   // Hamlib ic910.c
  CHECK(find_radio_model("ic910h")->main_link == Link::uplink);
  CHECK(find_radio_model("ic705")->civ_address == 0xA4);
  CHECK(find_radio_model("ft847")->satmode == SatCommand::ft847);
  CHECK(find_radio_model("ft817")->caps.links == 1);
  CHECK(find_radio_model("ft736")->caps.reads == false);
  CHECK(find_radio_model("ts2000")->hamlib_model == 2014);
  CHECK(find_radio_model_by_hamlib(3081) == &ic9700);
  CHECK(find_radio_model_by_hamlib(1001) == find_radio_model("ft847"));
  CHECK(find_radio_model_by_hamlib(2) == nullptr);   // rigctld is no radio model
  CHECK(find_radio_model_by_hamlib(1) == nullptr);
  CHECK(find_radio_model_by_hamlib(3073) == find_radio_model("ic7300"));
  CHECK(find_radio_model_by_hamlib(3078) == nullptr);   // the IC-7610: through Hamlib only
}

TEST_CASE("--radio MODEL:DEVICE[:BAUD]: parsed from the table") {
  auto a = parse_radio_spec("ic9700:/dev/ttyUSB0");
  REQUIRE(a.spec);
  CHECK(a.spec->name == "ic9700");
  CHECK(find_radio_model(a.spec->name)->protocol == Protocol::icom);   // the row says the protocol
  CHECK(a.spec->device == "/dev/ttyUSB0");
  CHECK(a.spec->baud == 0);
  CHECK_FALSE(a.spec->main_link);
  auto b = parse_radio_spec("ic9100:/dev/ttyUSB1:9600:maindown");
  REQUIRE(b.spec);
  CHECK(b.spec->baud == 9600);
  CHECK(b.spec->main_link == Link::downlink);
  CHECK(find_radio_model(parse_radio_spec("ft847:/dev/ttyS0").spec->name)->protocol == Protocol::ft847);
  CHECK(parse_radio_spec("ts2000:/dev/ttyS0:57600").spec->baud == 57600);
  CHECK(parse_radio_spec("ft818:/dev/ttyS0").spec->name == "ft818");
  // The model in any case, as hamlib:IC-9700 is (issue 47).
  const auto upper = parse_radio_spec("IC9700:/dev/ttyUSB0:19200");
  REQUIRE(upper.spec);
  CHECK(upper.spec->name == "ic9700");
  CHECK(upper.spec->baud == 19200);

  // Bad specs name what is wrong.
  CHECK(parse_radio_spec("ic9700").error ==
        "--radio \"ic9700\": missing DEVICE; expected ic9700:DEVICE[:BAUD][:maindown|:mainup], e.g. ic9700:/dev/ttyUSB0");
  CHECK(parse_radio_spec("ic9700:/dev/x:12345").error == "--radio \"ic9700:/dev/x:12345\": BAUD 12345 is not a serial speed (300..230400)");
  CHECK(parse_radio_spec("ic9700:/dev/x:fast").error.find("\"fast\" is not a serial speed") != std::string::npos);
  CHECK(parse_radio_spec("ft817:/dev/x:mainup").error ==
        "--radio \"ft817:/dev/x:mainup\": \"mainup\": the Yaesu FT-817 has no Main/Sub satellite mode to choose bands for");
  CHECK(parse_radio_spec("ic9700:/dev/x:19200:7").error.find("too many fields") == std::string::npos);   // 7: not a speed
  CHECK(parse_radio_spec("ic9700:/dev/x:19200:7").error.find("BAUD 7 is not a serial speed") != std::string::npos);
  CHECK(parse_radio_spec("sim:/dev/x").error == "--radio \"sim:/dev/x\": sim takes no device");
  const auto unknown = parse_radio_spec("ic9800:/dev/x", "--uplink-radio");
  CHECK(unknown.error.rfind("--uplink-radio \"ic9800:/dev/x\": unknown radio \"ic9800\"; expected one of sim, cat, icom,", 0) == 0);
  CHECK(unknown.error.find("ic9700") != std::string::npos);
}

TEST_CASE("hamlib:NAME: Hamlib models by name, case and punctuation ignored") {
  CHECK(parse_radio_spec("hamlib:IC-9700:/dev/ttyUSB0").spec->model == 3081);
  CHECK(parse_radio_spec("hamlib:ic9700:/dev/ttyUSB0:19200").spec->model == 3081);
  CHECK(parse_radio_spec("hamlib:ft-847:/dev/ttyUSB0").spec->model == 1001);
  CHECK(parse_radio_spec("hamlib:TS2000:/dev/ttyUSB0").spec->model == 2014);
  CHECK(hamlib_rig_by_name("Icom IC-9100").model == 3068);
  CHECK(model_key("IC-9700") == "ic9700");
  const auto near = parse_radio_spec("hamlib:IC-9701:/dev/x");
  CHECK_FALSE(near.spec);
  CHECK(near.error.find("Hamlib has no rig model named \"IC-9701\"; near: ") != std::string::npos);
  CHECK(near.error.find("Icom IC-9700 (3081)") != std::string::npos);
  CHECK(parse_radio_spec("hamlib:--:/dev/x").error.find("is not a Hamlib model number or name") != std::string::npos);
}

TEST_CASE("--radio list prints every entry of the table") {
  const std::string text = radio_list_text();
  for (const RadioModel& m : radio_models()) CHECK(text.find(spec_form(m)) != std::string::npos);
  CHECK(text.find("ic9700:DEVICE[:BAUD][:maindown|:mainup]") != std::string::npos);
}

TEST_CASE("make_radio: each model's driver from the table, one of two radios without satellite mode") {
  RadioConfig cfg;
  auto ic = make_radio("ic9700:/nonexistent/tty", cfg);
  REQUIRE(ic.driver);
  CHECK(ic.driver->describe() == "Icom IC-9700 CI-V on /nonexistent/tty (A2h, satellite mode)");
  CHECK(make_radio("ic705:/nonexistent/tty", cfg).driver->describe() == "Icom IC-705 CI-V on /nonexistent/tty (A4h)");
  // One of two radios: no satellite mode.
  const auto spec = parse_radio_spec("ic9700:/nonexistent/tty");
  CHECK(make_radio(*spec.spec, cfg, {}, RadioRole::downlink).driver->describe() == "Icom IC-9700 CI-V on /nonexistent/tty (A2h)");
  auto ft = make_radio("ft847:/nonexistent/tty", cfg);
  CHECK(ft.driver->describe() == "Yaesu FT-847 CAT on /nonexistent/tty");
  auto f8 = make_radio("ft817:/nonexistent/tty", cfg);
  CHECK(f8.driver->describe() == "Yaesu FT-817 CAT on /nonexistent/tty");
  // yaesu: with the FT-847 named in STATION.DAT line 4 gets the FT-847 driver, not the FT-736's.
  cfg.rig_model = RigModel::yaesu_847;
  CHECK(make_radio("yaesu:/nonexistent/tty", cfg).driver->describe() == "Yaesu FT-847 CAT on /nonexistent/tty");
  cfg.rig_model = RigModel::yaesu_736;
  CHECK(make_radio("yaesu:/nonexistent/tty", cfg).driver->describe() == "Yaesu FT-736 CAT on /nonexistent/tty");
}

TEST_CASE("--radio gqrx / sdrpp: receivers, one link, no tone, their own ports") {
  auto g = parse_radio_spec("gqrx");
  REQUIRE(g.spec);
  CHECK(g.spec->host == "127.0.0.1");
  CHECK(g.spec->port == 7356);
  g = parse_radio_spec("gqrx:192.0.2.4");
  REQUIRE(g.spec);
  CHECK(g.spec->host == "192.0.2.4");
  CHECK(g.spec->port == 7356);
  auto s = parse_radio_spec("sdrpp:localhost:4533");
  REQUIRE(s.spec);
  CHECK(s.spec->name == "sdrpp");
  CHECK(s.spec->port == 4533);
  CHECK(parse_radio_spec("sdrpp").spec->port == 4532);
  CHECK(parse_radio_spec("gqrx:host:99999").error.find("expected gqrx[:HOST[:PORT]]") != std::string::npos);
  const RadioModel* m = find_radio_model("gqrx");
  REQUIRE(m);
  CHECK(m->caps.links == 1);
  CHECK_FALSE(m->caps.ctcss);
  CHECK(m->one_client);
  CHECK(spec_form(*m) == "gqrx[:HOST[:PORT]]");
  auto made = make_radio("gqrx:127.0.0.1:9", RadioConfig{});
  REQUIRE(made.driver);
  CHECK(made.driver->describe() == "GQRX at 127.0.0.1:9");
}

TEST_CASE("--radio flex: the SmartSDR API on port 4992, :duplex last") {
  auto f = parse_radio_spec("flex");
  REQUIRE(f.spec);
  CHECK(f.spec->host == "127.0.0.1");
  CHECK(f.spec->port == 4992);
  CHECK_FALSE(f.spec->full_duplex);
  f = parse_radio_spec("flex:192.0.2.7");
  REQUIRE(f.spec);
  CHECK(f.spec->host == "192.0.2.7");
  CHECK(f.spec->port == 4992);
  f = parse_radio_spec("flex:192.0.2.7:5000:duplex");
  REQUIRE(f.spec);
  CHECK(f.spec->port == 5000);
  CHECK(f.spec->full_duplex);
  f = parse_radio_spec("flex:duplex");
  REQUIRE(f.spec);
  CHECK(f.spec->host == "127.0.0.1");
  CHECK(f.spec->full_duplex);
  f = parse_radio_spec("flex:[2001:db8::7]:duplex");
  REQUIRE(f.spec);
  CHECK(f.spec->host == "[2001:db8::7]");   // as the rigctld spec keeps it
  CHECK(f.spec->port == 4992);
  CHECK(f.spec->full_duplex);
  CHECK(parse_radio_spec("flex:host:99999").error.find("expected flex[:HOST[:PORT]][:duplex]") != std::string::npos);
  const RadioModel* m = find_radio_model("flex");
  REQUIRE(m);
  CHECK(m->caps.links == 2);
  CHECK(m->caps.reads);
  CHECK(m->caps.step_hz == 1);
  CHECK(m->protocol == Protocol::flex);
  auto made = make_radio("flex:127.0.0.1:9", RadioConfig{});
  REQUIRE(made.driver);
  CHECK(made.driver->describe() == "FlexRadio at 127.0.0.1:9");
}

TEST_CASE("the rigs of 2026, third round (issue 61): rows, defaults, :xvtr, --radio list in 80 columns") {
  const RadioModel& ic905 = *find_radio_model("ic905");
  CHECK(ic905.civ_address == 0xAC);
  CHECK(ic905.baud == 115200);
  CHECK(ic905.satmode == SatCommand::icom_16_5a);
  CHECK(ic905.xvtr_from == 10'000'000'000);
  CHECK(find_radio_model("ic7300")->civ_address == 0x94);
  CHECK(find_radio_model("ic7300")->baud == 115200);
  CHECK(find_radio_model("ic7100")->civ_address == 0x88);
  CHECK(find_radio_model("ic7100")->baud == 19200);
  CHECK(find_radio_model("ic706mkiig")->civ_address == 0x58);
  for (const char* one : {"ic7300", "ic7100", "ic706mkiig", "ft857", "ft897", "ft991", "ftx1", "ft710", "ftdx10"})
    CHECK_MESSAGE(find_radio_model(one)->caps.links == 1, one);
  CHECK(find_radio_model("ft857")->protocol == Protocol::ft817);
  CHECK(find_radio_model("ft897")->baud == 4800);
  CHECK(find_radio_model("ft991")->protocol == Protocol::newcat);
  CHECK(find_radio_model_by_hamlib(1022) == find_radio_model("ft857"));
  CHECK(find_radio_model_by_hamlib(1035) == find_radio_model("ft991"));
  CHECK(find_radio_model_by_hamlib(3070) == find_radio_model("ic7100"));
  CHECK(find_radio_model_by_hamlib(3011) == find_radio_model("ic706mkiig"));

  const auto x = parse_radio_spec("ic905:/dev/ttyUSB0:115200:xvtr");
  REQUIRE(x.spec);
  CHECK(x.spec->transverter);
  CHECK(x.spec->baud == 115200);
  const auto y = parse_radio_spec("ic905:/dev/ttyUSB0:maindown:xvtr");
  REQUIRE(y.spec);
  CHECK(y.spec->transverter);
  CHECK(y.spec->main_link == Link::downlink);
  CHECK_FALSE(parse_radio_spec("ic905:/dev/ttyUSB0").spec->transverter);
  CHECK(parse_radio_spec("ic9700:/dev/x:xvtr").error ==
        "--radio \"ic9700:/dev/x:xvtr\": \"xvtr\": the Icom IC-9700 has no transverter band trakbox drives");
  CHECK(spec_form(ic905) == "ic905:DEVICE[:BAUD][:maindown|:mainup][:xvtr]");

  RadioConfig cfg;
  CHECK(make_radio("ic905:/nonexistent/tty", cfg).driver->describe() ==
        "Icom IC-905 CI-V on /nonexistent/tty (ACh, satellite mode)");
  CHECK(make_radio("ic7300:/nonexistent/tty", cfg).driver->describe() == "Icom IC-7300 CI-V on /nonexistent/tty (94h)");
  CHECK(make_radio("ft857:/nonexistent/tty", cfg).driver->describe() == "Yaesu FT-857 CAT on /nonexistent/tty");
  CHECK(make_radio("ft991:/nonexistent/tty", cfg).driver->describe() == "Yaesu FT-991A CAT on /nonexistent/tty (VFO-A)");
  const auto up = parse_radio_spec("ft991:/nonexistent/tty");
  CHECK(make_radio(*up.spec, cfg, {}, RadioRole::uplink).driver->describe() ==
        "Yaesu FT-991A CAT on /nonexistent/tty (VFO-B)");

  const std::string text = radio_list_text();
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    const std::string line = text.substr(start, end - start);
    CHECK_MESSAGE(line.size() <= 80, line);
    if (end == std::string::npos) break;
    start = end + 1;
  }
}
