// Properties over thousands of random configurations (seeded, deterministic):
//  * the commanded position never leaves the limits;
//  * the closed loop (controller + simulated rotator, 100 ms ticks) settles inside the dead band
//    without oscillating (no drive direction reversals).
#include <doctest/doctest.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <memory>
#include <random>

#include "fixture.h"  // Rig
#include "rotator/controller.h"
#include "rotator/simulated.h"

using tb::station::RotorStart;
using tb::station::ManualClock;
using tb::orbit::from_civil;
using namespace std::chrono_literals;
using namespace tb::rotator;

namespace {

struct Case {
  RotatorConfig config;
  RotorStart start = RotorStart::north;
};

Case random_case(std::mt19937& rng) {
  auto uni = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  auto pick = [&](int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); };
  Case k;
  RotatorConfig& c = k.config;
  k.start = pick(0, 1) ? RotorStart::north : RotorStart::south;
  c.az_travel_deg = pick(0, 3) == 0 ? 450.0 : 360.0;
  c.el_flip_allowed = pick(0, 3) == 0;
  c.az_span.min = pick(0, 300);
  c.az_span.max = pick(c.az_span.min + 150, kAdcMaxCount);
  c.el_span.min = pick(0, 200);
  c.el_span.max = pick(c.el_span.min + 60, kAdcMaxCount);
  c.az_dead_band = pick(1, 6);
  c.el_dead_band = pick(1, 3);
  c.az_skew = pick(-15, 15);
  c.el_skew = pick(-8, 8);
  if (pick(0, 1)) {
    c.limits_enabled = true;
    const double width = pick(0, 2) == 0 ? 360.0 : uni(40.0, 359.0);
    c.az_limit_min = uni(0.0, 359.0);
    c.az_limit_max = width >= 360.0 ? c.az_limit_min + 360.0 : wrap360(c.az_limit_min + width);
    if (c.az_limit_max > 360.0) {  // keep both in 0..360 as the menu would
      c.az_limit_min = 0.0;
      c.az_limit_max = 360.0;
    }
    c.el_limit_min = uni(0.0, 30.0);
    c.el_limit_max = uni(c.el_limit_min + 10.0, c.el_flip_allowed ? 180.0 : 90.0);
  }
  c.az_rate_deg_s = uni(2.0, 8.0);
  c.el_rate_deg_s = uni(1.0, 5.0);
  c.coast_s = uni(0.0, 0.4);
  return k;
}

}  // namespace

TEST_CASE("Property: the commanded position never leaves the limits") {
  std::mt19937 rng(20260301);
  int checked = 0;
  for (int i = 0; i < 3000; ++i) {
    Case k = random_case(rng);
    if (!validate(k.config).empty()) continue;
    AdcModel m(k.config, k.start);
    const Range az = m.az_travel_range(), el = m.el_range();
    const Range caz = m.counts_range(Axis::az), cel = m.counts_range(Axis::el);
    REQUIRE_FALSE(az.empty());
    REQUIRE_FALSE(el.empty());
    std::uniform_real_distribution<double> uaz(-30.0, 400.0), uel(-20.0, 200.0), ucur(-50.0, 500.0);
    for (int j = 0; j < 20; ++j) {
      AzEl want{uaz(rng), uel(rng)};
      RotatorPosition p = m.target_for(want, ucur(rng));
      CAPTURE(i);
      CAPTURE(want.az);
      CAPTURE(want.el);
      CHECK(az.contains(p.az_travel));
      CHECK(el.contains(p.el));
      const int ca = m.target_counts(Axis::az, p), ce = m.target_counts(Axis::el, p);
      CHECK(ca >= caz.lo - 1e-9);
      CHECK(ca <= caz.hi + 1e-9);
      CHECK(ce >= cel.lo - 1e-9);
      CHECK(ce <= cel.hi + 1e-9);
      // The raw counts the pots are driven to stay inside the calibrated span (the mechanical stops).
      CHECK(m.raw(Axis::az, ca) >= k.config.az_span.min);
      CHECK(m.raw(Axis::az, ca) <= k.config.az_span.max);
      CHECK(m.raw(Axis::el, ce) >= k.config.el_span.min);
      CHECK(m.raw(Axis::el, ce) <= k.config.el_span.max);
      // Rotator coordinates clamp the same way (what a pass plan hands over).
      RotatorPosition q = m.clamp({ucur(rng), uel(rng)});
      CHECK(az.contains(q.az_travel));
      CHECK(el.contains(q.el));
      // A target inside the limits is left alone.
      if (az.contains(want.az) && el.contains(want.el)) CHECK(m.clamp({want.az, want.el}) == RotatorPosition{want.az, want.el});
      ++checked;
    }
  }
  CHECK(checked > 40000);
}

