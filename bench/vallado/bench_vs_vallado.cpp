// trakbox's SGP4 against Vallado's own C++ (the reference implementation of "Revisiting Spacetrack
// Report #3"), in one process, the same loop, the same compiler and flags. Vallado's source is not
// part of trakbox: scripts/fetch-vallado.sh fetches it, and -DTRAKBOX_VALLADO_DIR=DIR builds this
// program (docs/sgp4.md, "Speed"). Each workload is run for both, interleaved
// (--benchmark_enable_random_interleaving), and scripts/bench_ratios.py prints the ratios.
//
//   per call   one set, one propagation per call, one day at one-minute steps (ISS; the catalogue)
//   batch      trakbox's batch interface over the catalogue against Vallado's per call
#include <benchmark/benchmark.h>
#include "test_paths.h"  // TRAKBOX_GPREDICT_SATDATA

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "SGP4.h"  // Vallado's
#include "orbit/constants.h"
#include "orbit/elements.h"
#include "orbit/sgp4.h"
#include "orbit/sgp4_batch.h"
#include "support/gpredict_sets.h"
#include "../bench_support.h"

using namespace tb::orbit;
using tb::bench::thread_cpu_ns;

namespace {

// Vallado's satrec for a set, initialised as his twoline2rv does (WGS-72, improved mode) from the
// same numbers trakbox reads.
elsetrec vallado_init(const Sgp4& sat) {
  const Elements& e = sat.elements();
  elsetrec rec{};
  const double deg = tb::orbit::kDegToRad;
  const JulianDate epoch = sat.epoch_jd();
  rec.jdsatepoch = epoch.whole;
  rec.jdsatepochF = epoch.fraction;
  SGP4Funcs::sgp4init(::wgs72, 'i', "00000", (epoch.whole + epoch.fraction) - 2433281.5, e.bstar, 0.0, 0.0,
                      e.eccentricity, e.arg_perigee_deg * deg, e.inclination_deg * deg, e.mean_anomaly_deg * deg,
                      e.mean_motion_rev_per_day / (1440.0 / (2.0 * tb::orbit::kPi)), e.raan_deg * deg, rec);
  return rec;
}

std::vector<Sgp4> catalogue() {
  const std::vector<Elements> sets = tb::testing::gpredict_catalogue_sets();
  return {sets.begin(), sets.end()};
}

// The catalogue, or (Arg 1) its near-earth sets or (Arg 2) its deep-space sets only.
const std::vector<Sgp4>& sats(std::int64_t which = 0) {
  static const std::vector<Sgp4> all = catalogue();
  static const std::vector<Sgp4> near = [] {
    std::vector<Sgp4> v;
    for (const Sgp4& s : all) if (!s.deep_space()) v.push_back(s);
    return v;
  }();
  static const std::vector<Sgp4> deep = [] {
    std::vector<Sgp4> v;
    for (const Sgp4& s : all) if (s.deep_space()) v.push_back(s);
    return v;
  }();
  return which == 1 ? near : which == 2 ? deep : all;
}
const char* subset_label(std::int64_t which) {
  return which == 1 ? "near-earth sets" : which == 2 ? "deep-space sets" : "all sets";
}

// Minutes from each set's epoch to 2018-01-21 00:00 UTC + j minutes, j = 0..1439.
constexpr int kTimes = 1440;
std::vector<double> times_for(const JulianDate& epoch) {
  std::vector<double> t(kTimes);
  for (int j = 0; j < kTimes; ++j) t[j] = (2458139.5 - epoch.whole) * 1440.0 + (j / 1440.0 - epoch.fraction) * 1440.0;
  return t;
}

struct Sink {  // where results go, as python-sgp4's SatrecArray writes them
  std::vector<double> r, v;
  std::vector<std::uint8_t> error;
  explicit Sink(std::size_t n) : r(3 * n), v(3 * n), error(n) {}
  void put(std::size_t k, int code, const double* rk, const double* vk) {
    error[k] = static_cast<std::uint8_t>(code);
    for (int c = 0; c < 3; ++c) {
      r[3 * k + c] = rk[c];
      v[3 * k + c] = vk[c];
    }
  }
};

void per_propagation(benchmark::State& state, std::size_t n) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(n));
  state.counters["per_propagation"] = benchmark::Counter(
      static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// One set's day into sink[k0 ...]: Vallado's sgp4() per call, NaNs and his error code on failure.
void vallado_day(elsetrec& rec, const std::vector<double>& times, Sink& sink, std::size_t k0) {
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t j = 0; j < times.size(); ++j) {
    double r[3], v[3];
    SGP4Funcs::sgp4(rec, times[j], r, v);
    const int code = rec.error;
    if (code != 0) r[0] = r[1] = r[2] = v[0] = v[1] = v[2] = kNan;
    sink.put(k0 + j, code, r, v);
  }
}

