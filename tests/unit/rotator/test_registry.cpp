// The rotator registry (rotator/registry.h): one table chooses the parser and the factory for
// every --rotator.
#include <doctest/doctest.h>

#include "rotator/registry.h"
#include "station/clock.h"

using namespace tb;

TEST_CASE("--rotator: one table for the drivers and a Satrak ACU") {
  auto sim = rotator::parse_rotator("simulated");
  REQUIRE(sim.error.empty());
  REQUIRE(sim.choice.rotator);
  CHECK(sim.choice.rotator->kind == rotator::RotatorSpec::Kind::simulated);
  CHECK_FALSE(sim.choice.satrak);

  auto ham = rotator::parse_rotator("hamlib:603:/dev/ttyUSB0:9600");
  REQUIRE(ham.choice.rotator);
  CHECK(ham.choice.rotator->model == 603);
  CHECK(ham.choice.rotator->baud == 9600);

  auto acu = rotator::parse_rotator("satrak:192.0.2.7");
  REQUIRE(acu.choice.satrak);
  CHECK(acu.choice.satrak->port == 4001);
  CHECK_FALSE(acu.choice.rotator);

  // Each kind's own parser says what is wrong; an unknown kind lists the table's forms.
  CHECK(rotator::parse_rotator("rotctld:").error.find("missing HOST") != std::string::npos);
  CHECK(rotator::parse_rotator("satrak:").error.find("expected satrak:HOST[:PORT]") != std::string::npos);
  CHECK(rotator::parse_rotator("").error ==
        "bad --rotator '': unknown rotator ''; expected simulated[:mount=AZ,EL], hamlib:MODEL:DEVICE[:BAUD], rotctld:HOST[:PORT], "
        "easycomm3:DEVICE[:BAUD], easycomm2:DEVICE[:BAUD], pstrotator:HOST[:PORT], satrak:HOST[:PORT] (trakbox --rotator list)");
  CHECK(rotator::parse_rotator("simulated:fast").error == "bad --rotator 'simulated:fast': expected simulated or simulated:mount=AZ,EL (a mounting error in degrees: "
        "the rotator reads that much more than where the antenna points), e.g. simulated:mount=2.0,-1.0");
  CHECK(rotator::parse_rotator("gs232:/dev/ttyS0").error ==
        "bad --rotator 'gs232:/dev/ttyS0': unknown rotator 'gs232'; expected simulated[:mount=AZ,EL], hamlib:MODEL:DEVICE[:BAUD], "
        "rotctld:HOST[:PORT], easycomm3:DEVICE[:BAUD], easycomm2:DEVICE[:BAUD], pstrotator:HOST[:PORT], satrak:HOST[:PORT] "
        "(trakbox --rotator list)");
  CHECK_FALSE(rotator::parse_rotator("gs232").choice.rotator);

  // Easycomm natively: the SatNOGS firmware's 19200 baud for III unless given, 9600 for II.
  auto ec3 = rotator::parse_rotator("easycomm3:/dev/ttyACM0");
  REQUIRE(ec3.choice.rotator);
  CHECK(ec3.choice.rotator->kind == rotator::RotatorSpec::Kind::easycomm3);
  CHECK(ec3.choice.rotator->device == "/dev/ttyACM0");
  CHECK(ec3.choice.rotator->baud == 0);
  CHECK(rotator::to_string(*ec3.choice.rotator) == "easycomm3:/dev/ttyACM0");
  auto ec2 = rotator::parse_rotator("easycomm2:/dev/ttyUSB0:4800");
  REQUIRE(ec2.choice.rotator);
  CHECK(ec2.choice.rotator->baud == 4800);
  CHECK(rotator::to_string(*ec2.choice.rotator) == "easycomm2:/dev/ttyUSB0:4800");
  CHECK(rotator::parse_rotator("easycomm3:").error ==
        "bad --rotator 'easycomm3:': missing DEVICE; expected easycomm3:DEVICE[:BAUD], e.g. easycomm3:/dev/ttyUSB0:19200");
  CHECK(rotator::parse_rotator("easycomm2:/dev/ttyUSB0:9601").error ==
        "bad --rotator 'easycomm2:/dev/ttyUSB0:9601': BAUD '9601' is not a serial speed (1200..115200); expected "
        "easycomm2:DEVICE[:BAUD], e.g. easycomm2:/dev/ttyUSB0:9600");
  CHECK(rotator::parse_rotator("easycomm3:/dev/x:19200:7").error.find("too many fields") != std::string::npos);
  auto box = rotator::parse_rotator("pstrotator:192.0.2.20");
  REQUIRE(box.choice.rotator);
  CHECK(box.choice.rotator->port == 12000);
  CHECK(rotator::to_string(*box.choice.rotator) == "pstrotator:192.0.2.20:12000");
  CHECK(rotator::parse_rotator("pstrotator:192.0.2.20:65535").error ==
        "bad --rotator 'pstrotator:192.0.2.20:65535': PORT 65535: its replies come to PORT+1, so at most 65534");

  const std::string list = rotator::rotator_list_text();
  for (const rotator::RotatorKind& k : rotator::rotator_kinds()) {
    CHECK(list.find(std::string(k.form)) != std::string::npos);
    CHECK(list.find(std::string(k.reads)) != std::string::npos);   // each row says what it reads back
  }
  std::size_t from = 0;
  for (std::size_t nl; (nl = list.find('\n', from)) != std::string::npos; from = nl + 1)
    CHECK_MESSAGE(nl - from <= 80, list.substr(from, nl - from));   // an 80-column terminal
}

TEST_CASE("--rotator: each row's factory makes its own driver") {
  station::ManualClock clock(orbit::from_civil(2026, 1, 1));
  const rotator::RotatorContext context{clock, {}};
  auto make = [&](const char* spec) {
    const auto parsed = rotator::parse_rotator(spec);
    REQUIRE(parsed.error.empty());
    REQUIRE(parsed.choice.kind);
    CHECK(parsed.choice.kind->name == std::string_view(spec).substr(0, std::string_view(spec).find(':')));
    return rotator::make_rotator(parsed.choice, context);
  };
  auto sim = make("simulated");
  REQUIRE(sim->as_adc());
  CHECK(sim->description() == "simulated");
  auto ham = make("hamlib:601:/nonexistent/ttyTB0:9600");
  REQUIRE(ham->as_degrees());
  CHECK(ham->description() == "hamlib 601 /nonexistent/ttyTB0 9600");
  auto net = make("rotctld:127.0.0.1:9");
  REQUIRE(net->as_degrees());
  CHECK(net->description().find("127.0.0.1:9") != std::string::npos);
  auto ec = make("easycomm3:/nonexistent/ttyTB0");
  REQUIRE(ec->as_degrees());
  CHECK(ec->description() == "Easycomm III on /nonexistent/ttyTB0 at 19200 baud");
  auto acu = make("satrak:127.0.0.1:9");
  CHECK(acu->description().find("127.0.0.1") != std::string::npos);
  // Nothing chosen (a TrackerConfig made in code): the simulated rotator.
  CHECK(rotator::make_rotator({}, context)->description() == "simulated");
}
