#include <doctest/doctest.h>
#include "test_paths.h"  // TRAKBOX_SOURCE_DIR, ...

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "orbit/elements.h"
#include "orbit/passes.h"
#include "support/gpredict_sets.h"
#include "pass_places.h"

using namespace tb::orbit;

using namespace tb::testing::pass_places;

namespace {

// The 979 element sets of Debian's gpredict, by catalog number (epochs 2017-12 .. 2018-01-22).
const std::map<int, Elements>& catalog() {
  static const std::map<int, Elements> sets = [] {
    std::map<int, Elements> m;
    for (const Elements& e : tb::testing::gpredict_catalogue_sets()) m.emplace(e.catalog_number, e);
    return m;
  }();
  return sets;
}

const Elements& set(int catalog_number) {
  const auto it = catalog().find(catalog_number);
  REQUIRE(it != catalog().end());
  return it->second;
}

const Observer kTucsonPasses{32.2226, -110.9747, 800.0};
const Observer kTromso{69.6496, 18.9560, 100.0};

double since0(UtcTime t) { return minutes_between(kDay0, t) * 60.0; }

// --- Skyfield reference -----------------------------------------------------------------------------
// Window 2018-01-21T00:00Z .. 2018-01-22T00:00Z, horizon -2 deg, times in seconds from the window
// start. Skyfield's find_events is good to about a second (one UKUBE-1 set is 1 s off), so each event
// is polished on Skyfield's own altitude. Printed by this script (Debian python3-skyfield 1.45 with
// python3-sgp4, run with /usr/bin/python3; T(43200).dut1 = 0.206455 s is the UT1 both sides use):
//
//   # /usr/bin/python3 gen_reference.py  (Debian python3-skyfield; builtin timescale, no ephemeris files)
//   # Skyfield's find_events gives rise/culminate/set to about a second; each event is then polished on
//   # Skyfield's own altitude (bisection to 1e-4 s, golden section to 1e-3 s).
//   from skyfield.api import load, wgs84, EarthSatellite
//   import numpy as np
//   ts = load.timescale(builtin=True)
//   sats = {}
//   for block in open('/usr/share/gpredict/data/satdata/satellites.dat').read().split('\n['):
//       d = dict(l.split('=', 1) for l in block.splitlines() if '=' in l)
//       if 'TLE1' in d: sats[int(d['TLE1'][2:7])] = EarthSatellite(d['TLE1'], d['TLE2'], d['NAME'], ts)
//   stations = {'tucson': (32.2226, -110.9747, 800.0), 'darmstadt': (49.8706, 8.6494, 140.0),
//               'sydney': (-33.8688, 151.2093, 50.0), 'tromso': (69.6496, 18.9560, 100.0)}
//   cases = [(25544, 'tucson'), (33591, 'darmstadt'), (40025, 'tucson'), (40074, 'darmstadt'),
//            (38771, 'tromso'), (42725, 'tromso'), (13070, 'tucson')]
//   t0, t1 = ts.utc(2018, 1, 21), ts.utc(2018, 1, 22)
//   def T(sec): return ts.utc(2018, 1, 21, 0, 0, sec)  # seconds from the window start
//   def alt(sat, topo, sec): return (sat - topo).at(T(sec)).altaz()[0].degrees
//   def cross(f, a, b):  # the sign change of f next to [a, b], bisected to 1e-4 s
//       while (f(a) < 0) == (f(b) < 0): a, b = a - 1, b + 1
//       fa = f(a)
//       while b - a > 1e-4:
//           m = (a + b) / 2
//           if (f(m) < 0) == (fa < 0): a = m
//           else: b = m
//       return (a + b) / 2
//   def peak(f, a, b):  # golden section to 1e-3 s
//       g = 0.6180339887498949
//       c, d = b - g * (b - a), a + g * (b - a)
//       fc, fd = f(c), f(d)
//       while b - a > 1e-3:
//           if fc > fd: b, d, fd = d, c, fc; c = b - g * (b - a); fc = f(c)
//           else: a, c, fc = c, d, fd; d = a + g * (b - a); fd = f(d)
//       return (a + b) / 2
//   print(f'// DUT1 {T(43200).dut1:.6f} s')
//   for num, st in cases:
//       sat, topo = sats[num], wgs84.latlon(*stations[st])
//       f = lambda sec: alt(sat, topo, sec) + 2.0
//       t, ev = sat.find_events(topo, t0, t1, altitude_degrees=-2.0)
//       print(f'{{{num}, "{st}", {{  // {sat.name}, events {"".join(map(str, ev))}')
//       p = None
//       for jd, e in zip(t, ev):
//           sec = (jd - t0) * 86400.0
//           if e == 0: p = [cross(f, sec - 0.5, sec + 0.5), []]
//           elif e == 1 and p is not None:
//               m = peak(f, sec - 60, sec + 60); p[1].append((m, alt(sat, topo, m)))
//           elif e == 2 and p is not None:
//               s = cross(f, sec - 0.5, sec + 0.5)
//               print(f'  {{{p[0]:.3f}, {s:.3f}, {{' + ', '.join(f'{{{m:.3f}, {el:.5f}}}' for m, el in p[1]) + '}},')
//               p = None
//       print('}},')
//   for num, st in [(38552, 'darmstadt'), (41866, 'sydney')]:  # geostationary: no events, so sample
//       sat, topo = sats[num], wgs84.latlon(*stations[st])
//       secs = np.arange(0, 86401, 60.0)
//       alts = (sat - topo).at(T(secs)).altaz()[0].degrees
//       i = int(np.argmax(alts))
//       print(f'// {num} {sat.name} from {st}: el {alts.min():.5f} .. {alts.max():.5f} (highest minute {secs[i]:.0f} s)')
//
constexpr double kDut1 = 0.206455;

struct RefPass {
  double rise, set;
  std::vector<std::pair<double, double>> culminations;  // time, elevation (deg)
};
struct RefCase {
  int catalog_number;
  Observer station;
  const char* what;
  std::vector<RefPass> passes;
};

const std::vector<RefCase>& skyfield_cases() {
  static const std::vector<RefCase> cases = {
      {25544, kTucsonPasses, "ISS (ZARYA), LEO 51.6 deg", {
        {7012.063, 7557.616, {{7284.557, 7.09724}}},
        {12693.346, 13397.764, {{13044.271, 68.16384}}},
        {18574.430, 19154.774, {{18863.919, 8.52553}}},
        {24562.991, 24929.670, {{24746.215, 0.85163}}},
        {30434.859, 30865.890, {{30650.463, 2.23533}}},
        {36190.498, 36835.354, {{36513.482, 15.28810}}},
        {41961.841, 42659.518, {{42311.380, 43.90372}}},
        {47892.258, 48219.570, {{48055.878, 0.34898}}},
      }},
      {33591, kDarmstadt, "NOAA 19, LEO sun-synchronous", {
        {7088.167, 7953.765, {{7522.330, 14.06888}}},
        {13103.921, 14123.271, {{13614.272, 82.17180}}},
        {19167.540, 20070.093, {{19618.363, 20.55534}}},
        {25253.661, 25822.324, {{25537.624, 3.20378}}},
        {37072.873, 37356.261, {{37214.522, -0.87659}}},
        {42720.468, 43462.690, {{43091.066, 8.81158}}},
        {48562.350, 49538.977, {{49048.507, 40.61565}}},
        {54605.120, 55586.503, {{55092.572, 36.22355}}},
        {60927.549, 61539.066, {{61231.883, 3.53861}}},
      }},
      {40025, kTucsonPasses, "QB50P1: a grazing pass 0.003 deg above the horizon", {
        {20710.655, 21228.732, {{20970.731, 3.29731}}},
        {26324.196, 27163.228, {{26745.683, 81.50222}}},
        {32149.311, 32744.986, {{32447.198, 6.36302}}},
        {59898.357, 59911.807, {{59905.082, -1.99694}}},
        {65175.666, 65970.847, {{65571.306, 30.55473}}},
        {70947.966, 71689.738, {{71316.338, 16.21263}}},
      }},
      {40074, kDarmstadt, "UKUBE-1: two grazing passes", {
        {718.526, 1548.449, {{1132.055, 47.04994}}},
        {6517.025, 7301.395, {{6907.351, 21.04435}}},
        {12707.162, 12828.787, {{12767.925, -1.77399}}},
        {42912.755, 43465.755, {{43190.165, 4.08234}}},
        {48597.679, 49433.110, {{49017.117, 44.34145}}},
        {54371.889, 55155.109, {{54764.188, 23.66854}}},
        {60202.097, 60669.792, {{60435.919, 2.40227}}},
        {77152.353, 77188.853, {{77170.603, -1.97754}}},
        {82471.324, 83144.888, {{82807.752, 10.44127}}},
      }},
      {38771, kTromso, "METOP-B from 69.6 N: fourteen passes", {
        {3782.186, 4154.228, {{3968.096, -0.24709}}},
        {10081.316, 10376.010, {{10228.693, -0.93314}}},
        {16178.091, 16760.505, {{16469.731, 2.91483}}},
        {22235.997, 23063.696, {{22651.017, 12.10502}}},
        {28280.811, 29242.651, {{28763.324, 31.88247}}},
        {34311.614, 35310.512, {{34812.418, 82.52196}}},
        {40321.467, 41293.222, {{40808.065, 45.27036}}},
        {46300.336, 47227.515, {{46764.121, 27.96882}}},
        {52243.992, 53158.417, {{52701.040, 25.27114}}},
        {58171.131, 59118.614, {{58644.271, 33.75684}}},
        {64123.670, 65113.763, {{64617.470, 65.04226}}},
        {70144.038, 71134.934, {{70637.734, 52.38134}}},
        {76263.283, 77173.120, {{76716.596, 20.14242}}},
        {82502.571, 83223.833, {{82862.314, 6.81691}}},
      }},
      {42725, kTromso, "LILACSAT-1: a pass 0.005 deg above the horizon lasting 16 s", {
        {3340.504, 3356.289, {{3348.396, -1.99488}}},
        {74692.237, 75026.522, {{74859.291, 0.62911}}},
        {80326.158, 80702.666, {{80514.342, 1.47743}}},
        {86040.537, 86291.730, {{86166.121, -0.60686}}},
      }},
      {13070, kTucsonPasses, "MOLNIYA 1-53: an 11-hour pass with two maxima", {
        {24393.688, 65255.324, {{28083.403, 89.56845}, {62655.733, 87.28836}}},
      }},
  };
  return cases;
}

}  // namespace