// The same through trakbox: per call, or (batch) propagate_batch into `scratch` first.
void trakbox_day(const Sgp4& sat, const std::vector<double>& times, Sink& sink, std::size_t k0, bool batch,
                 std::vector<Propagation>& scratch) {
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  const double nan3[3] = {kNan, kNan, kNan};
  auto put = [&](std::size_t j, const Propagation& p) {
    if (p.ok())
      sink.put(k0 + j, 0, p.state.r_km.data(), p.state.v_km_s.data());
    else
      sink.put(k0 + j, static_cast<int>(p.error), nan3, nan3);
  };
  if (batch) {
    propagate_batch(sat, times, scratch);
    for (std::size_t j = 0; j < times.size(); ++j) put(j, scratch[j]);
  } else {
    for (std::size_t j = 0; j < times.size(); ++j) put(j, sat.propagate_minutes(times[j]));
  }
}

// ---- one set (ISS, 2018), one call per propagation
void BM_PerCall_ISS_Vallado(benchmark::State& state) {
  const Sgp4 sat(tb::testing::iss_2018());
  elsetrec rec = vallado_init(sat);
  double r[3], v[3];
  for (auto _ : state) {
    for (int m = 0; m < kTimes; ++m) {
      SGP4Funcs::sgp4(rec, m, r, v);
      benchmark::DoNotOptimize(r);
      benchmark::DoNotOptimize(v);
    }
  }
  per_propagation(state, kTimes);
}
void BM_PerCall_ISS_Trakbox(benchmark::State& state) {
  const Sgp4 sat(tb::testing::iss_2018());
  for (auto _ : state) {
    for (int m = 0; m < kTimes; ++m) {
      Propagation p = sat.propagate_minutes(m);
      benchmark::DoNotOptimize(p);
    }
  }
  per_propagation(state, kTimes);
}

// The two implementations' largest differences over the whole catalogue day, and the propagations
// whose error codes differ (0 expected): the "results unchanged" half of the comparison.
struct Agreement {
  double dr_km = 0.0, dv_km_s = 0.0;
  std::size_t codes_differ = 0;
};
const Agreement& agreement() {
  static const Agreement a = [] {
    Agreement out;
    for (const Sgp4& s : sats()) {
      elsetrec rec = vallado_init(s);
      for (const double t : times_for(s.epoch_jd())) {
        double r[3], v[3];
        SGP4Funcs::sgp4(rec, t, r, v);
        const Propagation p = s.propagate_minutes(t);
        // Vallado's code 6 (decayed) still fills in a state; trakbox gives none.
        if (static_cast<int>(p.error) != rec.error) ++out.codes_differ;
        if (!p.ok() || rec.error != 0) continue;
        for (int c = 0; c < 3; ++c) {
          out.dr_km = std::max(out.dr_km, std::abs(p.state.r_km[c] - r[c]));
          out.dv_km_s = std::max(out.dv_km_s, std::abs(p.state.v_km_s[c] - v[c]));
        }
      }
    }
    return out;
  }();
  return a;
}

// ---- the catalogue, every set at every minute of a day, one call per propagation
void BM_PerCall_Catalogue_Vallado(benchmark::State& state) {
  const std::vector<Sgp4>& set = sats(state.range(0));
  std::vector<elsetrec> recs;
  std::vector<std::vector<double>> times;
  for (const Sgp4& s : set) {
    recs.push_back(vallado_init(s));
    times.push_back(times_for(s.epoch_jd()));
  }
  Sink sink(recs.size() * kTimes);
  for (auto _ : state) {
    for (std::size_t s = 0; s < recs.size(); ++s) vallado_day(recs[s], times[s], sink, s * kTimes);
    benchmark::ClobberMemory();
  }
  state.SetLabel(subset_label(state.range(0)));
  per_propagation(state, recs.size() * kTimes);
}

