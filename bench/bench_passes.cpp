// One day of passes for a whole catalogue from one station: the pass search against the naive
// one-minute stepping. Run a Release build: bench_passes --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include "test_paths.h"  // TRAKBOX_SOURCE_DIR, ...

#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "orbit/elements.h"
#include "orbit/passes.h"

using namespace tb::orbit;

namespace {

const Observer kStation{49.8706, 8.6494, 140.0};  // Darmstadt
const UtcTime kStart = from_civil(2018, 1, 21);
const UtcTime kStop = from_civil(2018, 1, 22);

// The 979 sets of Debian's gpredict (epochs within a few days of the window).
const std::vector<Elements>& real_sets() {
  static const std::vector<Elements> sets = [] {
    std::ifstream f(TRAKBOX_GPREDICT_SATDATA);
    std::stringstream ss;
    ss << f.rdbuf();
    return parse_gpredict_satdata(ss.str()).sets;
  }();
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

void search(benchmark::State& state, const std::vector<Sgp4>& sats) {
  long passes = 0, props = 0;
  for (auto _ : state) {
    passes = 0;
    props = 0;
    for (const Sgp4& s : sats) {
      PassSearchStats stats;
      const std::vector<Pass> p = find_passes(s, kStation, kStart, kStop, {}, {}, stats);
      passes += static_cast<long>(p.size());
      props += stats.propagations;
      benchmark::DoNotOptimize(p.data());
    }
  }
  state.counters["sets"] = static_cast<double>(sats.size());
  state.counters["passes"] = static_cast<double>(passes);
  state.counters["props/set"] = static_cast<double>(props) / static_cast<double>(sats.size());
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
  state.counters["sets"] = static_cast<double>(sats.size());
  state.counters["passes"] = static_cast<double>(passes);
  state.counters["props/set"] = 1440.0;
}

void BM_Passes_RealCatalogue(benchmark::State& state) {
  static const std::vector<Sgp4> sats = catalogue(real_sets().size());
  search(state, sats);
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
BENCHMARK(BM_Passes_Catalogue10k)->Unit(benchmark::kMillisecond)->MinTime(3.0);
BENCHMARK(BM_MinuteSteps_RealCatalogue)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MinuteSteps_Catalogue10k)->Unit(benchmark::kMillisecond)->Iterations(2);

BENCHMARK_MAIN();