TEST_CASE("Passes agree with Skyfield's find_events: LEO, grazing, Molniya") {
  const EarthOrientation eo{kDut1};
  double worst_aos = 0.0, worst_los = 0.0, worst_tca = 0.0, worst_el = 0.0;
  for (const RefCase& c : skyfield_cases()) {
    CAPTURE(c.what);
    const Sgp4 sat(set(c.catalog_number));
    const std::vector<Pass> passes = find_passes(sat, c.station, kDay0, kDay1, {}, eo);
    REQUIRE(passes.size() == c.passes.size());
    for (std::size_t i = 0; i < passes.size(); ++i) {
      const Pass& p = passes[i];
      const RefPass& r = c.passes[i];
      CAPTURE(i);
      CHECK_FALSE(p.up_at_start);
      CHECK_FALSE(p.up_at_end);
      const auto top = *std::max_element(r.culminations.begin(), r.culminations.end(),
                                         [](const auto& a, const auto& b) { return a.second < b.second; });
      CHECK(std::abs(since0(p.aos) - r.rise) < 1.0);
      CHECK(std::abs(since0(p.los) - r.set) < 1.0);
      CHECK(std::abs(since0(p.tca) - top.first) < 1.0);
      CHECK(std::abs(p.max_el_deg - top.second) < 0.01);
      CHECK(p.aos < p.tca);
      CHECK(p.tca < p.los);
      worst_aos = std::max(worst_aos, std::abs(since0(p.aos) - r.rise));
      worst_los = std::max(worst_los, std::abs(since0(p.los) - r.set));
      worst_tca = std::max(worst_tca, std::abs(since0(p.tca) - top.first));
      worst_el = std::max(worst_el, std::abs(p.max_el_deg - top.second));
    }
  }
  // What the comparison measures (docs/passes.md quotes it): far inside the tolerances above.
  MESSAGE("worst differences: AOS " << worst_aos << " s, LOS " << worst_los << " s, TCA " << worst_tca
                                    << " s, max elevation " << worst_el << " deg");
  CHECK(worst_aos < 0.05);
  CHECK(worst_los < 0.05);
  CHECK(worst_tca < 0.1);
  CHECK(worst_el < 1e-4);
}

