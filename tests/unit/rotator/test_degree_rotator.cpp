// Degree rotators (Hamlib) through the controller: the same model, dead band and skew as an ADC
// rotator, the rotator's own azimuth convention, resends, faults. A fake rotator records commands.
#include <doctest/doctest.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <memory>
#include <vector>

#include "rotator/controller.h"
#include "fixture.h"

using namespace tb::rotator;
using namespace std::chrono_literals;
using tb::orbit::from_civil;
using tb::station::RotorStart;
using rotator_test::kAzCount;
using rotator_test::kElCount;

namespace {

class FakeDegrees final : public DegreeRotator {
 public:
  AzEl pos{0.0, 0.0};
  std::vector<AzEl> sent;
  Range range{-180.0, 450.0};
  Health h{LinkState::ok, {}, 1};
  AxisMotion m;
  int stops = 0;

  std::string description() const override { return "fake"; }
  Health health() override { return h; }
  AxisMotion motion() override { return m; }
  void stop() override { ++stops; }
  std::optional<AzEl> read() override { return pos; }
  void set_position(AzEl p) override { sent.push_back(p); }
  Range az_range() override { return range; }
};

struct DegreeRig {
  FakeDegrees* rot = nullptr;
  std::unique_ptr<Controller> ctl;
  tb::orbit::UtcTime now = from_civil(2026, 4, 1, 12);
  explicit DegreeRig(RotatorConfig c = {}, RotorStart start = RotorStart::north) {
    spdlog::set_level(spdlog::level::off);
    auto f = std::make_unique<FakeDegrees>();
    rot = f.get();
    ctl = std::make_unique<Controller>(c, start, std::move(f));
  }
  void tick(std::chrono::milliseconds d = 100ms) {
    now += d;
    ctl->tick(now);
  }
};


}  // namespace

TEST_CASE("A degree rotator is sent its target once, and nothing inside the dead band") {
  DegreeRig rig;
  rig.tick();
  CHECK(rig.ctl->status().has_position);
  CHECK(rig.ctl->raw_counts() == Counts{0, 0});
  rig.ctl->set_target(AzEl{90.0, 45.0});
  rig.tick();
  REQUIRE(rig.rot->sent.size() == 1);
  CHECK(rig.rot->sent[0].az == doctest::Approx(90.0).epsilon(1e-3));  // whole counts: 255.75 -> 256
  CHECK(std::abs(rig.rot->sent[0].az - 90.0) <= kAzCount / 2);
  CHECK(std::abs(rig.rot->sent[0].el - 45.0) <= kElCount / 2);
  rig.rot->m = {Drive::increase, Drive::increase};
  rig.tick();
  CHECK(rig.rot->sent.size() == 1);  // unchanged while it moves
  rig.rot->pos = {90.0, 45.0};
  rig.rot->m = {};
  rig.tick();
  CHECK(rig.ctl->status().on_target);
  CHECK(format_monitor_line(rig.ctl->status()) == "AZ= 256 / 90.0deg EL= 256 / 45.0deg.");
  // A new target within the dead band (3 counts = 1.06 deg az, 1 count = 0.18 deg el): nothing sent.
  rig.ctl->set_target(AzEl{90.9, 45.1});
  rig.tick();
  CHECK(rig.rot->sent.size() == 1);
  CHECK(rig.ctl->status().on_target);
  // Beyond it on azimuth only: the elevation holds where it is.
  rig.ctl->set_target(AzEl{92.0, 45.1});
  rig.tick();
  REQUIRE(rig.rot->sent.size() == 2);
  CHECK(std::abs(rig.rot->sent[1].az - 92.0) <= kAzCount / 2);
  CHECK(rig.rot->sent[1].el == doctest::Approx(45.0));
}

TEST_CASE("While it moves, a target creeping inside the dead band of the last command sends nothing new") {
  DegreeRig rig;
  rig.tick();
  rig.ctl->set_target(AzEl{90.0, 45.0});
  rig.tick();
  REQUIRE(rig.rot->sent.size() == 1);
  rig.rot->m = {Drive::increase, Drive::increase};   // on its way
  // A satellite's target moving 0.3 deg a tick: within the 3-count (1.06 deg) dead band of the
  // command sent (256 counts), nothing is sent; beyond it, the new position.
  for (const double az : {90.3, 90.6, 90.9}) {
    rig.ctl->set_target(AzEl{az, 45.0});
    rig.tick();
  }
  CHECK(rig.rot->sent.size() == 1);
  // 91.6 deg is 260 counts, 4 from the 256 sent: beyond the band.
  rig.ctl->set_target(AzEl{91.6, 45.0});
  rig.tick();
  REQUIRE(rig.rot->sent.size() == 2);
  CHECK(std::abs(rig.rot->sent[1].az - 91.6) <= kAzCount / 2);
}

