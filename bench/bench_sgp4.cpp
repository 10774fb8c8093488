// SGP4/SDP4 speed: one near-earth and one deep-space propagation, and a catalogue run over the 979
// real element sets of Debian gpredict's satellites.dat at 1440 one-minute steps, looped as
// python-sgp4's SatrecArray.sgp4(jd, fr) loops (every satellite at every time, results written to
// position/velocity/error arrays). scripts/bench_reference_sgp4.py runs the same workload through
// python-sgp4 for a same-machine baseline.
#include <benchmark/benchmark.h>
#include "test_paths.h"  // TRAKBOX_SOURCE_DIR, ...

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "orbit/elements.h"
#include "orbit/sgp4.h"
#include "orbit/sgp4_batch.h"
#include "orbit/state_lines.h"
#include "support/gpredict_sets.h"

using namespace tb::orbit;

namespace {

void propagate_over_a_day(benchmark::State& state, const Elements& elements) {
  const Sgp4 sat(elements);
  double t = 0.0;
  for (auto _ : state) {
    Propagation p = sat.propagate_minutes(t);
    benchmark::DoNotOptimize(p);
    t = t < 1439.0 ? t + 1.0 : 0.0;
  }
}

void BM_Sgp4NearEarth(benchmark::State& state) { propagate_over_a_day(state, tb::testing::iss_2018()); }
BENCHMARK(BM_Sgp4NearEarth);

void BM_Sgp4DeepSpaceResonant(benchmark::State& state) { propagate_over_a_day(state, tb::testing::molniya_2018()); }
BENCHMARK(BM_Sgp4DeepSpaceResonant);

// A resonant (Molniya, half-day) set propagated over one day starting `age` days after its epoch:
// SDP4 integrates the resonance from epoch, so without checkpoints the cost grows with the age.
void BM_Sgp4ResonantAtAge(benchmark::State& state) {
  const Sgp4 sat(tb::testing::molniya_2018());
  const double start = 1440.0 * static_cast<double>(state.range(0));
  double t = start;
  for (auto _ : state) {
    Propagation p = sat.propagate_minutes(t);
    benchmark::DoNotOptimize(p);
    t = t < start + 1439.0 ? t + 1.0 : start;
  }
  state.SetLabel("days after epoch: " + std::to_string(state.range(0)));
}
BENCHMARK(BM_Sgp4ResonantAtAge)->Arg(0)->Arg(7)->Arg(30)->Arg(365);

std::vector<Sgp4> gpredict_catalogue() {
  const std::vector<Elements> sets = tb::testing::gpredict_catalogue_sets();
  return {sets.begin(), sets.end()};
}

// The catalogue workload as python-sgp4's SatrecArray.sgp4(jd, fr) runs it: every set at
// 2018-01-21 00:00 UTC + k minutes, k = 0..1439 (the file's epochs are 2017 Dec 23 to 2018 Jan 22),
// times given as a split Julian date as SatrecArray takes them, and the arrays it fills: position,
// velocity (NaN on failure), error code, one entry per set and time.
struct CatalogueDay {
  static constexpr int kTimes = 1440;
  static constexpr double kJd = 2458139.5;
  std::vector<Sgp4> sats = gpredict_catalogue();
  std::vector<double> fr = [] {
    std::vector<double> f(kTimes);
    for (int k = 0; k < kTimes; ++k) f[k] = k / 1440.0;
    return f;
  }();
  std::size_t n = sats.size() * kTimes;
  std::vector<double> r = std::vector<double>(3 * n);
  std::vector<double> v = std::vector<double>(3 * n);
  std::vector<std::uint8_t> errors = std::vector<std::uint8_t>(n);