TEST_CASE("Geostationary: always up is one pass over the window, never up is none") {
  const EarthOrientation eo{kDut1};
  // METEOSAT-10 from Darmstadt: Skyfield, every minute of the day, gives 31.41719 .. 33.31521 deg,
  // highest at 83640 s; find_events reports its one culmination at 83655.514 s, 33.31521 deg.
  const Sgp4 meteosat(set(38552));
  PassSearchStats stats;
  const std::vector<Pass> up = find_passes(meteosat, kDarmstadt, kDay0, kDay1, {}, eo, stats);
  REQUIRE(up.size() == 1);
  CHECK(up[0].up_at_start);
  CHECK(up[0].up_at_end);
  CHECK(up[0].aos == kDay0);
  CHECK(up[0].los == kDay1);
  CHECK(std::abs(up[0].max_el_deg - 33.31521) < 0.001);
  CHECK(std::abs(since0(up[0].tca) - 83655.514) < 120.0);  // a flat top: 0.00001 deg per minute
  CHECK(stats.propagations < 60);
  // GOES 16 from Sydney: -41.44716 .. -41.40697 deg all day.
  const Sgp4 goes(set(41866));
  PassSearchStats none_stats;
  CHECK(find_passes(goes, kSydney, kDay0, kDay1, {}, eo, none_stats).empty());
  CHECK(none_stats.propagations < 20);
  // A horizon above GOES 16 as seen from Tucson (36.38 deg) leaves no pass; one below it, one pass.
  const Sgp4 goes16(set(41866));
  PassOptions high;
  high.horizon_deg = 40.0;
  CHECK(find_passes(goes16, kTucsonPasses, kDay0, kDay1, high, eo).empty());
  high.horizon_deg = 30.0;
  CHECK(find_passes(goes16, kTucsonPasses, kDay0, kDay1, high, eo).size() == 1);
}

