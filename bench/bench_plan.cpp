// What planning a pass costs (issue 57): an 88.8-degree pass of the ISS's speed (0.9 deg/s overhead,
// 200 s above the horizon, synthetic, along a great circle) planned on the factory rotator without
// flip (the keyhole's schedule) and with flip (over the top), sampled the old way (every 10 s) and
// as the station samples it now (rotator::pass_sample_times: every 10 s and every second within two
// minutes of the culmination). Planned once a pass, before AOS. Run a Release build:
// bench_plan --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <vector>

#include "rotator/adc_model.h"
#include "rotator/pass_plan.h"

using namespace tb;

namespace {

// ENU (sin s sin d, cos s, sin s cos d) at angle s along the pass: AOS at azimuth 0, culmination
// 90 - miss at azimuth 90, LOS at 180.
rotator::TrackPoint point_at(orbit::UtcTime aos, orbit::UtcTime t, double miss_deg) {
  constexpr double k = std::numbers::pi / 180.0;
  const double s = 0.9 * orbit::minutes_between(aos, t) * 60.0 * k;
  const double e = std::sin(s) * std::sin(miss_deg * k), n = std::cos(s), u = std::sin(s) * std::cos(miss_deg * k);
  return {t, rotator::wrap360(std::atan2(e, n) / k), std::asin(std::clamp(u, -1.0, 1.0)) / k};
}

// state.range(0): 0 every 10 s, 1 pass_sample_times; state.range(1): 0 no flip, 1 flip.
void BM_PlanPass(benchmark::State& state) {
  const orbit::UtcTime aos = orbit::from_civil(2026, 5, 23, 13, 45);
  const orbit::UtcTime los = aos + std::chrono::seconds(200);
  const orbit::UtcTime tca = aos + std::chrono::seconds(100);
  std::vector<orbit::UtcTime> times;
  if (state.range(0) == 0)
    for (int s = 0; s <= 200; s += 10) times.push_back(aos + std::chrono::seconds(s));
  else
    times = rotator::pass_sample_times(aos, tca, los);
  std::vector<rotator::TrackPoint> track;
  for (const orbit::UtcTime t : times) track.push_back(point_at(aos, t, 1.2));
  rotator::RotatorConfig c;
  c.el_flip_allowed = state.range(1) != 0;
  const auto g = rotator::PassGeometry::from(rotator::AdcModel(c, station::RotorStart::south));
  rotator::PassPlan plan;
  for (auto _ : state) {
    plan = rotator::plan_pass(track, g);
    benchmark::DoNotOptimize(plan);
  }
  state.counters["samples"] = static_cast<double>(track.size());
  state.counters["worst_deg"] = plan.max_error_deg;
  state.counters["keyhole"] = plan.lead.empty() ? 0.0 : 1.0;
  state.counters["over_top"] = plan.over_top ? 1.0 : 0.0;
}

}  // namespace

BENCHMARK(BM_PlanPass)->ArgsProduct({{0, 1}, {0, 1}})->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
