// One day of passes for a whole catalogue from one station: the pass search against the naive
// one-minute stepping, and against SGP4 alone at the very times the search propagates (what a step
// costs beyond its propagation). Run a Release build: bench_passes --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "bench_support.h"
#include "support/gpredict_sets.h"

#include "orbit/elements.h"
#include "orbit/passes.h"

using namespace tb::orbit;
using tb::bench::thread_cpu_ns;

namespace {

const Observer kStation{49.8706, 8.6494, 140.0};  // Darmstadt
const UtcTime kStart = from_civil(2018, 1, 21);
const UtcTime kStop = from_civil(2018, 1, 22);

// The 979 sets of Debian's gpredict (epochs within a few days of the window).
const std::vector<Elements>& real_sets() {
  static const std::vector<Elements> sets = tb::testing::gpredict_catalogue_sets();
  return sets;
}

// A 10,000-set catalogue: the real sets, then copies of them turned round their orbit and about
// the Earth's axis (mean anomaly + 97 deg k, RAAN + 36 deg k for the k-th copy), so that the orbit
// types keep the real mix while the passes fall elsewhere.
std::vector<Sgp4> catalogue(std::size_t n) {
  const std::vector<Elements>& base = real_sets();
  std::vector<Sgp4> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    Elements e = base[i % base.size()];
    const double k = static_cast<double>(i / base.size());
    e.mean_anomaly_deg = std::fmod(e.mean_anomaly_deg + 97.0 * k, 360.0);
    e.raan_deg = std::fmod(e.raan_deg + 36.0 * k, 360.0);
    out.emplace_back(e);
  }
  return out;
}

// The (set, tsince) pairs the search propagates, in its order: tsince[first[i] .. first[i + 1]) for set i.
struct Trace {
  std::vector<double> tsince;
  std::vector<std::size_t> first;
};
Trace record(const std::vector<Sgp4>& sats) {
  Trace tr;
  tr.first.push_back(0);
  for (const Sgp4& s : sats) {
    PassSearchStats stats;
    stats.tsince_minutes = &tr.tsince;
    find_passes(s, kStation, kStart, kStop, {}, {}, stats);
    tr.first.push_back(tr.tsince.size());
  }
  return tr;
}

// One day of passes for every set; returns the propagations.
long search_once(const std::vector<Sgp4>& sats, long& passes) {
  long props = 0;
  passes = 0;
  for (const Sgp4& s : sats) {
    PassSearchStats stats;
    const std::vector<Pass> p = find_passes(s, kStation, kStart, kStop, {}, {}, stats);
    passes += static_cast<long>(p.size());
    props += stats.propagations;
    benchmark::DoNotOptimize(p.data());
  }
  return props;
}

// SGP4 alone at the recorded times; returns the propagations.
long replay_once(const std::vector<Sgp4>& sats, const Trace& tr) {
  for (std::size_t i = 0; i < sats.size(); ++i) {
    for (std::size_t k = tr.first[i]; k < tr.first[i + 1]; ++k) {
      Propagation p = sats[i].propagate_minutes(tr.tsince[k]);
      benchmark::DoNotOptimize(p);
    }
  }
  return static_cast<long>(tr.tsince.size());
}

// The counters every benchmark here reports: the catalogue's size, the passes found (negative:
// not counted) and the propagations per set.
void catalogue_counters(benchmark::State& state, const std::vector<Sgp4>& sats, long passes, double props_per_set) {
  state.counters["sets"] = static_cast<double>(sats.size());
  if (passes >= 0) state.counters["passes"] = static_cast<double>(passes);
  state.counters["props/set"] = props_per_set;
}

void search(benchmark::State& state, const std::vector<Sgp4>& sats) {
  long passes = 0, props = 0;
  for (auto _ : state) props = search_once(sats, passes);
  catalogue_counters(state, sats, passes, static_cast<double>(props) / static_cast<double>(sats.size()));
  state.counters["s/step"] = benchmark::Counter(static_cast<double>(props),
                                                benchmark::Counter::kIsIterationInvariantRate |
                                                    benchmark::Counter::kInvert);
}