namespace {

// Steps every 10 s through the window with observe() and checks every interval above the horizon
// against find_passes: each must lie inside one pass whose AOS and LOS are within one step of it and
// whose maximum is at least the highest sample. Every pass must also start and end on the horizon.
struct BruteStats {
  long runs = 0, grazing_runs = 0, passes = 0, propagations = 0, sets = 0;
};

void brute_force_check(const Sgp4& sat, const Observer& o, UtcTime start, UtcTime stop, const PassOptions& opt,
                       BruteStats& stats) {
  constexpr double step_s = 10.0;
  PassSearchStats ps;
  const std::vector<Pass> passes = find_passes(sat, o, start, stop, opt, {}, ps);
  stats.propagations += ps.propagations;
  stats.passes += static_cast<long>(passes.size());
  ++stats.sets;
  CAPTURE(sat.elements().name);
  CAPTURE(o.lat_deg);
  CAPTURE(o.lon_deg);
  for (std::size_t i = 0; i < passes.size(); ++i) {
    const Pass& p = passes[i];
    CAPTURE(format_iso8601(p.aos, 2));
    CHECK(p.aos <= p.tca);
    CHECK(p.tca <= p.los);
    CHECK(p.aos >= start);
    CHECK(p.los <= stop);
    if (i > 0) CHECK(passes[i - 1].los < p.aos);
    CHECK(p.max_el_deg >= opt.min_max_elevation_deg);
    // On the horizon at AOS and LOS (to the precision), at the maximum at TCA.
    const Observation at_tca = observe(sat, o, p.tca);
    REQUIRE(at_tca.ok());
    CHECK(std::abs(at_tca.look.el_deg - p.max_el_deg) < 1e-4);
    if (!p.up_at_start) {
      CHECK(observe(sat, o, add_seconds(p.aos, -opt.precision_s)).look.el_deg < opt.horizon_deg);
      CHECK(observe(sat, o, add_seconds(p.aos, opt.precision_s)).look.el_deg >= opt.horizon_deg);
    }
    if (!p.up_at_end) {
      CHECK(observe(sat, o, add_seconds(p.los, -opt.precision_s)).look.el_deg >= opt.horizon_deg);
      CHECK(observe(sat, o, add_seconds(p.los, opt.precision_s)).look.el_deg < opt.horizon_deg);
    }
  }
  auto check_run = [&](UtcTime a, UtcTime b, double highest) {
    ++stats.runs;
    if (highest < opt.horizon_deg + 0.5) ++stats.grazing_runs;
    if (highest < opt.min_max_elevation_deg - 1e-4) return;  // filtered out, rightly or not: see below
    // Inside a pass, to the precision (a sample may fall a hair after a true AOS).
    const auto it = std::find_if(passes.begin(), passes.end(), [&](const Pass& p) {
      return p.aos <= add_seconds(a, opt.precision_s) && add_seconds(b, -opt.precision_s) <= p.los;
    });
    CAPTURE(format_iso8601(a));
    CAPTURE(format_iso8601(b));
    CAPTURE(highest);
    REQUIRE_MESSAGE(it != passes.end(), "a pass the 10 s steps see is missing");
    if (!it->up_at_start) CHECK(minutes_between(it->aos, a) * 60.0 <= step_s);
    if (!it->up_at_end) CHECK(minutes_between(b, it->los) * 60.0 <= step_s);
    CHECK(it->max_el_deg >= highest - 1e-4);
  };
  bool up = false;
  UtcTime run_start{}, run_end{};
  double highest = -90.0;
  for (UtcTime t = start; t < stop; t = add_seconds(t, step_s)) {
    const Observation ob = observe(sat, o, t);
    if (!ob.ok()) break;  // the search must end here too: checked by the decay test
    if (ob.look.el_deg >= opt.horizon_deg) {
      if (!up) {
        up = true;
        run_start = t;
        highest = -90.0;
      }
      run_end = t;
      highest = std::max(highest, ob.look.el_deg);
    } else if (up) {
      up = false;
      check_run(run_start, run_end, highest);
    }
  }
  if (up) check_run(run_start, run_end, highest);
}

}  // namespace