// trakbox per call (batch false) or through the batch interface, the kernel dispatch chooses.
void trakbox_catalogue(benchmark::State& state, bool batch) {
  const std::vector<Sgp4>& set = sats(state.range(0));
  std::vector<std::vector<double>> times;
  for (const Sgp4& s : set) times.push_back(times_for(s.epoch_jd()));
  Sink sink(set.size() * kTimes);
  std::vector<Propagation> scratch(kTimes);
  for (auto _ : state) {
    for (std::size_t s = 0; s < set.size(); ++s) trakbox_day(set[s], times[s], sink, s * kTimes, batch, scratch);
    benchmark::ClobberMemory();
  }
  state.SetLabel(batch ? std::string(subset_label(state.range(0))) + ", " + batch_kernel_isa()
                       : std::string(subset_label(state.range(0))));
  per_propagation(state, set.size() * kTimes);
  if (!batch && state.range(0) == 0) {
    state.counters["max_dr_km"] = agreement().dr_km;
    state.counters["max_dv_km_s"] = agreement().dv_km_s;
    state.counters["codes_differ"] = static_cast<double>(agreement().codes_differ);
  }
}
void BM_PerCall_Catalogue_Trakbox(benchmark::State& state) { trakbox_catalogue(state, false); }
void BM_Batch_Catalogue_Trakbox(benchmark::State& state) { trakbox_catalogue(state, true); }

// ---- both in one loop: set by set, Vallado's day then trakbox's (the order alternating), each
// timed on the thread's CPU clock, so that the machine's load falls on both alike. Counters:
// ns per propagation of each and their ratio. Arg as above; Arg 10 + k: trakbox's batch instead.
void BM_Ratio_Catalogue(benchmark::State& state) {
  const bool batch = state.range(0) >= 10;
  const std::int64_t which = state.range(0) % 10;
  const std::vector<Sgp4>& set = sats(which);
  std::vector<elsetrec> recs;
  std::vector<std::vector<double>> times;
  for (const Sgp4& s : set) {
    recs.push_back(vallado_init(s));
    times.push_back(times_for(s.epoch_jd()));
  }
  Sink sink_v(kTimes), sink_t(kTimes);
  std::vector<Propagation> scratch(kTimes);
  double ns_v = 0.0, ns_t = 0.0;
  bool vallado_first = true;
  auto run_vallado = [&](std::size_t s) {
    const double t0 = thread_cpu_ns();
    vallado_day(recs[s], times[s], sink_v, 0);
    benchmark::ClobberMemory();
    ns_v += thread_cpu_ns() - t0;
  };
  auto run_trakbox = [&](std::size_t s) {
    const double t0 = thread_cpu_ns();
    trakbox_day(set[s], times[s], sink_t, 0, batch, scratch);
    benchmark::ClobberMemory();
    ns_t += thread_cpu_ns() - t0;
  };
  for (auto _ : state) {
    for (std::size_t s = 0; s < set.size(); ++s) {
      if (vallado_first) {
        run_vallado(s);
        run_trakbox(s);
      } else {
        run_trakbox(s);
        run_vallado(s);
      }
      vallado_first = !vallado_first;
    }
  }
  const double n = static_cast<double>(state.iterations()) * static_cast<double>(set.size() * kTimes);
  state.counters["vallado_ns"] = ns_v / n;
  state.counters["trakbox_ns"] = ns_t / n;
  state.counters["ratio"] = ns_t / ns_v;
  state.SetLabel(std::string(subset_label(which)) + (batch ? ", trakbox batch (" + std::string(batch_kernel_isa()) + ")"
                                                           : ", trakbox per call"));
}

}  // namespace

BENCHMARK(BM_Ratio_Catalogue)->Arg(0)->Arg(1)->Arg(2)->Arg(10)->Arg(11)->Arg(12)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_PerCall_ISS_Vallado);
BENCHMARK(BM_PerCall_ISS_Trakbox);
BENCHMARK(BM_PerCall_Catalogue_Vallado)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_PerCall_Catalogue_Trakbox)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_Batch_Catalogue_Trakbox)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->MinTime(2.0);

BENCHMARK_MAIN();