  // Minutes from a set's epoch to time j.
  double tsince(const JulianDate& epoch, int j) const {
    return (kJd - epoch.whole) * 1440.0 + (fr[j] - epoch.fraction) * 1440.0;
  }
  // One result into the arrays, at k = set * kTimes + time.
  void store(const Propagation& p, std::size_t k) {
    constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
    errors[k] = static_cast<std::uint8_t>(p.error);
    for (int c = 0; c < 3; ++c) {
      r[3 * k + c] = p.ok() ? p.state.r_km[c] : kNan;
      v[3 * k + c] = p.ok() ? p.state.v_km_s[c] : kNan;
    }
  }
  // Seconds per propagation (printed with an SI prefix: "650n" is 650 ns).
  benchmark::Counter per_propagation() const {
    return benchmark::Counter(static_cast<double>(n),
                              benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  }
};

// The catalogue workload, one propagation at a time.
void BM_Sgp4Gpredict979x1440(benchmark::State& state) {
  CatalogueDay w;
  for (auto _ : state) {
    std::size_t k = 0;
    for (const Sgp4& sat : w.sats) {
      const JulianDate epoch = sat.epoch_jd();
      for (int j = 0; j < CatalogueDay::kTimes; ++j, ++k) w.store(sat.propagate_minutes(w.tsince(epoch, j)), k);
    }
    benchmark::ClobberMemory();
  }
  std::size_t failed = 0;
  for (std::uint8_t e : w.errors) failed += e != 0;
  state.counters["sets"] = static_cast<double>(w.sats.size());
  state.counters["failed"] = static_cast<double>(failed);
  state.counters["per_propagation"] = w.per_propagation();
}
BENCHMARK(BM_Sgp4Gpredict979x1440)->Unit(benchmark::kMillisecond)->MinTime(5.0);

// The same workload through the batch interface (orbit/sgp4_batch.h): every set over the same 1440
// minutes, results in the same arrays. items_per_second: propagations per second. Arg: which kernel
// (0: the one dispatch chooses here, then each available one, best first; the label names it).
void BM_Sgp4BatchGpredict979x1440(benchmark::State& state) {
  const auto kernels = batch_kernels_available();
  const auto which = static_cast<std::size_t>(state.range(0));
  if (which > kernels.size()) {
    state.SkipWithError("no such kernel on this processor");
    return;
  }
  const char* isa = which == 0 ? batch_kernel_isa() : kernels[which - 1];
  CatalogueDay w;
  std::vector<double> tsince(CatalogueDay::kTimes);
  std::vector<Propagation> out(CatalogueDay::kTimes);
  for (auto _ : state) {
    std::size_t k = 0;
    for (const Sgp4& sat : w.sats) {
      const JulianDate epoch = sat.epoch_jd();
      for (int j = 0; j < CatalogueDay::kTimes; ++j) tsince[j] = w.tsince(epoch, j);
      propagate_batch_with(isa, sat, tsince, out);
      for (int j = 0; j < CatalogueDay::kTimes; ++j, ++k) w.store(out[j], k);
    }
    benchmark::ClobberMemory();
  }
  state.SetLabel(isa);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(w.n));
  state.counters["per_propagation"] = w.per_propagation();
}
BENCHMARK(BM_Sgp4BatchGpredict979x1440)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->MinTime(3.0);

// The propagate command's output line, one day of ISS at one-minute steps: the baseline writes it
// with snprintf as before (BM_PropagateLinePrintf), the command with append_fixed: exact integer
// arithmetic in the command's ranges, to_chars beyond (BM_PropagateLineToChars, the name it had,
// orbit/state_lines.h). The two give the same characters (unit_util); the ratio is the saving per
// line, apart from SGP4 itself (BM_Sgp4NearEarth).
std::vector<std::pair<double, StateVector>> iss_day_states() {
  const Sgp4 sat(tb::testing::iss_2018());
  std::vector<std::pair<double, StateVector>> states;
  for (int m = 0; m < 1440; ++m) states.emplace_back(m, sat.propagate_minutes(m).state);
  return states;
}

void BM_PropagateLinePrintf(benchmark::State& state) {
  const auto states = iss_day_states();
  std::string out;
  char line[256];
  for (auto _ : state) {
    out.clear();
    for (const auto& [t, s] : states) {
      const int n = std::snprintf(line, sizeof line, " %16.8f %16.8f %16.8f %16.8f %12.9f %12.9f %12.9f\n", t,
                                  s.r_km[0], s.r_km[1], s.r_km[2], s.v_km_s[0], s.v_km_s[1], s.v_km_s[2]);
      out.append(line, static_cast<std::size_t>(n));
    }
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(states.size()));
}
BENCHMARK(BM_PropagateLinePrintf);

void BM_PropagateLineToChars(benchmark::State& state) {
  const auto states = iss_day_states();
  std::string out;
  for (auto _ : state) {
    out.clear();
    for (const auto& [t, s] : states) append_state_line(out, t, s);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(states.size()));
}
BENCHMARK(BM_PropagateLineToChars);

}  // namespace

BENCHMARK_MAIN();