TEST_CASE("Brute force: every interval above the horizon in 10 s steps is found") {
  // Every 10th set of the catalogue plus every elliptical and geostationary one, from three stations.
  std::vector<const Elements*> sample;
  int k = 0;
  for (const auto& [num, e] : catalog()) {
    const bool special = e.eccentricity > 0.1 || e.mean_motion_rev_per_day < 1.5;
    if (special || k++ % 10 == 0) sample.push_back(&e);
  }
  BruteStats stats;
  for (const Observer& o : {kDarmstadt, kSydney, kTromso}) {
    for (const Elements* e : sample) brute_force_check(Sgp4(*e), o, kDay0, kDay1, {}, stats);
  }
  MESSAGE(stats.sets << " set-days, " << stats.runs << " intervals above the horizon (" << stats.grazing_runs
                     << " with a maximum within 0.5 deg of it), " << stats.passes << " passes, "
                     << static_cast<double>(stats.propagations) / static_cast<double>(stats.sets)
                     << " propagations per set-day");
  CHECK(stats.grazing_runs > 10);  // the sample does exercise grazing passes
}

TEST_CASE("Brute force: other horizons, a minimum elevation, a two-day window") {
  BruteStats stats;
  PassOptions ten;
  ten.horizon_deg = 10.0;
  PassOptions zero_min20;
  zero_min20.horizon_deg = 0.0;
  zero_min20.min_max_elevation_deg = 20.0;
  for (int num : {25544, 33591, 13070, 38552, 25989, 40025, 20580}) {
    const Sgp4 sat(set(num));
    brute_force_check(sat, kTucsonPasses, kDay0, kDay1, ten, stats);
    brute_force_check(sat, kDarmstadt, kDay0, kDay1, zero_min20, stats);
    brute_force_check(sat, kSydney, from_civil(2018, 1, 20, 7, 13, 5.5), from_civil(2018, 1, 22, 9), {}, stats);
  }
}