TEST_CASE("Skew means the same counts on a degree rotator") {
  RotatorConfig c;
  c.az_skew = 10;  // 3.52 deg
  c.el_skew = -2;  // -0.35 deg
  DegreeRig rig(c);
  rig.rot->pos = {90.0, 45.0};
  rig.tick();
  CHECK(rig.ctl->status().az.deg == doctest::Approx(90.0 + 10 * kAzCount));
  CHECK(rig.ctl->status().el.deg == doctest::Approx(45.0 - 2 * kElCount));
  CHECK(rig.ctl->status().az.counts == 256);  // raw, as the monitor shows
  rig.ctl->set_target(AzEl{100.0, 30.0});
  rig.tick();
  REQUIRE(rig.rot->sent.size() == 1);
  CHECK(std::abs(rig.rot->sent[0].az - (100.0 - 10 * kAzCount)) <= kAzCount / 2);
  CHECK(std::abs(rig.rot->sent[0].el - (30.0 + 2 * kElCount)) <= kElCount / 2);
}

TEST_CASE("Rotor start South on a rotator counting -180..180") {
  DegreeRig rig({}, RotorStart::south);
  rig.rot->range = {-180.0, 180.0};
  rig.rot->pos = {-90.0, 0.0};  // west
  rig.tick();
  CHECK(rig.ctl->status().az.deg == doctest::Approx(270.0));
  CHECK(rig.ctl->status().az.travel == doctest::Approx(90.0));
  rig.ctl->set_target(AzEl{90.0, 10.0});  // east: travel 270, 180 + 270 = 450 -> 90
  rig.tick();
  REQUIRE(rig.rot->sent.size() == 1);
  CHECK(std::abs(rig.rot->sent[0].az - 90.0) <= kAzCount / 2);
  rig.ctl->set_target(AzEl{200.0, 10.0});  // just past the south stop: travel 20 -> az -160
  rig.tick();
  REQUIRE(rig.rot->sent.size() == 2);
  CHECK(std::abs(rig.rot->sent[1].az - (-160.0)) <= kAzCount / 2);
}

TEST_CASE("An unchanged target is sent again while the rotator idles off target") {
  DegreeRig rig;
  rig.ctl->set_target(AzEl{50.0, 10.0});
  rig.tick();
  CHECK(rig.rot->sent.size() == 1);
  rig.tick(1000ms);
  CHECK(rig.rot->sent.size() == 1);
  rig.tick(1100ms);  // 2.1 s since it was sent, the rotator never moved
  CHECK(rig.rot->sent.size() == 2);
  rig.rot->m = {Drive::increase, Drive::stop};
  rig.tick(3000ms);  // moving: no resend
  CHECK(rig.rot->sent.size() == 2);
}

TEST_CASE("A degree rotator fault: nothing sent, position invalid, target resent on recovery") {
  DegreeRig rig;
  rig.ctl->set_target(AzEl{50.0, 10.0});
  rig.tick();
  CHECK(rig.rot->sent.size() == 1);
  rig.rot->h = {LinkState::fault, "lost fake: IO error", 1};
  rig.tick();
  CHECK(rig.ctl->status().link.state == LinkState::fault);
  CHECK_FALSE(rig.ctl->status().has_position);
  CHECK(rig.ctl->status().message == "rotator fault: lost fake: IO error (motors stopped)");
  rig.tick(5000ms);
  CHECK(rig.rot->sent.size() == 1);
  rig.rot->h = {LinkState::ok, {}, 2};
  rig.tick();
  CHECK(rig.rot->sent.size() == 2);  // at once, not after the resend interval
  CHECK(rig.ctl->status().message == "rotator link restored (fake)");
}

TEST_CASE("Keyboard control and stop on a degree rotator") {
  DegreeRig rig;
  rig.rot->pos = {100.0, 20.0};
  rig.tick();
  rig.ctl->manual_key('6');
  rig.tick();
  REQUIRE(rig.rot->sent.size() == 1);
  CHECK(rig.rot->sent[0].az == doctest::Approx(360.0).epsilon(1e-3));  // to the CW end
  CHECK(rig.rot->sent[0].el == doctest::Approx(20.0));                   // elevation holds
  int stops = rig.rot->stops;
  rig.ctl->manual_key('5');
  CHECK(rig.rot->stops == stops + 1);
  CHECK(rig.ctl->status().mode == ControlMode::idle);
  rig.tick();
  CHECK(rig.rot->sent.size() == 1);
  // E off: stop at once, nothing sent.
  rig.ctl->set_target(AzEl{200.0, 20.0});
  rig.ctl->set_control_enabled(false);
  CHECK(rig.rot->stops == stops + 2);
  rig.tick();
  CHECK(rig.rot->sent.size() == 1);
}
