// The resonance integrator's checkpoints must not change a single bit: a propagation that starts
// from a checkpoint gives exactly what integrating from epoch gives (the reference's way, here the
// same set with its checkpoints dropped), from a year before epoch to a year after and beyond the
// checkpoints' span. The states pinned below were printed with %a by the integrate-from-epoch code
// with glibc's sine and cosine; since the propagator has its own (sgp4_common.h) and, on x86-64 with
// FMA, contracted multiply-adds, they are checked to 1e-11 relative (a year from epoch the two
// differ by 2e-8 km of 20,000 km; 2e-7 km is the tolerance of the comparison with Vallado's output).
#include <doctest/doctest.h>

#include <array>
#include <vector>

#include "orbit/sgp4.h"
#include "support/gpredict_sets.h"

using namespace tb::orbit;

namespace {
struct Pinned {
  double minutes;
  Vec3 r, v;
};
constexpr std::array<Pinned, 8> kPinned{{
  {-527373.25, {-0x1.53fec5ae7bb05p+14, -0x1.6a809a84871b3p+13, 0x1.0046cece8d1e1p+15}, {0x1.9b63247eb3e34p-1, -0x1.184b6eb7eef7dp+0, 0x1.9a5aedfa5cb14p+0}},
  {-43200.50, {0x1.fd6c28e2d1f57p+11, -0x1.7b92c442191a8p+13, 0x1.c064858a465f8p+10}, {0x1.4c59ad12e688bp+0, 0x1.04f64d6c7dbe1p+2, -0x1.54878b4a6423bp+2}},
  {-1439.00, {-0x1.96825bc2a6235p+13, 0x1.f8732a2a39e11p+13, 0x1.b32bd06840364p+13}, {-0x1.f8369fa43e284p+0, -0x1.33c65db2d00cap-5, 0x1.ce16bd84d0ae3p+1}},
  {1439.00, {-0x1.a9d439cfd63b9p+13, 0x1.f9046157e9591p+13, 0x1.dc3a503056ca8p+13}, {-0x1.da411841717f2p+0, -0x1.5f0739b70b776p-3, 0x1.bdaa48897faa6p+1}},
  {10081.70, {-0x1.f4fbf4acd3f27p+13, 0x1.ea717213d3f8cp+13, 0x1.409ca28972222p+14}, {-0x1.6d9816c614c31p+0, -0x1.3a9898b946396p-1, 0x1.7b9c197621d3p+1}},
  {43200.00, {-0x1.416799411e7f9p+14, 0x1.575c7954e0d1p+13, 0x1.04af5faa3531p+15}, {-0x1.23ab2372492dcp-1, -0x1.42a4962d014b1p+0, 0x1.a18920eb6c051p+0}},
  {144000.25, {-0x1.00bb638c7c086p+14, -0x1.86925c403bfb2p+13, 0x1.fce7f755a4ffp+14}, {0x1.ff7ce9377a10cp-1, -0x1.3117536ca52ffp+0, -0x1.ccea775614f09p+0}},
  {528040.00, {-0x1.1bafb081bf09p+14, -0x1.d208a18d90a07p+12, 0x1.242687cf0ae22p+14}, {0x1.49fa6ba6e5d78p+0, -0x1.32e3fc050e5f5p+0, -0x1.ae51ff91f4b4p+1}},
}};
}  // namespace

TEST_CASE("Resonant SDP4 with integrator checkpoints is bit-identical to integrating from epoch") {
  const Sgp4 sat(tb::testing::molniya_2018());
  for (const Pinned& p : kPinned) {
    CAPTURE(p.minutes);
    const Propagation got = sat.propagate_minutes(p.minutes);
    REQUIRE(got.ok());
    for (int c = 0; c < 3; ++c) {
      CHECK(got.state.r_km[c] == doctest::Approx(p.r[c]).epsilon(1e-11));
      CHECK(got.state.v_km_s[c] == doctest::Approx(p.v[c]).epsilon(1e-11));
    }
  }
  // Bit for bit against integrating from epoch: the pinned times, then every 97.3 minutes over two
  // years each way (past the 366 days of checkpoints), and on and beside step boundaries.
  const Sgp4 from_epoch = detail::without_resonance_checkpoints(sat);
  std::vector<double> times;
  for (const Pinned& p : kPinned) times.push_back(p.minutes);
  for (double t = -1051200.0; t <= 1051200.0; t += 97.3) times.push_back(t);
  for (double k : {1.0, 2.0, 3.0, 731.0, 732.0, 733.0}) {
    for (double d : {-1e-3, 0.0, 1e-3}) {
      times.push_back(k * 720.0 + d);
      times.push_back(-k * 720.0 + d);
    }
  }
  std::size_t compared = 0;
  for (const double t : times) {
    CAPTURE(t);
    const Propagation a = sat.propagate_minutes(t);
    const Propagation b = from_epoch.propagate_minutes(t);
    REQUIRE(a.error == b.error);
    if (!a.ok()) continue;
    for (int c = 0; c < 3; ++c) {
      REQUIRE(a.state.r_km[c] == b.state.r_km[c]);
      REQUIRE(a.state.v_km_s[c] == b.state.v_km_s[c]);
    }
    ++compared;
  }
  CHECK(compared > 21000);
}

TEST_CASE("Resonant SDP4: a checkpoint boundary gives the same bits whichever side is asked first") {
  const Sgp4 a(tb::testing::molniya_2018());
  const Sgp4 b(tb::testing::molniya_2018());
  // 1440 minutes is two integrator steps: t on either side of a checkpoint and exactly on it.
  for (double t : {2879.999, 2880.0, 2880.001, 3599.999, 3600.0, -2880.0, -2880.001}) {
    CAPTURE(t);
    const Propagation x = a.propagate_minutes(t);
    (void)b.propagate_minutes(-t);
    const Propagation y = b.propagate_minutes(t);
    for (int c = 0; c < 3; ++c) CHECK(x.state.r_km[c] == y.state.r_km[c]);
  }
}