TEST_CASE("A window that starts or ends inside a pass") {
  // ISS from Tucson, Skyfield: rise 12693.346 s, culminate 13044.271 s at 68.16384 deg, set 13397.764 s.
  const Sgp4 iss(set(25544));
  const EarthOrientation eo{kDut1};
  const UtcTime rise = add_seconds(kDay0, 12693.346), top = add_seconds(kDay0, 13044.271);
  const UtcTime set_time = add_seconds(kDay0, 13397.764);

  SUBCASE("starts before the maximum") {
    const UtcTime start = add_seconds(rise, 100.0);
    const std::vector<Pass> p = find_passes(iss, kTucsonPasses, start, kDay1, {}, eo);
    REQUIRE(!p.empty());
    CHECK(p[0].up_at_start);
    CHECK_FALSE(p[0].up_at_end);
    CHECK(p[0].aos == start);
    CHECK(std::abs(minutes_between(set_time, p[0].los) * 60.0) < 0.05);
    CHECK(std::abs(minutes_between(top, p[0].tca) * 60.0) < 0.1);
    CHECK(std::abs(p[0].max_el_deg - 68.16384) < 1e-4);
    CHECK(p[0].aos_az_deg == doctest::Approx(observe(iss, kTucsonPasses, start, eo).look.az_deg).epsilon(1e-9));
  }
  SUBCASE("starts after the maximum: the highest point is the start") {
    const UtcTime start = add_seconds(top, 150.0);
    const std::vector<Pass> p = find_passes(iss, kTucsonPasses, start, kDay1, {}, eo);
    REQUIRE(!p.empty());
    CHECK(p[0].up_at_start);
    CHECK(p[0].tca == start);
    CHECK(p[0].max_el_deg == doctest::Approx(observe(iss, kTucsonPasses, start, eo).look.el_deg).epsilon(1e-9));
  }
  SUBCASE("ends before the maximum: the highest point is the end") {
    const UtcTime stop = add_seconds(top, -60.0);
    const std::vector<Pass> p = find_passes(iss, kTucsonPasses, kDay0, stop, {}, eo);
    REQUIRE(!p.empty());
    CHECK(p.back().up_at_end);
    CHECK_FALSE(p.back().up_at_start);
    CHECK(p.back().los == stop);
    CHECK(p.back().tca == stop);
    CHECK(std::abs(minutes_between(rise, p.back().aos) * 60.0) < 0.05);
    CHECK(p.back().max_el_deg == doctest::Approx(observe(iss, kTucsonPasses, stop, eo).look.el_deg).epsilon(1e-9));
    CHECK(p.back().los_az_deg == doctest::Approx(observe(iss, kTucsonPasses, stop, eo).look.az_deg).epsilon(1e-9));
  }
  SUBCASE("the whole window inside one pass") {
    const UtcTime start = add_seconds(top, -30.0), stop = add_seconds(top, 40.0);
    const std::vector<Pass> p = find_passes(iss, kTucsonPasses, start, stop, {}, eo);
    REQUIRE(p.size() == 1);
    CHECK(p[0].up_at_start);
    CHECK(p[0].up_at_end);
    CHECK(p[0].aos == start);
    CHECK(p[0].los == stop);
    CHECK(std::abs(p[0].max_el_deg - 68.16384) < 1e-4);
  }
  SUBCASE("empty and reversed windows") {
    CHECK(find_passes(iss, kTucsonPasses, top, top, {}, eo).empty());
    CHECK(find_passes(iss, kTucsonPasses, kDay1, kDay0, {}, eo).empty());
    CHECK_FALSE(next_pass(iss, kTucsonPasses, kDay0, 0.0, {}, eo).has_value());
  }
  SUBCASE("a window ending exactly at AOS has no pass; one ending just after has a short one") {
    const std::vector<Pass> before = find_passes(iss, kTucsonPasses, add_seconds(rise, -600.0), add_seconds(rise, -0.2));
    CHECK(before.empty());
    const std::vector<Pass> after = find_passes(iss, kTucsonPasses, add_seconds(rise, -600.0), add_seconds(rise, 1.0), {}, eo);
    REQUIRE(after.size() == 1);
    CHECK(after[0].up_at_end);
  }
}

