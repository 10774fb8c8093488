// The propagator's own arithmetic (orbit/sgp4_common.h) against the C library it stands in for:
// fmod(x, 2pi) exactly, and sine and cosine within a few units in the last place.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "orbit/constants.h"
#include "orbit/sgp4_common.h"

using namespace tb::orbit;

TEST_CASE("fmod_two_pi is fmod(x, 2pi) bit for bit") {
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> exponent(-3.0, 9.0);  // |x| from 1e-3 to 1e9 rad
  std::uniform_int_distribution<int> sign(0, 1);
  long compared = 0;
  auto check = [&](double x) {
    const double want = std::fmod(x, kTwoPi);
    const double got = detail::fmod_two_pi(x);
    CAPTURE(x);
    REQUIRE(std::signbit(got) == std::signbit(want));
    REQUIRE(got == want);
    ++compared;
  };
  for (int i = 0; i < 2000000; ++i) check((sign(rng) ? -1.0 : 1.0) * std::pow(10.0, exponent(rng)));
  // Multiples of 2pi and their neighbours, where x / 2pi rounds across an integer.
  for (double k = 1.0; k < 5e7; k = k * 1.37 + 1.0) {
    const double m = std::floor(k) * kTwoPi;
    for (double x : {m, std::nextafter(m, 0.0), std::nextafter(m, 1e300), -m, -std::nextafter(m, 0.0)}) check(x);
  }
  for (double x : {kTwoPi, -kTwoPi, std::nextafter(kTwoPi, 0.0), 0.0, -0.0, 1e300, -1e300}) check(x);
  CHECK(std::isnan(detail::fmod_two_pi(std::nan(""))));
  CHECK(std::isnan(detail::fmod_two_pi(INFINITY)));
  MESSAGE(compared << " values compared with fmod");
}

TEST_CASE("poly_sin_cos agrees with libm within 2^-51 (absolute) up to kReducibleAngle") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-8.0, std::log10(detail::kReducibleAngle));
  double worst = 0.0;  // in units of 2^-52 (ulp of 1)
  for (int i = 0; i < 1000000; ++i) {
    const double x = (i % 2 ? -1.0 : 1.0) * std::pow(10.0, exponent(rng));
    const detail::SinCos sc = detail::poly_sin_cos(x);
    worst = std::max({worst, std::fabs(sc.s - std::sin(x)) / 0x1p-52, std::fabs(sc.c - std::cos(x)) / 0x1p-52});
  }
  MESSAGE("worst |poly - libm| " << worst << " x 2^-52");
  CHECK(worst <= 2.0);
}