// SGP4 alone, at exactly the (set, tsince) pairs the search propagates.
void sgp4_only(benchmark::State& state, const std::vector<Sgp4>& sats) {
  static const Trace tr = record(sats);
  long props = 0;
  for (auto _ : state) props = replay_once(sats, tr);
  catalogue_counters(state, sats, -1, static_cast<double>(props) / static_cast<double>(sats.size()));
  state.counters["s/sgp4"] = benchmark::Counter(static_cast<double>(props),
                                                benchmark::Counter::kIsIterationInvariantRate |
                                                    benchmark::Counter::kInvert);
}

// Both in every iteration, alternating (the machine's speed drifts between benchmarks): CPU ns per
// search step, per SGP4 call at the same times, and their ratio.
void step_ratio(benchmark::State& state, const std::vector<Sgp4>& sats) {
  static const Trace tr = record(sats);
  double search_ns = 0.0, sgp4_ns = 0.0;
  long props = 0, passes = 0, replayed = 0;
  for (auto _ : state) {
    const double t0 = thread_cpu_ns();
    props += search_once(sats, passes);
    const double t1 = thread_cpu_ns();
    replayed += replay_once(sats, tr);
    sgp4_ns += thread_cpu_ns() - t1;
    search_ns += t1 - t0;
  }
  catalogue_counters(state, sats, passes,
                     static_cast<double>(props) / static_cast<double>(state.iterations()) / static_cast<double>(sats.size()));
  const double step = search_ns / static_cast<double>(props), sgp4 = sgp4_ns / static_cast<double>(replayed);
  state.counters["ns/step"] = step;
  state.counters["ns/sgp4"] = sgp4;
  state.counters["step/sgp4"] = step / sgp4;
}

// The baseline: propagate every minute, rotate to Earth-fixed, elevation; count the intervals up.
void step_every_minute(benchmark::State& state, const std::vector<Sgp4>& sats) {
  long passes = 0;
  for (auto _ : state) {
    passes = 0;
    for (const Sgp4& s : sats) {
      bool up = false;
      for (int m = 0; m < 1440; ++m) {
        const UtcTime t = kStart + std::chrono::minutes(m);
        const Propagation p = s.propagate(t);
        if (!p.ok()) break;
        const bool now = look_angles(teme_to_ecef(p.state, t), kStation).el_deg >= kAosThresholdDeg;
        if (now && !up) ++passes;
        up = now;
      }
    }
  }
  catalogue_counters(state, sats, passes, 1440.0);
}

void BM_Passes_RealCatalogue(benchmark::State& state) {
  static const std::vector<Sgp4> sats = catalogue(real_sets().size());
  search(state, sats);
}
void BM_Passes_Sgp4Only_RealCatalogue(benchmark::State& state) {
  static const std::vector<Sgp4> sats = catalogue(real_sets().size());
  sgp4_only(state, sats);
}
void BM_PassStep_Ratio_RealCatalogue(benchmark::State& state) {
  static const std::vector<Sgp4> sats = catalogue(real_sets().size());
  step_ratio(state, sats);
}
void BM_Passes_Catalogue10k(benchmark::State& state) {
  static const std::vector<Sgp4> sats = catalogue(10000);
  search(state, sats);
}
void BM_MinuteSteps_RealCatalogue(benchmark::State& state) {
  static const std::vector<Sgp4> sats = catalogue(real_sets().size());
  step_every_minute(state, sats);
}
void BM_MinuteSteps_Catalogue10k(benchmark::State& state) {
  static const std::vector<Sgp4> sats = catalogue(10000);
  step_every_minute(state, sats);
}

}  // namespace

BENCHMARK(BM_Passes_RealCatalogue)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Passes_Sgp4Only_RealCatalogue)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PassStep_Ratio_RealCatalogue)->Unit(benchmark::kMillisecond)->MinTime(3.0);
BENCHMARK(BM_Passes_Catalogue10k)->Unit(benchmark::kMillisecond)->MinTime(3.0);
BENCHMARK(BM_MinuteSteps_RealCatalogue)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MinuteSteps_Catalogue10k)->Unit(benchmark::kMillisecond)->Iterations(2);

BENCHMARK_MAIN();
