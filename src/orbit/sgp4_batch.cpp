#include "orbit/sgp4_batch.h"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "orbit/constants.h"
#include "orbit/sgp4_common.h"

namespace tb::orbit {
namespace {

using wgs72::kJ2;
using wgs72::kKmPerSecPerErPerMin;
using wgs72::kXke;
constexpr double kEarthRadiusKm = wgs72::kRadiusKm;
static_assert(kTwoPi == 6.28318530717958647693);  // the literal this file used to spell out

// 2pi in two parts (twice fdlibm's pio2_1, pio2_1t; see poly_sin_cos in sgp4_common.h).
constexpr double kTwoPiHi = 4.0 * 1.57079632673412561417e+00;
constexpr double kTwoPiLo = 4.0 * 6.07710050650619224932e-11;

using detail::SinCos;
[[gnu::always_inline]] inline SinCos sin_cos(double x) { return detail::poly_sin_cos(x); }

// fmod(x, 2pi) where |x| >= 2pi, x itself below, to rounding: the value of the scalar propagator's
// detail::fmod_two_pi without its branches (its off-by-one correction and its libm fallback for
// huge x), so that the loops over lanes vectorise.
[[gnu::always_inline]] inline double wrap_two_pi(double x) {
  const double t = x * (1.0 / kTwoPi);
  const double k = t >= 0.0 ? std::floor(t) : -std::floor(-t);
  const double r = (x - k * kTwoPiHi) - k * kTwoPiLo;
  return std::fabs(x) < kTwoPi ? x : r;
}

// sin and cos of (a + d) from those of a; for |d| < 2e-3 the short series sgp4.cpp uses, so that the
// two agree to rounding where most of the propagator's corrections are.
[[gnu::always_inline]] inline SinCos add_angle(SinCos a, double d) {
  const SinCos e = sin_cos(d);
  const SinCos small = detail::small_angle_sin_cos(d);
  const bool is_small = std::fabs(d) < detail::kSmallAngle;
  const double sd = is_small ? small.s : e.s;
  const double cd = is_small ? small.c : e.c;
  return {a.s * cd + a.c * sd, a.c * cd - a.s * sd};
}

constexpr std::size_t kBlock = 64;

// The lanes of one block of at most kBlock times, stage by stage. Each stage is a separate loop over
// the lanes so that each is a simple loop the compiler vectorises; the stages are always inline, so
// that near_earth_block compiles to the same loops over the same local arrays as one function would.
struct Block {
  // Secular stage: semi-major axis, mean motion, the long-period axn/ayn, the argument Kepler's
  // equation is solved for, the node; the error so far (Sgp4Error as a double: lanes of one width
  // vectorise).
  double am[kBlock], nm[kBlock], axnl[kBlock], aynl[kBlock], u[kBlock], nodep[kBlock];
  double err[kBlock];
  // Kepler stage: the eccentric longitude (its first iterate u, set by the secular stage) and its sine
  // and cosine; 1 where converged.
  double eo1[kBlock], es[kBlock], ec[kBlock];
  double done[kBlock];
  // Short-period stage: position (km) and velocity (km/s), 0 where the lane failed.
  double rx[kBlock], ry[kBlock], rz[kBlock], vxo[kBlock], vyo[kBlock], vzo[kBlock];
};

// Secular gravity and drag, the long-period periodics: sgp4.cpp's near-earth update up to Kepler.
template <bool kDrag>
[[gnu::always_inline]] inline void secular_stage(const NearEarthTerms& k, const double* tsince, std::size_t n,
                                                 Block& b) {
  for (std::size_t i = 0; i < n; ++i) {
    const double t = tsince[i];
    const double xmdf = k.mo + k.mdot * t;
    const double argpdf = k.argpo + k.argpdot * t;
    const double nodedf = k.nodeo + k.nodedot * t;
    const double t2 = t * t;
    double argpm = argpdf;
    double mm = xmdf;
    const double nodem0 = nodedf + k.nodecf * t2;
    double tempa = 1.0 - k.cc1 * t;
    double tempe = k.bstar * k.cc4 * t;
    double templ = k.t2cof * t2;
    if constexpr (kDrag) {  // !simplified_drag
      const double delomg = k.omgcof * t;
      const SinCos xm = sin_cos(xmdf);
      const double delmtemp = 1.0 + k.eta * xm.c;
      const double delm = k.xmcof * (delmtemp * delmtemp * delmtemp - k.delmo);
      const double temp = delomg + delm;
      mm = xmdf + temp;
      argpm = argpdf - temp;
      const double t3 = t2 * t;
      const double t4 = t3 * t;
      tempa = tempa - k.d2 * t2 - k.d3 * t3 - k.d4 * t4;
      tempe = tempe + k.bstar * k.cc5 * (add_angle(xm, temp).s - k.sinmao);
      templ = templ + k.t3cof * t3 + t4 * (k.t4cof + t * k.t5cof);
    }
    const double a = k.ao * tempa * tempa;
    const double nmv = kXke / (a * std::sqrt(a));
    double em = k.ecco - tempe;
    b.err[i] = (em >= 1.0 || em < -0.001) ? static_cast<double>(Sgp4Error::mean_eccentricity) : 0.0;
    em = em < 1.0e-6 ? 1.0e-6 : em;
    mm = mm + k.no_unkozai * templ;
    double xlm = mm + argpm + nodem0;
    const double nodem = wrap_two_pi(nodem0);
    argpm = wrap_two_pi(argpm);
    xlm = wrap_two_pi(xlm);
    mm = wrap_two_pi(xlm - argpm - nodem);

    const SinCos argp = sin_cos(argpm);
    const double ax = em * argp.c;
    const double temp = 1.0 / (a * (1.0 - em * em));
    const double ay = em * argp.s + temp * k.aycof;
    const double xl = mm + argpm + nodem + temp * k.xlcof * ax;
    b.am[i] = a;
    b.nm[i] = nmv;
    b.axnl[i] = ax;
    b.aynl[i] = ay;
    b.u[i] = wrap_two_pi(xl - nodem);
    b.eo1[i] = b.u[i];  // Kepler's first iterate
    b.nodep[i] = nodem;
  }
}

// Kepler's equation, Newton steps limited to 0.95 rad; as in sgp4.cpp, the sine and cosine kept are
// those of the last iterate evaluated. The block is swept until every lane has converged.
[[gnu::always_inline]] inline void kepler_stage(std::size_t n, Block& b) {
  for (std::size_t i = 0; i < n; ++i) {
    const SinCos e = sin_cos(b.eo1[i]);
    b.es[i] = e.s;
    b.ec[i] = e.c;
    b.done[i] = 0.0;
  }
  for (int iteration = 1; iteration <= 10; ++iteration) {
    for (std::size_t i = 0; i < n; ++i) {
      double tem5 = 1.0 - b.ec[i] * b.axnl[i] - b.es[i] * b.aynl[i];
      tem5 = (b.u[i] - b.aynl[i] * b.ec[i] + b.axnl[i] * b.es[i] - b.eo1[i]) / tem5;
      tem5 = std::fabs(tem5) >= 0.95 ? std::copysign(0.95, tem5) : tem5;
      const bool was_done = b.done[i] != 0.0;
      b.eo1[i] = was_done ? b.eo1[i] : b.eo1[i] + tem5;
      // (| rather than ||: a short-circuit is a branch, and a branch keeps the loop from vectorising)
      const bool now_done = was_done | (std::fabs(tem5) < 1.0e-12) | (iteration == 10);
      const SinCos next = add_angle({b.es[i], b.ec[i]}, tem5);
      b.es[i] = now_done ? b.es[i] : next.s;
      b.ec[i] = now_done ? b.ec[i] : next.c;
      b.done[i] = now_done ? 1.0 : 0.0;
    }
    double open = 0.0;
    for (std::size_t i = 0; i < n; ++i) open += 1.0 - b.done[i];
    if (open == 0.0) break;
  }
}

// The inclination-dependent coefficients of the short-period stage: a near-earth set's own, the same
// for every lane, or a deep-space set's, which depend on the perturbed inclination, lane by lane.
struct SetCoefficients {
  const NearEarthTerms& k;
  double con41(std::size_t) const { return k.con41; }
  double x1mth2(std::size_t) const { return k.x1mth2; }
  double x7thm1(std::size_t) const { return k.x7thm1; }
  double sinio(std::size_t) const { return k.sinio; }
  double cosio(std::size_t) const { return k.cosio; }
};

// A deep-space set's lanes: what Sgp4::perturbed_terms gave for each time (scalar), for the
// vectorised long-period, Kepler and short-period stages.
struct DeepLanes {
  double em[kBlock], argpp[kBlock], mp[kBlock], aycof[kBlock], xlcof[kBlock];
  double con41_[kBlock], x1mth2_[kBlock], x7thm1_[kBlock], sinip[kBlock], cosip[kBlock];
  double con41(std::size_t i) const { return con41_[i]; }
  double x1mth2(std::size_t i) const { return x1mth2_[i]; }
  double x7thm1(std::size_t i) const { return x7thm1_[i]; }
  double sinio(std::size_t i) const { return sinip[i]; }
  double cosio(std::size_t i) const { return cosip[i]; }
};

// Short-period periodics and the orientation vectors: position and velocity, or the lane's error.
template <class Coefficients>
[[gnu::always_inline]] inline void short_period_stage(const Coefficients& k, std::size_t n, Block& b) {
  for (std::size_t i = 0; i < n; ++i) {
    const double a = b.am[i];
    const double ax = b.axnl[i], ay = b.aynl[i];
    const double ecose = ax * b.ec[i] + ay * b.es[i];
    const double esine = ax * b.es[i] - ay * b.ec[i];
    const double el2 = ax * ax + ay * ay;
    const double pl = a * (1.0 - el2);
    const double rl = a * (1.0 - ecose);
    const double rdotl = std::sqrt(a) * esine / rl;
    const double rvdotl = std::sqrt(pl) / rl;
    const double betal = std::sqrt(1.0 - el2);
    double temp = esine / (1.0 + betal);
    const double sinu = a / rl * (b.es[i] - ay - ax * temp);
    const double cosu = a / rl * (b.ec[i] - ax + ay * temp);
    const double sin2u = (cosu + cosu) * sinu;
    const double cos2u = 1.0 - 2.0 * sinu * sinu;
    temp = 1.0 / pl;
    const double temp1 = 0.5 * kJ2 * temp;
    const double temp2 = temp1 * temp;
    const double mrt = rl * (1.0 - 1.5 * temp2 * betal * k.con41(i)) + 0.5 * temp1 * k.x1mth2(i) * cos2u;
    const double xnode = b.nodep[i] + 1.5 * temp2 * k.cosio(i) * sin2u;
    const double mvt = rdotl - b.nm[i] * temp1 * k.x1mth2(i) * sin2u / kXke;
    const double rvdot = rvdotl + b.nm[i] * temp1 * (k.x1mth2(i) * cos2u + 1.5 * k.con41(i)) / kXke;
    const double unit = 1.0 / std::sqrt(sinu * sinu + cosu * cosu);
    const SinCos s = add_angle({sinu * unit, cosu * unit}, -0.25 * temp2 * k.x7thm1(i) * sin2u);
    const SinCos node = sin_cos(xnode);
    const SinCos inc = add_angle({k.sinio(i), k.cosio(i)}, 1.5 * temp2 * k.cosio(i) * k.sinio(i) * cos2u);
    const detail::Orientation o = detail::orientation(s, node, inc);
    double e = b.err[i];
    e = e != 0.0 ? e : (pl < 0.0 ? static_cast<double>(Sgp4Error::semi_latus_rectum) : 0.0);
    e = e != 0.0 ? e : (mrt < 1.0 ? static_cast<double>(Sgp4Error::decayed) : 0.0);
    const bool ok = e == 0.0;
    b.err[i] = e;
    b.rx[i] = ok ? (mrt * o.ux) * kEarthRadiusKm : 0.0;
    b.ry[i] = ok ? (mrt * o.uy) * kEarthRadiusKm : 0.0;
    b.rz[i] = ok ? (mrt * o.uz) * kEarthRadiusKm : 0.0;
    b.vxo[i] = ok ? (mvt * o.ux + rvdot * o.vx) * kKmPerSecPerErPerMin : 0.0;
    b.vyo[i] = ok ? (mvt * o.uy + rvdot * o.vy) * kKmPerSecPerErPerMin : 0.0;
    b.vzo[i] = ok ? (mvt * o.uz + rvdot * o.vz) * kKmPerSecPerErPerMin : 0.0;
  }
}

[[gnu::always_inline]] inline void store_stage(const Block& b, std::size_t n, Propagation* out) {
  for (std::size_t i = 0; i < n; ++i) {
    Propagation& p = out[i];
    p.error = static_cast<Sgp4Error>(static_cast<int>(b.err[i]));
    p.state.r_km = {b.rx[i], b.ry[i], b.rz[i]};
    p.state.v_km_s = {b.vxo[i], b.vyo[i], b.vzo[i]};
  }
}

// One block of at most kBlock times.
template <bool kDrag>
[[gnu::always_inline]] inline void near_earth_block(const NearEarthTerms& k, const double* tsince, std::size_t n,
                                                    Propagation* out) {
  Block b;
  secular_stage<kDrag>(k, tsince, n, b);
  kepler_stage(n, b);
  short_period_stage(SetCoefficients{k}, n, b);
  store_stage(b, n, out);
}

[[gnu::always_inline]] inline void near_earth_blocks(const NearEarthTerms& k, const double* t, std::size_t n,
                                                     Propagation* out) {
  for (std::size_t b = 0; b < n; b += kBlock) {
    if (k.simplified_drag)
      near_earth_block<false>(k, t + b, std::min(kBlock, n - b), out + b);
    else
      near_earth_block<true>(k, t + b, std::min(kBlock, n - b), out + b);
  }
}

// A deep-space set's long-period periodics, lane by lane: sgp4.cpp's finish() up to Kepler.
[[gnu::always_inline]] inline void long_period_stage(const DeepLanes& d, std::size_t n, Block& b) {
  for (std::size_t i = 0; i < n; ++i) {
    const double em = d.em[i], a = b.am[i];
    const SinCos argp = sin_cos(d.argpp[i]);
    const double ax = em * argp.c;
    const double temp = 1.0 / (a * (1.0 - em * em));
    const double ay = em * argp.s + temp * d.aycof[i];
    const double xl = d.mp[i] + d.argpp[i] + b.nodep[i] + temp * d.xlcof[i] * ax;
    b.axnl[i] = ax;
    b.aynl[i] = ay;
    b.u[i] = wrap_two_pi(xl - b.nodep[i]);
    b.eo1[i] = b.u[i];
  }
}

// One block of a deep-space set: the secular, resonance and lunar-solar terms by the scalar code
// (Sgp4::perturbed_terms), the rest vectorised. A lane whose first half failed carries its error
// and harmless numbers through the rest.
[[gnu::always_inline]] inline void deep_space_block(const Sgp4& sat, const double* tsince, std::size_t n,
                                                    Propagation* out) {
  Block b;
  DeepLanes d;
  for (std::size_t i = 0; i < n; ++i) {
    PerturbedTerms p = sat.perturbed_terms(tsince[i]);
    if (p.error != Sgp4Error::none) {
      const Sgp4Error e = p.error;
      p = {1.0, kXke, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, e};
    }
    b.am[i] = p.am;
    b.nm[i] = p.nm;
    b.nodep[i] = p.nodep;
    b.err[i] = static_cast<double>(static_cast<int>(p.error));
    d.em[i] = p.ep;
    d.argpp[i] = p.argpp;
    d.mp[i] = p.mp;
    d.aycof[i] = p.aycof;
    d.xlcof[i] = p.xlcof;
    d.con41_[i] = p.con41;
    d.x1mth2_[i] = p.x1mth2;
    d.x7thm1_[i] = p.x7thm1;
    d.sinip[i] = p.sinip;
    d.cosip[i] = p.cosip;
  }
  long_period_stage(d, n, b);
  kepler_stage(n, b);
  short_period_stage(d, n, b);
  store_stage(b, n, out);
}

[[gnu::always_inline]] inline void deep_space_blocks(const Sgp4& sat, const double* t, std::size_t n,
                                                     Propagation* out) {
  for (std::size_t b = 0; b < n; b += kBlock) deep_space_block(sat, t + b, std::min(kBlock, n - b), out + b);
}

void near_earth_all(const NearEarthTerms& k, const double* t, std::size_t n, Propagation* out) {
  near_earth_blocks(k, t, n, out);
}
void deep_space_all(const Sgp4& sat, const double* t, std::size_t n, Propagation* out) {
  deep_space_blocks(sat, t, n, out);
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define TB_BATCH_DISPATCH 1
[[gnu::target("avx512f,avx512dq,avx512vl")]] void near_earth_avx512(const NearEarthTerms& k, const double* t,
                                                                     std::size_t n, Propagation* out) {
  near_earth_blocks(k, t, n, out);
}
[[gnu::target("avx2,fma")]] void near_earth_avx2(const NearEarthTerms& k, const double* t, std::size_t n,
                                                 Propagation* out) {
  near_earth_blocks(k, t, n, out);
}
[[gnu::target("avx512f,avx512dq,avx512vl")]] void deep_space_avx512(const Sgp4& sat, const double* t, std::size_t n,
                                                                     Propagation* out) {
  deep_space_blocks(sat, t, n, out);
}
[[gnu::target("avx2,fma")]] void deep_space_avx2(const Sgp4& sat, const double* t, std::size_t n, Propagation* out) {
  deep_space_blocks(sat, t, n, out);
}
#endif

using Kernel = void (*)(const NearEarthTerms&, const double*, std::size_t, Propagation*);
using DeepKernel = void (*)(const Sgp4&, const double*, std::size_t, Propagation*);

struct Chosen {
  Kernel kernel;
  DeepKernel deep;
  const char* isa;
};

std::vector<Chosen> available() {
  std::vector<Chosen> out;
#ifdef TB_BATCH_DISPATCH
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl"))
    out.push_back({near_earth_avx512, deep_space_avx512, "avx512f"});
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) out.push_back({near_earth_avx2, deep_space_avx2, "avx2"});
#endif
  out.push_back({near_earth_all, deep_space_all, "baseline"});
  return out;
}

const Chosen& chosen() {
  static const Chosen c = available().front();
  return c;
}

// Beyond this many minutes from epoch (19 years) the angles the kernel takes the sine of may pass
// detail::kReducibleAngle (mean motion 0.07 rad/min times 2.3e7 minutes); such times go through the
// scalar propagator, which falls back to libm there.
constexpr double kKernelMaxMinutes = 1e7;

void run(const Chosen& c, const Sgp4& sat, std::span<const double> tsince, std::span<Propagation> out) {
  const bool in_range = std::all_of(tsince.begin(), tsince.end(),
                                    [](double t) { return std::fabs(t) <= kKernelMaxMinutes; });
  if (!in_range) {
    for (std::size_t j = 0; j < tsince.size(); ++j) out[j] = sat.propagate_minutes(tsince[j]);
    return;
  }
  if (const auto terms = sat.near_earth_terms()) {
    c.kernel(*terms, tsince.data(), tsince.size(), out.data());
  } else if (sat.deep_space() && sat.init_error() == Sgp4Error::none) {
    c.deep(sat, tsince.data(), tsince.size(), out.data());
  } else {
    for (std::size_t j = 0; j < tsince.size(); ++j) out[j] = sat.propagate_minutes(tsince[j]);
  }
}

}  // namespace

const char* batch_kernel_isa() { return chosen().isa; }

std::vector<const char*> batch_kernels_available() {
  std::vector<const char*> names;
  for (const Chosen& c : available()) names.push_back(c.isa);
  return names;
}

void propagate_batch(const Sgp4& sat, std::span<const double> tsince, std::span<Propagation> out) {
  run(chosen(), sat, tsince, out);
}

bool propagate_batch_with(const char* isa, const Sgp4& sat, std::span<const double> tsince,
                          std::span<Propagation> out) {
  for (const Chosen& c : available())
    if (std::string_view(c.isa) == isa) {
      run(c, sat, tsince, out);
      return true;
    }
  return false;
}

void Sgp4Batch::propagate(std::span<const UtcTime> times, std::span<Propagation> out) const {
  std::vector<double> tsince(times.size());
  for (std::size_t s = 0; s < sets_.size(); ++s) {
    const Sgp4& sat = sets_[s];
    for (std::size_t j = 0; j < times.size(); ++j) tsince[j] = minutes_between(sat.epoch(), times[j]);
    propagate_batch(sat, tsince, out.subspan(s * times.size(), times.size()));
  }
}

}  // namespace tb::orbit