TEST_CASE("A decayed satellite: the search ends where the propagation does") {
  // Vallado's 28872 (MINOTAUR R/B, SGP4-VER.TLE) decays 51.50311 min after its epoch (SGP4 error 6)
  // over 24.60 S, 113.08 W.
  const ParseResult r = parse_nasa(
      "1 28872U 05037B   05333.02012661  .25992681  00000-0  24476-3 0  1534\n"
      "2 28872  96.4736 157.9986 0303955 244.0492 110.6523 16.46015938 10708\n");
  REQUIRE(r.sets.size() == 1);
  const Sgp4 sat(r.sets[0]);
  const UtcTime epoch = sat.epoch();
  const UtcTime decay = add_minutes(epoch, 51.50311);
  REQUIRE(sat.propagate(add_minutes(decay, -0.001)).ok());
  REQUIRE(sat.propagate(add_minutes(decay, 0.001)).error == Sgp4Error::decayed);

  // Beneath the end: the pass is cut by the decay.
  const std::vector<Pass> cut = find_passes(sat, {-24.6018, -113.0817, 0.0}, epoch, add_minutes(epoch, 1440.0));
  REQUIRE(cut.size() == 1);
  CHECK(cut[0].up_at_end);
  CHECK(cut[0].los <= decay);
  CHECK(minutes_between(cut[0].los, decay) * 60.0 < 0.2);
  // Further along the track, a whole pass before the decay, and nothing after.
  const std::vector<Pass> whole = find_passes(sat, {35.0, -100.0, 0.0}, epoch, add_minutes(epoch, 1440.0));
  REQUIRE(whole.size() == 1);
  CHECK_FALSE(whole[0].up_at_end);
  CHECK(whole[0].los < decay);
  // A window after the decay: nothing, at the cost of one propagation.
  PassSearchStats stats;
  CHECK(find_passes(sat, {35.0, -100.0, 0.0}, add_minutes(epoch, 60.0), add_minutes(epoch, 1440.0), {}, {}, stats).empty());
  CHECK(stats.propagations == 1);
  CHECK_FALSE(next_pass(sat, {-24.6018, -113.0817, 0.0}, add_minutes(epoch, 52.0)).has_value());
  // A set SGP4 refuses at initialisation: no pass, no propagation.
  Elements bad = set(25544);
  bad.eccentricity = 1.2;
  const Sgp4 refused(bad);
  REQUIRE(refused.init_error() != Sgp4Error::none);
  PassSearchStats none;
  CHECK(find_passes(refused, kTucsonPasses, kDay0, kDay1, {}, {}, none).empty());
  CHECK(none.propagations == 0);
}

TEST_CASE("Grazing: a horizon a thousandth of a degree under a maximum still finds that pass") {
  // Set the horizon just below (then just above) a known maximum: the pass shrinks to a few seconds
  // around its top and must still be found, at the right time, with the right maximum.
  struct Top {
    int num;
    Observer station;
    double t, el;
  };
  const Top tops[] = {
      {25544, kTucsonPasses, 13044.271, 68.16384},    // ISS, high
      {33591, kDarmstadt, 37214.522, -0.87659}, // NOAA 19, low
      {40025, kTucsonPasses, 59905.082, -1.99694},    // QB50P1, already grazing at -2
      {13070, kTucsonPasses, 62655.733, 87.28836},    // Molniya's lower maximum: its pass splits in two
  };
  const EarthOrientation eo{kDut1};
  for (const Top& top : tops) {
    CAPTURE(top.num);
    const Sgp4 sat(set(top.num));
    PassOptions below, above;
    below.horizon_deg = top.el - 0.001;
    above.horizon_deg = top.el + 0.001;
    const std::vector<Pass> with = find_passes(sat, top.station, kDay0, kDay1, below, eo);
    const std::vector<Pass> without = find_passes(sat, top.station, kDay0, kDay1, above, eo);
    const auto near_top = [&](const Pass& p) { return std::abs(since0(p.tca) - top.t) < 1.0; };
    const auto it = std::find_if(with.begin(), with.end(), near_top);
    REQUIRE(it != with.end());
    CHECK(std::abs(it->max_el_deg - top.el) < 1e-4);
    CHECK(minutes_between(it->aos, it->los) * 60.0 < 60.0);
    CHECK(std::none_of(without.begin(), without.end(), near_top));
    CHECK(with.size() == without.size() + 1);
  }
}