namespace {
// Closed loops on `count` random configurations, ticking every `step`.
void closed_loops(unsigned seed, int count, std::chrono::milliseconds step, double mismatch = 1.0, int max_reversals = 0) {
  spdlog::set_level(spdlog::level::off);
  std::mt19937 rng(seed);
  const int ticks_per_s = static_cast<int>(1000 / step.count());
  int runs = 0, total_reversals = 0;
  for (int i = 0; runs < count; ++i) {
    Case k = random_case(rng);
    if (!validate(k.config).empty()) continue;
    ++runs;
    AdcModel m(k.config, k.start);
    const Range az = m.az_travel_range(), el = m.el_range();
    std::uniform_real_distribution<double> uaz(az.lo, az.hi), uel(el.lo, el.hi), ucomp(0.0, 360.0),
        uel_target(-5.0, 185.0);

    SimulatedRotatorParams p = SimulatedRotatorParams::matching(k.config);
    // A real rotator is not its model: rates and coast off by `mismatch`, either way.
    if (mismatch != 1.0) {
      auto f = [&] { return std::uniform_int_distribution<int>(0, 1)(rng) ? mismatch : 1.0 / mismatch; };
      p.az_rate_deg_s *= f();
      p.el_rate_deg_s *= f();
      p.coast_s *= f();
    }
    // The antenna starts somewhere inside the limits (in true degrees, the pot is unskewed).
    p.start = {m.az_travel_from_counts(m.raw(Axis::az, m.counts_from_az_travel(uaz(rng)))),
               m.el_from_counts(m.raw(Axis::el, m.counts_from_el(uel(rng))))};
    p.start.az_travel = std::clamp(p.start.az_travel, 0.0, k.config.az_travel_deg);
    p.start.el = std::clamp(p.start.el, 0.0, p.el_max_deg);
    rotator_test::Rig rig(k.config, k.start, p.start, p, from_civil(2026, 3, 1) + std::chrono::hours(i));
    ManualClock& clock = rig.clock;
    SimulatedRotator& sim = *rig.sim;
    Controller& ctl = *rig.ctl;
    RotatorPosition target = ctl.set_target(AzEl{ucomp(rng), uel_target(rng)});

    const Range caz = m.counts_range(Axis::az), cel = m.counts_range(Axis::el);
    Drive last_dir[2] = {Drive::stop, Drive::stop};
    int reversals[2] = {0, 0};
    bool settled = false;
    bool left_limits = false;
    int settled_ticks = 0;
    for (int t = 0; t < 400 * ticks_per_s && !settled; ++t) {  // up to 400 s
      clock.advance(step);
      ctl.tick(clock.now());
      const Status& s = ctl.status();
      REQUIRE(s.has_position);
      for (Axis a : {Axis::az, Axis::el}) {
        const int idx = a == Axis::az ? 0 : 1;
        const Drive d = a == Axis::az ? s.az.motion : s.el.motion;
        if (d != Drive::stop) {
          if (last_dir[idx] != Drive::stop && d != last_dir[idx]) ++reversals[idx];
          last_dir[idx] = d;
        }
        // The commanded count never leaves the limits.
        const auto& g = a == Axis::az ? s.az.goal_counts : s.el.goal_counts;
        const Range& cr = a == Axis::az ? caz : cel;
        REQUIRE(g);
        if (*g < cr.lo - 1e-9 || *g > cr.hi + 1e-9) left_limits = true;
      }
      settled_ticks = s.on_target ? settled_ticks + 1 : 0;
      settled = settled_ticks >= 2 * ticks_per_s;  // two seconds on target
    }
    CAPTURE(i);
    CAPTURE(target.az_travel);
    CAPTURE(target.el);
    CAPTURE(k.config.coast_s);
    CHECK(settled);
    CHECK_FALSE(left_limits);
    CHECK(reversals[0] <= max_reversals);
    CHECK(reversals[1] <= max_reversals);
    total_reversals += reversals[0] + reversals[1];
    // Inside the dead band, in counts, and it stays there with the motors off.
    const Status& s = ctl.status();
    CHECK(std::abs(*s.az.goal_counts - m.corrected(Axis::az, s.az.counts)) <= k.config.az_dead_band);
    CHECK(std::abs(*s.el.goal_counts - m.corrected(Axis::el, s.el.counts)) <= k.config.el_dead_band);
    for (int t = 0; t < 5 * ticks_per_s; ++t) {
      clock.advance(step);
      ctl.tick(clock.now());
      CHECK(ctl.status().az.motion == Drive::stop);
      CHECK(ctl.status().el.motion == Drive::stop);
    }
    CHECK(sim.motion().az == Drive::stop);
  }
  if (max_reversals == 0) CHECK(total_reversals == 0);
}
}  // namespace

TEST_CASE("Property: the closed loop settles inside the dead band without oscillating (100 ms ticks)") {
  closed_loops(19940209, 1000, 100ms);
}

TEST_CASE("Property: ... and so does a loop ticking once a second") { closed_loops(3101993, 300, 1000ms); }

TEST_CASE("Property: a rotator 20% off its model (rates, coast) still settles, with at most two reversals") { closed_loops(777, 300, 100ms, 1.2, 2); }
