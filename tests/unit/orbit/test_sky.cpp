#include <doctest/doctest.h>

#include <cmath>
#include <memory>

#include "orbit/horizon_mask.h"
#include "orbit/moon.h"
#include "orbit/sky.h"

using namespace tb::orbit;

namespace {

// Smallest difference between two azimuths, degrees.
double sky_az_gap(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

struct SkyRef {
  Observer o;
  UtcTime t;
  double sun_az, sun_el, moon_az, moon_el, moon_km;  // moon_km: topocentric range
};

// From tests/integration/orbit_ref/sky_reference_values.py: PyEphem 4.1.4 (Debian python3-ephem),
// topocentric az/el of the centres with refraction off, and the Moon's distance from the station
// (PyEphem's earth_distance of a body computed for an observer is topocentric).
const SkyRef kSkyRefs[] = {
    {{32.259, -110.778, 842.0}, from_civil(2026, 5, 21, 18, 0), 119.0102, 68.5548, 71.1112, 6.8839, 370746.5},
    {{32.259, -110.778, 842.0}, from_civil(2026, 12, 21, 12, 0), 100.9499, -28.7790, 300.1638, -3.5841, 364727.1},
    {{32.259, -110.778, 842.0}, from_civil(2026, 3, 20, 9, 0), 37.6910, -51.5358, 11.1834, -48.0662, 374014.9},
    {{32.259, -110.778, 842.0}, from_civil(2024, 4, 8, 18, 20), 145.1196, 61.1060, 145.0438, 60.9637, 354213.4},
    {{32.259, -110.778, 842.0}, from_civil(2031, 7, 4, 3, 30), 306.1655, -10.9130, 131.1910, 18.3629, 355478.3},
    {{48.1458, 11.625, 520.0}, from_civil(2026, 5, 21, 18, 0), 292.6590, 7.0749, 230.0165, 52.9421, 366449.2},
    {{48.1458, 11.625, 520.0}, from_civil(2026, 12, 21, 12, 0), 191.6486, 17.5944, 46.3406, -5.5239, 364946.9},
    {{48.1458, 11.625, 520.0}, from_civil(2026, 3, 20, 9, 0), 136.5630, 32.9341, 115.5078, 32.4494, 365822.8},
    {{48.1458, 11.625, 520.0}, from_civil(2024, 4, 8, 18, 20), 287.1848, -4.9533, 287.5013, -5.8041, 360400.7},
    {{48.1458, 11.625, 520.0}, from_civil(2031, 7, 4, 3, 30), 55.1963, 0.6261, 244.1208, -5.5195, 358096.1},
    {{-33.9249, 18.4241, 10.0}, from_civil(2026, 5, 21, 18, 0), 277.4044, -26.7740, 322.2844, 25.1978, 368786.6},
    {{-33.9249, 18.4241, 10.0}, from_civil(2026, 12, 21, 12, 0), 297.4437, 70.4259, 85.1409, -38.9746, 368347.1},
    {{-33.9249, 18.4241, 10.0}, from_civil(2026, 3, 20, 9, 0), 44.2255, 46.9287, 51.2417, 29.3192, 366113.3},
    {{-33.9249, 18.4241, 10.0}, from_civil(2024, 4, 8, 18, 20), 263.3311, -23.2887, 263.5333, -24.5027, 362404.0},
    {{-33.9249, 18.4241, 10.0}, from_civil(2031, 7, 4, 3, 30), 80.4499, -28.7311, 257.8783, 18.3290, 355498.2},
    {{69.6496, 18.956, 100.0}, from_civil(2026, 5, 21, 18, 0), 295.3749, 12.3963, 223.3554, 35.0476, 367861.3},
    {{69.6496, 18.956, 100.0}, from_civil(2026, 12, 21, 12, 0), 197.8275, -4.1332, 53.6909, 11.2839, 363084.9},
    {{69.6496, 18.956, 100.0}, from_civil(2026, 3, 20, 9, 0), 150.5499, 17.8010, 132.9624, 23.3157, 366713.8},
    {{69.6496, 18.956, 100.0}, from_civil(2024, 4, 8, 18, 20), 294.6634, -0.7957, 294.8993, -1.5470, 359927.6},
    {{69.6496, 18.956, 100.0}, from_civil(2031, 7, 4, 3, 30), 63.8739, 14.8920, 253.9056, -16.8276, 359334.6},
};

}  // namespace

TEST_CASE("Sun and Moon topocentric az/el against PyEphem: Sun 0.01 deg, Moon 0.02 deg") {
  double worst[5] = {0, 0, 0, 0, 0};
  for (const SkyRef& r : kSkyRefs) {
    const LookAngles sun = body_look(Body::sun, r.o, r.t);
    const LookAngles moon = body_look(Body::moon, r.o, r.t);
    const double d[5] = {sky_az_gap(sun.az_deg, r.sun_az), std::abs(sun.el_deg - r.sun_el),
                         sky_az_gap(moon.az_deg, r.moon_az), std::abs(moon.el_deg - r.moon_el),
                         std::abs(moon.range_km - r.moon_km)};
    CAPTURE(r.o.lat_deg);
    CAPTURE(format_iso8601(r.t));
    CHECK(d[0] < 0.01);
    CHECK(d[1] < 0.01);
    CHECK(d[2] < 0.02);
    CHECK(d[3] < 0.02);
    CHECK(d[4] < 10.0);
    for (int i = 0; i < 5; ++i) worst[i] = std::max(worst[i], d[i]);
  }
  MESSAGE("worst: sun az ", worst[0], " el ", worst[1], " moon az ", worst[2], " el ", worst[3],
          " range km ", worst[4]);
}

TEST_CASE("Moon: parallax lowers the topocentric Moon by up to about 1 deg") {
  // sky_reference_values.py parallax(): PyEphem's geocentric elevation (the geocentric direction
  // against the station's horizon) and topocentric elevation, degrees.
  struct ParallaxRef {
    Observer o;
    UtcTime t;
    double geo_el, topo_el;
  };
  const ParallaxRef refs[] = {
      {{32.259, -110.778, 842.0}, from_civil(2026, 5, 21, 18, 0), 7.8597, 6.8839},
      {{32.259, -110.778, 842.0}, from_civil(2026, 12, 21, 12, 0), -2.5840, -3.5841},
      {{48.1458, 11.625, 520.0}, from_civil(2026, 5, 21, 18, 0), 53.5321, 52.9421},
      {{48.1458, 11.625, 520.0}, from_civil(2026, 3, 20, 9, 0), 33.2823, 32.4494},
  };
  constexpr double kD = 3.141592653589793 / 180.0;
  for (const ParallaxRef& r : refs) {
    const Vec3 m = teme_to_ecef(moon_state_teme(r.t), r.t).r_km;
    const Vec3 up = {std::cos(r.o.lat_deg * kD) * std::cos(r.o.lon_deg * kD),
                     std::cos(r.o.lat_deg * kD) * std::sin(r.o.lon_deg * kD), std::sin(r.o.lat_deg * kD)};
    const double len = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    const double geo_el = std::asin((m[0] * up[0] + m[1] * up[1] + m[2] * up[2]) / len) / kD;
    const double topo_el = body_look(Body::moon, r.o, r.t).el_deg;
    CAPTURE(r.geo_el);
    CHECK(std::abs(geo_el - r.geo_el) < 0.02);
    CHECK(std::abs(topo_el - r.topo_el) < 0.02);
    CHECK(std::abs((geo_el - topo_el) - (r.geo_el - r.topo_el)) < 0.005);
  }
}

TEST_CASE("Sun and Moon: range rate is the derivative of the range") {
  const Observer munich{48.1458, 11.625, 520.0};
  for (Body b : {Body::sun, Body::moon}) {
    const UtcTime t = from_civil(2026, 3, 20, 9, 0);
    const LookAngles now = body_look(b, munich, t);
    const double before = body_look(b, munich, add_seconds(t, -1.0)).range_km;
    const double after = body_look(b, munich, add_seconds(t, 1.0)).range_km;
    CHECK(std::abs(now.range_rate_km_s - (after - before) / 2.0) < 1e-4);
  }
  // The Moon rising in the east at Tucson (az 71, el 6.9): the Earth's turn carries the station
  // towards it, about 0.39 km/s at that latitude, less the Moon's own recession.
  const LookAngles rising = body_look(Body::moon, {32.259, -110.778, 842.0}, from_civil(2026, 5, 21, 18, 0));
  CHECK(rising.range_rate_km_s < -0.25);
  CHECK(rising.range_rate_km_s > -0.45);
}

TEST_CASE("EME self-echo Doppler is -2 f rdot / c") {
  // Hand-computed: 2 * 1296e6 * 0.3 / 299792.458 = 2593.794 Hz; 2 * 144.1e6 * 0.4 / c = 384.533 Hz.
  CHECK(std::abs(eme_echo_doppler_hz(1296e6, 0.3) - -2593.7944) < 1e-3);
  CHECK(std::abs(eme_echo_doppler_hz(144.1e6, -0.4) - 384.5327) < 1e-3);
  CHECK(eme_echo_doppler_hz(10368e6, 0.0) == 0.0);
}

TEST_CASE("Refraction: Saemundsson against PyEphem, Bennett its inverse") {
  // PyEphem 4.1.4 at 1010 hPa, 10 C (sky_reference_values.py): the Sun at these true elevations is
  // lifted by these amounts, degrees. PyEphem's libastro has its own refraction formula: the two
  // agree to 0.003 deg (0.2') from 2.5 deg up.
  const double refs[][2] = {{7.0749, 0.1194}, {2.5577, 0.2484}, {16.6077, 0.0539}, {36.4819, 0.0218}};
  for (const auto& r : refs) {
    CAPTURE(r[0]);
    CHECK(std::abs(refraction_deg(r[0]) - r[1]) < 0.004);
  }
  // Meeus ch. 16: Saemundsson's formula is consistent with Bennett's to about 4".
  for (double h : {0.0, 0.5, 2.0, 10.0, 45.0, 89.0}) {
    const double lift = refraction_deg(h);
    CHECK(std::abs(refraction_from_apparent_deg(h + lift) - lift) < 4.5 / 3600.0);
  }
  // Meeus: Bennett's refraction at the apparent horizon is 34.5' (1/tan(7.31/4.4 deg) arcmin).
  CHECK(std::abs(refraction_from_apparent_deg(0.0) * 60.0 - 34.48) < 0.01);
  // Thinner, warmer air bends less: the lift scales with P / 1010 and 283 / (273 + T).
  CHECK(std::abs(refraction_deg(5.0, 505.0, 10.0) - refraction_deg(5.0) / 2.0) < 1e-12);
  CHECK(refraction_deg(-3.0) == refraction_deg(-1.0));
}

TEST_CASE("Body names") {
  CHECK(parse_body("SUN") == Body::sun);
  CHECK(parse_body("moon") == Body::moon);
  CHECK(parse_body("Moon") == Body::moon);
  CHECK_FALSE(parse_body("ISS").has_value());
  CHECK_FALSE(parse_body(" SUN").has_value());
  CHECK(body_name(Body::sun) == "SUN");
  CHECK(body_name(Body::moon) == "MOON");
}

TEST_CASE("Sun and Moon: rise, culmination and set against PyEphem at a -2 deg horizon") {
  // sky_reference_values.py events(): PyEphem next_rising / next_transit / next_setting of the
  // centre, horizon -2 deg, pressure 0, from 2026-03-20 00:00 UTC.
  struct Events {
    Observer o;
    Body b;
    UtcTime rise, transit, set;
    double max_el;
  };
  const Events refs[] = {
      {{32.259, -110.778, 842.0}, Body::sun, from_civil(2026, 3, 20, 13, 21, 8), from_civil(2026, 3, 20, 19, 30, 27),
       from_civil(2026, 3, 21, 1, 40, 17), 57.8179},
      {{32.259, -110.778, 842.0}, Body::moon, from_civil(2026, 3, 20, 14, 6, 22), from_civil(2026, 3, 20, 20, 53, 27),
       from_civil(2026, 3, 21, 3, 50, 44), 70.2479},
      {{48.1458, 11.625, 520.0}, Body::sun, from_civil(2026, 3, 20, 5, 9, 45), from_civil(2026, 3, 20, 11, 20, 57),
       from_civil(2026, 3, 20, 17, 33, 3), 41.7962},
      {{48.1458, 11.625, 520.0}, Body::moon, from_civil(2026, 3, 20, 5, 26, 55), from_civil(2026, 3, 20, 12, 26, 41),
       from_civil(2026, 3, 20, 19, 45, 29), 51.8690},
  };
  for (const Events& r : refs) {
    CAPTURE(body_name(r.b));
    CAPTURE(r.o.lat_deg);
    const auto passes = find_body_passes(r.b, r.o, from_civil(2026, 3, 20), from_civil(2026, 3, 22));
    REQUIRE(passes.size() >= 2);
    const Pass* p = passes[0].up_at_start ? &passes[1] : &passes[0];
    CHECK_FALSE(p->up_at_start);
    // 0.02 deg of elevation is 5 s at these rates; PyEphem rounds to the second.
    CHECK(std::abs(minutes_between(r.rise, p->aos)) * 60.0 < 6.0);
    CHECK(std::abs(minutes_between(r.set, p->los)) * 60.0 < 6.0);
    // PyEphem's transit is the meridian crossing; the highest point is within a few minutes of it
    // (the Moon's declination changes meanwhile) and its elevation the same to 0.02 deg.
    CHECK(std::abs(minutes_between(r.transit, p->tca)) < 5.0);
    CHECK(std::abs(p->max_el_deg - r.max_el) < 0.02);
    CHECK(sky_az_gap(p->tca_az_deg, 180.0) < 2.0);
  }
}

TEST_CASE("Body passes: a window starting with the body up, and one ending with it up") {
  const Observer munich{48.1458, 11.625, 520.0};
  const auto passes = find_body_passes(Body::sun, munich, from_civil(2026, 3, 20, 9, 0),
                                       from_civil(2026, 3, 22, 9, 0));
  REQUIRE(passes.size() == 3);
  CHECK(passes[0].up_at_start);
  CHECK(passes[0].aos == from_civil(2026, 3, 20, 9, 0));
  CHECK_FALSE(passes[1].up_at_start);
  CHECK_FALSE(passes[1].up_at_end);
  CHECK(passes[2].up_at_end);
  CHECK(passes[2].los == from_civil(2026, 3, 22, 9, 0));
  // A minimum culmination drops the passes that stay lower.
  PassOptions high;
  high.min_max_elevation_deg = 60.0;
  CHECK(find_body_passes(Body::sun, munich, from_civil(2026, 3, 20), from_civil(2026, 3, 23), high).empty());
  // An empty window has none.
  CHECK(find_body_passes(Body::moon, munich, from_civil(2026, 3, 20), from_civil(2026, 3, 20)).empty());
}

TEST_CASE("Body passes: the midnight Sun at Tromso is one pass through the window") {
  const Observer tromso{69.6496, 18.956, 100.0};
  const auto passes = find_body_passes(Body::sun, tromso, from_civil(2026, 6, 20), from_civil(2026, 6, 23));
  REQUIRE(passes.size() == 1);
  CHECK(passes[0].up_at_start);
  CHECK(passes[0].up_at_end);
  // 90 - 69.65 + 23.44 = 43.8 deg at the highest.
  CHECK(std::abs(passes[0].max_el_deg - 43.79) < 0.1);
}

TEST_CASE("Body passes: a stretch above the horizon shorter than the 10-minute grid is found") {
  // The Moon's culmination at Munich with the horizon put a thousandth of a degree under it: a
  // pass of a few minutes, between two grid samples, found by refining the local maximum.
  const Observer munich{48.1458, 11.625, 520.0};
  const UtcTime from = from_civil(2026, 3, 20, 6, 0), to = from_civil(2026, 3, 20, 19, 0);
  const auto full = find_body_passes(Body::moon, munich, from, to);
  REQUIRE(full.size() == 1);
  PassOptions grazing;
  grazing.horizon_deg = full[0].max_el_deg - 0.001;
  const auto brief = find_body_passes(Body::moon, munich, from, to, grazing);
  REQUIRE(brief.size() == 1);
  const double minutes = minutes_between(brief[0].aos, brief[0].los);
  CAPTURE(minutes);
  CHECK(minutes > 0.5);
  CHECK(minutes < 10.0);
  CHECK(std::abs(brief[0].max_el_deg - full[0].max_el_deg) < 1e-5);
  CHECK(std::abs(minutes_between(brief[0].tca, full[0].tca)) < 0.1);
  // A thousandth of a degree above the maximum: nothing.
  grazing.horizon_deg = full[0].max_el_deg + 0.001;
  CHECK(find_body_passes(Body::moon, munich, from, to, grazing).empty());
}

TEST_CASE("Body passes above a horizon mask: the Sun rises at the eastern step, sets at the western one") {
  // Munich, 2026-03-20: the Sun rises near azimuth 89 and sets near 271. A stepped mask, 15 deg from
  // 0 to 180 (a ridge in the east), 10 deg from 180 to 360. AOS and LOS are then where body_look
  // (against PyEphem above) gives 15 and 10 deg, and the culmination is the Sun's own highest point.
  const Observer munich{48.1458, 11.625, 520.0};
  PassOptions po;
  po.precision_s = 1.0;
  const auto read = read_horizon_mask("0 15 180 10 360");
  REQUIRE(read.mask);
  po.mask = std::make_shared<const HorizonMask>(*read.mask);
  const auto masked = find_body_passes(Body::sun, munich, from_civil(2026, 3, 20), from_civil(2026, 3, 21), po);
  const auto plain = find_body_passes(Body::sun, munich, from_civil(2026, 3, 20), from_civil(2026, 3, 21));
  REQUIRE(masked.size() == 1);
  REQUIRE(plain.size() == 1);
  const Pass& m = masked[0];
  CHECK(body_look(Body::sun, munich, m.aos).el_deg == doctest::Approx(15.0).epsilon(0.001));  // 1 s: 0.003 deg
  CHECK(body_look(Body::sun, munich, add_seconds(m.aos, -2.0)).el_deg < 15.0);
  CHECK(body_look(Body::sun, munich, m.los).el_deg == doctest::Approx(10.0).epsilon(0.001));
  CHECK(body_look(Body::sun, munich, add_seconds(m.los, 2.0)).el_deg < 10.0);
  CHECK(minutes_between(plain[0].aos, m.aos) > 60.0);  // about 1 h 50 min later than at -2 deg
  CHECK(minutes_between(m.los, plain[0].los) > 60.0);
  CHECK(std::abs(minutes_between(plain[0].tca, m.tca)) * 60.0 < 2.0);
  CHECK(m.max_el_deg == doctest::Approx(plain[0].max_el_deg).epsilon(1e-6));
}