TEST_CASE("Minimum elevation and next_pass") {
  const Sgp4 noaa(set(33591));
  const EarthOrientation eo{kDut1};
  const std::vector<Pass> all = find_passes(noaa, kDarmstadt, kDay0, add_seconds(kDay0, 5 * 86400.0), {}, eo);
  PassOptions ten;
  ten.min_max_elevation_deg = 10.0;
  const std::vector<Pass> high = find_passes(noaa, kDarmstadt, kDay0, add_seconds(kDay0, 5 * 86400.0), ten, eo);
  std::vector<Pass> expected;
  std::copy_if(all.begin(), all.end(), std::back_inserter(expected), [](const Pass& p) { return p.max_el_deg >= 10.0; });
  REQUIRE(high.size() == expected.size());
  REQUIRE(high.size() < all.size());
  for (std::size_t i = 0; i < high.size(); ++i) {
    CHECK(high[i].aos == expected[i].aos);  // the same search, only fewer passes kept
    CHECK(high[i].los == expected[i].los);
    CHECK(high[i].max_el_deg == expected[i].max_el_deg);
  }
  // next_pass: the first pass reaching the minimum, wherever the search starts.
  for (double from_s : {0.0, 7000.0, 8000.0, 40000.0, 100000.0}) {
    CAPTURE(from_s);
    const UtcTime from = add_seconds(kDay0, from_s);
    const std::optional<Pass> next = next_pass(noaa, kDarmstadt, from, 4.0, ten, eo);
    REQUIRE(next.has_value());
    const auto first = std::find_if(high.begin(), high.end(), [&](const Pass& p) { return p.los > from; });
    REQUIRE(first != high.end());
    // The same crossings, found from other samples: the same to far below the precision.
    CHECK(std::abs(minutes_between(next->los, first->los)) * 60.0 < 0.01);
    CHECK(next->up_at_start == (first->aos < from));
    if (!next->up_at_start) CHECK(std::abs(minutes_between(next->aos, first->aos)) * 60.0 < 0.01);
  }
  // A pass in progress counts (aos = from, up_at_start) when what is left of it reaches the minimum.
  const std::optional<Pass> now = next_pass(noaa, kDarmstadt, add_seconds(kDay0, 7400.0), 1.0, ten, eo);
  REQUIRE(now.has_value());
  CHECK(now->up_at_start);
  CHECK(now->aos == add_seconds(kDay0, 7400.0));
  // Nothing reaches 89.9 deg within a day.
  PassOptions zenith;
  zenith.min_max_elevation_deg = 89.9;
  CHECK_FALSE(next_pass(noaa, kDarmstadt, kDay0, 1.0, zenith, eo).has_value());
}

TEST_CASE("The search is cheap: propagations per set-day") {
  // Counts, not clock time (benchmarks measure time): one-minute stepping would cost 1440.
  long total = 0;
  std::size_t n = 0;
  for (const auto& [num, e] : catalog()) {
    PassSearchStats stats;
    find_passes(Sgp4(e), kDarmstadt, kDay0, kDay1, {}, {}, stats);
    total += stats.propagations;
    ++n;
  }
  const double mean = static_cast<double>(total) / static_cast<double>(n);
  MESSAGE(n << " sets from Darmstadt: " << mean << " propagations per set-day");
  CHECK(mean < 200.0);
}

TEST_CASE("PassSearchStats records the time of every propagation, without changing the search") {
  // bench_passes replays these through SGP4 alone to measure what a step costs beyond it.
  const Sgp4 noaa(set(33591));
  PassSearchStats plain;
  const std::vector<Pass> a = find_passes(noaa, kDarmstadt, kDay0, kDay1, {}, {}, plain);
  std::vector<double> times;
  PassSearchStats traced;
  traced.tsince_minutes = &times;
  const std::vector<Pass> b = find_passes(noaa, kDarmstadt, kDay0, kDay1, {}, {}, traced);
  CHECK(traced.propagations == plain.propagations);
  REQUIRE(times.size() == static_cast<std::size_t>(traced.propagations));
  const double t0 = minutes_between(noaa.epoch(), kDay0), t1 = minutes_between(noaa.epoch(), kDay1);
  CHECK(times.front() == t0);  // the search starts at the window start
  for (double t : times) {
    CHECK(t >= t0);
    CHECK(t <= t1);
  }
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].aos == b[i].aos);
    CHECK(a[i].tca == b[i].tca);
    CHECK(a[i].los == b[i].los);
    CHECK(a[i].max_el_deg == b[i].max_el_deg);
  }
}
