#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "rotator/adc_model.h"
#include "rotator/sky_calibration.h"
#include "rotator/sun_noise.h"
#include "rotator/sun_scan.h"

using namespace tb::rotator;
using tb::orbit::Body;
using tb::orbit::from_civil;

namespace {

tb::orbit::LookAngles sky_at(double az, double el) {
  tb::orbit::LookAngles la;
  la.az_deg = az;
  la.el_deg = el;
  return la;
}

// A beam of -3 dB full width beam_deg, peak_db over a cold sky of cold_db, seen by an antenna whose
// reading is off by (az_err, el_err) (reading = true + error), on a body at `body`; the level a
// receiver reports when the rotator reads `reading`, with a fixed +-0.1 dB ripple.
struct Beam {
  double beam_deg, peak_over_cold_db, cold_db, az_err, el_err;
  double level(AzEl reading, AzEl body, int i) const {
    const double kD = std::numbers::pi / 180.0;
    const double true_az = reading.az - az_err, true_el = reading.el - el_err;
    const double dx = std::remainder(true_az - body.az, 360.0) * std::cos(body.el * kD);
    const double dy = true_el - body.el;
    const double cold = std::pow(10.0, cold_db / 10.0);
    const double peak = cold * (std::pow(10.0, peak_over_cold_db / 10.0) - 1.0);
    const double p = cold + peak * std::exp(-4.0 * std::numbers::ln2 * (dx * dx + dy * dy) / (beam_deg * beam_deg));
    const double ripple = 0.1 * std::sin(1.7 * i + 0.3);  // deterministic "noise"
    return 10.0 * std::log10(p) + ripple;
  }
};

// Runs a scan of `shape` over a Sun moving 0.25 deg/min in azimuth (one point every 20 s).
std::vector<ScanSample> run_scan(const Beam& beam, ScanShape shape, double span, double step, AzEl sun0) {
  const ScanPattern plan = scan_pattern(shape, span, step);
  REQUIRE(plan.ok());
  std::vector<ScanSample> samples;
  int i = 0;
  for (const ScanPoint& p : plan.points) {
    const AzEl sun{sun0.az + 0.25 * i / 3.0, sun0.el + 0.05 * i / 3.0};
    const AzEl target = scan_target(sun, p);
    samples.push_back({target, sun, beam.level(target, sun, i)});
    ++i;
  }
  return samples;
}

}  // namespace

TEST_CASE("This is the Sun: the correction makes the reading equal the computed position") {
  const auto t = from_civil(2026, 3, 20, 11, 0);
  const BodyFix fix = body_fix(Body::sun, t, {182.0, 44.0}, sky_at(180.0, 45.0));
  REQUIRE(fix.ok());
  CHECK(fix.correction.az_deg == doctest::Approx(-2.0));
  CHECK(fix.correction.el_deg == doctest::Approx(1.0));
  CHECK(fix.time == t);
  CHECK(fix.computed.az == 180.0);
  // Across north: reading 359.5, Moon at 0.5 -> +1.0.
  const BodyFix north = body_fix(Body::moon, t, {359.5, 30.0}, sky_at(0.5, 30.0));
  REQUIRE(north.ok());
  CHECK(north.correction.az_deg == doctest::Approx(1.0));
  CHECK(body_fix(Body::sun, t, {0.0, 30.0}, sky_at(180.0, 30.0)).correction.az_deg == 180.0);
}

TEST_CASE("This is the Sun: refusals name what is wrong") {
  const auto t = from_civil(2026, 3, 20, 11, 0);
  const BodyFix low = body_fix(Body::moon, t, {90.0, 1.0}, sky_at(90.0, 1.2));
  CHECK_FALSE(low.ok());
  CHECK(low.error == "the MOON is at 1.2 deg elevation, below the 2 deg a calibration needs");
  const BodyFix flipped = body_fix(Body::sun, t, {10.0, 120.0}, sky_at(190.0, 60.0));
  CHECK_FALSE(flipped.ok());
  CHECK(flipped.error.find("outside 0..90") != std::string::npos);
  CHECK_FALSE(body_fix(Body::sun, t, {NAN, 10.0}, sky_at(190.0, 60.0)).ok());
}

TEST_CASE("This is the Sun: the correction as skew, applied and undone") {
  // Factory spans: azimuth 1023 counts for 360 deg (2.841667 counts/deg), elevation 511 counts for
  // 90 deg (5.677778 counts/deg). -2.0 deg az -> round(-5.683) = -6 counts, residual
  // -2.0 + 6 / 2.841667 = +0.111437 deg; +1.0 deg el -> round(5.678) = 6 counts, residual -0.056751.
  RotatorConfig c;
  c.az_skew = 4;
  c.el_skew = -3;
  const SkewChange s = skew_for(c, {-2.0, 1.0});
  REQUIRE(s.ok());
  CHECK(s.az_skew_before == 4);
  CHECK(s.el_skew_before == -3);
  CHECK(s.az_skew_after == -2);
  CHECK(s.el_skew_after == 3);
  CHECK(s.az_residual_deg == doctest::Approx(0.111437).epsilon(1e-5));
  CHECK(s.el_residual_deg == doctest::Approx(-0.056751).epsilon(1e-5));
  const RotatorConfig applied = s.apply(c);
  CHECK(applied.az_skew == -2);
  CHECK(applied.el_skew == 3);
  const RotatorConfig undone = s.undo(applied);
  CHECK(undone.az_skew == 4);
  CHECK(undone.el_skew == -3);

  // Through the ADC model: a rotator reading 182.0/44.0 at these raw counts reads the computed
  // 180.0/45.0 afterwards, less the residual the whole counts could not hold (under half a count).
  const AdcModel before(c, tb::station::RotorStart::north);
  const double raw_az = before.raw(Axis::az, before.counts_from_az_travel(182.0));
  const double raw_el = before.raw(Axis::el, before.counts_from_el(44.0));
  const SkewChange fix = skew_for(c, body_fix(Body::sun, {}, {182.0, 44.0}, sky_at(180.0, 45.0)).correction);
  const AdcModel after(fix.apply(c), tb::station::RotorStart::north);
  CHECK(std::abs(after.az_deg_from_raw(raw_az) - (180.0 - fix.az_residual_deg)) < 1e-9);
  CHECK(std::abs(after.el_deg_from_raw(raw_el) - (45.0 - fix.el_residual_deg)) < 1e-9);
}

TEST_CASE("This is the Sun: a skew that would leave its range is refused") {
  RotatorConfig c;
  c.az_skew = 500;
  const SkewChange s = skew_for(c, {30.0, 0.0});
  CHECK_FALSE(s.ok());
  CHECK(s.error == "azimuth skew 585 counts (+30.00 deg) would leave -512..512");
  CHECK(s.apply(c).az_skew == 500);
  CHECK_FALSE(skew_for(c, {0.0, -100.0}).ok());
}

TEST_CASE("Scan patterns: cross and grid") {
  const ScanPattern cross = scan_pattern(ScanShape::cross, 4.0, 1.0);
  REQUIRE(cross.ok());
  CHECK(cross.points.size() == 17);
  CHECK(cross.points.front().x_deg == -4.0);
  CHECK(cross.points.back().y_deg == 4.0);
  const ScanPattern grid = scan_pattern(ScanShape::grid, 4.0, 1.0);
  REQUIRE(grid.ok());
  CHECK(grid.points.size() == 81);
  // Back and forth: the second row starts where the first ended.
  CHECK(grid.points[8].x_deg == 4.0);
  CHECK(grid.points[9].x_deg == 4.0);
  CHECK(grid.points[9].y_deg == -3.0);
  CHECK(scan_pattern(ScanShape::grid, 4.5, 1.0).points.size() == 81);  // ends at the last whole step
  CHECK(scan_pattern(ScanShape::grid, 4.0, 0.0).error == "the scan's span and step must be positive numbers of degrees");
  CHECK_FALSE(scan_pattern(ScanShape::cross, 21.0, 1.0).ok());
  CHECK_FALSE(scan_pattern(ScanShape::cross, 1.0, 2.0).ok());
}

TEST_CASE("Scan target: cross-elevation offsets widen with elevation") {
  const AzEl t = scan_target({100.0, 60.0}, {1.0, -0.5});
  CHECK(t.az == doctest::Approx(102.0));  // 1 / cos 60
  CHECK(t.el == doctest::Approx(59.5));
  CHECK(scan_target({359.0, 0.0}, {2.0, 0.0}).az == doctest::Approx(1.0));
}

TEST_CASE("Levels average as power") {
  const double levels[] = {-10.0, -20.0};
  CHECK(average_level_db(levels) == doctest::Approx(-12.596373));  // 10 log10((0.1 + 0.01) / 2)
  CHECK(std::isnan(average_level_db({})));
}

TEST_CASE("Sun-noise scan finds a +2.0 az / -1.0 el rotator offset within a tenth of the beam") {
  const Beam beam{8.0, 6.0, -60.0, 2.0, -1.0};
  for (ScanShape shape : {ScanShape::grid, ScanShape::cross}) {
    CAPTURE(static_cast<int>(shape));
    const auto samples = run_scan(beam, shape, 16.0, 2.0, {150.0, 35.0});
    const ScanFit fit = fit_scan(samples);
    REQUIRE(fit.ok());
    // The rotator reads 2.0 deg too much in azimuth and 1.0 too little in elevation: the correction
    // (true - reading) is -2.0 / +1.0.
    CHECK(std::abs(fit.correction.az_deg - -2.0) < 0.8);
    CHECK(std::abs(fit.correction.el_deg - 1.0) < 0.8);
    CHECK(std::abs(fit.correction.az_deg - -2.0) < 0.1);   // well within: the ripple is small
    CHECK(std::abs(fit.correction.el_deg - 1.0) < 0.1);
    CHECK(std::abs(fit.beamwidth_x_deg - 8.0) < 0.4);
    CHECK(std::abs(fit.beamwidth_y_deg - 8.0) < 0.4);
    CHECK(std::abs(fit.peak_over_cold_db - 6.0) < 0.3);
    CHECK(std::abs(fit.cold_sky_db - -60.0) < 0.2);
    CHECK(fit.rms_db < 0.15);
    MESSAGE("correction ", fit.correction.az_deg, " / ", fit.correction.el_deg, ", beam ",
            fit.beamwidth_x_deg, " x ", fit.beamwidth_y_deg, ", Y ", fit.peak_over_cold_db, " dB, ",
            fit.points_used, " points");
  }
}

TEST_CASE("Sun-noise scan: a narrow dish beam and a small offset") {
  // 0.5 deg beam (a 2.4 m dish at 17 GHz), offset 0.1 / -0.05, scan +-1 deg in 0.125 deg steps.
  const Beam beam{0.5, 10.0, -70.0, 0.1, -0.05};
  const ScanFit fit = fit_scan(run_scan(beam, ScanShape::grid, 1.0, 0.125, {200.0, 20.0}));
  REQUIRE(fit.ok());
  CHECK(std::abs(fit.correction.az_deg - -0.1) < 0.05);
  CHECK(std::abs(fit.correction.el_deg - 0.05) < 0.05);
  CHECK(std::abs(fit.beamwidth_y_deg - 0.5) < 0.05);
}

TEST_CASE("Sun-noise scan: refusals") {
  const Beam flat{8.0, 0.0, -60.0, 0.0, 0.0};
  const ScanFit none = fit_scan(run_scan(flat, ScanShape::grid, 8.0, 2.0, {150.0, 35.0}));
  CHECK_FALSE(none.ok());
  CHECK(none.error.find("no peak") != std::string::npos);
  // The antenna 12 deg off: the scan of +-8 deg sees only the beam's flank.
  const Beam far{4.0, 6.0, -60.0, 12.0, 0.0};
  const ScanFit outside = fit_scan(run_scan(far, ScanShape::grid, 8.0, 2.0, {150.0, 35.0}));
  CHECK_FALSE(outside.ok());
  CHECK(fit_scan({}).error == "0 points are too few for a fit (at least 6)");
}

TEST_CASE("Expected Sun noise: i8cvs's example") {
  // i8cvs (amsat-bb, January 2002): 42 SFU, 17.14 dBic, 435 MHz, Tsys 142 K -> Ta ~ 298 K, Y ~ 4.9 dB.
  // By hand: G = 10^1.714 = 51.76, lambda = 0.68918 m, Ta = 42 x 51.76 x 0.47497 / 3.46995 = 297.57 K,
  // Y = 10 log10(439.57 / 142) = 4.907 dB.
  const double ta = sun_antenna_temperature_k(42.0, 17.14, 435e6);
  CHECK(ta == doctest::Approx(297.57).epsilon(1e-4));
  CHECK(sun_noise_y_db(ta, 142.0) == doctest::Approx(4.907).epsilon(1e-3));
  // Tsys of a 1 dB noise figure on 20 K of sky: (1.2589 - 1) x 290 + 20 = 95.09 K.
  CHECK(system_temperature_k(1.0, 20.0) == doctest::Approx(95.088).epsilon(1e-4));
}

TEST_CASE("Solar flux between the RSTN frequencies") {
  const FluxPoint day[] = {{245, 20}, {410, 35}, {610, 60}, {1415, 80}, {2695, 120}, {4995, 150}, {8800, 250}, {15400, 500}};
  // 1296 MHz between 610 (60) and 1415 (80): 60 x (80/60)^(ln(1296/610)/ln(1415/610)) = 77.633 SFU.
  CHECK(solar_flux_at(day, 1296.0).sfu == doctest::Approx(77.633).epsilon(1e-4));
  CHECK(solar_flux_at(day, 2695.0).sfu == 120.0);
  CHECK(solar_flux_at(day, 245.0).sfu == 20.0);
  CHECK(solar_flux_at(day, 144.0).error == "144 MHz is outside the measured 245..15400 MHz");
  const FluxPoint two[] = {{1415, 100}, {2695, 150}};
  CHECK(solar_flux_at(two, 2000.0).sfu == doctest::Approx(124.329).epsilon(1e-5));
  const FluxPoint unsorted[] = {{2695, 150}, {1415, 100}};
  CHECK(solar_flux_at(unsorted, 2000.0).error == "flux point 2 (1415 MHz) does not follow 2695 MHz in rising frequency");
  const FluxPoint bad[] = {{1415, 0}};
  CHECK_FALSE(solar_flux_at(bad, 1415.0).ok());
  CHECK_FALSE(solar_flux_at({}, 1415.0).ok());
}

TEST_CASE("Sky offsets: the correction added to the stored offsets, recorded, and undone") {
  RotatorConfig c;
  c.az_offset_deg = 0.5;
  const OffsetChange ch = offsets_for(c, {-2.0, 1.0}, "sun", "2026-03-20T09:00:00Z");
  REQUIRE(ch.ok());
  CHECK(ch.after.az_offset_deg == doctest::Approx(-1.5).epsilon(1e-12));
  CHECK(ch.after.el_offset_deg == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(ch.after.sky.source == "sun");
  CHECK(ch.after.sky.time == "2026-03-20T09:00:00Z");
  CHECK(ch.after.sky.previous_az_offset_deg == 0.5);
  CHECK(ch.after.sky.previous_source.empty());
  // Undo: back to c exactly, the undone kept as "previous" (a second undo redoes).
  const OffsetChange back = undo_offsets(ch.after);
  REQUIRE(back.ok());
  CHECK(back.after.az_offset_deg == 0.5);
  CHECK(back.after.el_offset_deg == 0.0);
  CHECK(back.after.sky.source.empty());
  CHECK(back.after.sky.previous_source == "sun");
  CHECK(undo_offsets(back.after).after == ch.after);
  // Nothing recorded: nothing to undo; an offset beyond 45 deg is refused, nothing changed.
  CHECK(undo_offsets(RotatorConfig{}).error == "no sky calibration to undo");
  const OffsetChange far = offsets_for(c, {0.0, -46.0}, "moon", "2026-03-20T09:00:00Z");
  CHECK(far.error.find("the elevation offset would be -46.00 deg, beyond 45 either way") == 0);
  CHECK(far.after == c);
}

TEST_CASE("Sky offsets: the reading moves by the offset exactly, the skew's whole counts beside it") {
  RotatorConfig c;
  const AdcModel plain(c, tb::station::RotorStart::north);
  c.az_offset_deg = -2.0;
  c.el_offset_deg = 1.0;
  c.az_skew = 3;
  const AdcModel off(c, tb::station::RotorStart::north);
  for (const double raw : {100.0, 511.0, 900.0}) {
    CAPTURE(raw);
    const double skew_deg = 3 * plain.deg_per_count(Axis::az);
    CHECK(off.az_deg_from_raw(raw) == doctest::Approx(plain.az_deg_from_raw(raw) - 2.0 + skew_deg).epsilon(1e-12));
    CHECK(off.el_from_counts(off.corrected(Axis::el, raw / 2)) ==
          doctest::Approx(plain.el_from_counts(plain.corrected(Axis::el, raw / 2)) + 1.0).epsilon(1e-12));
    CHECK(off.raw(Axis::az, off.corrected(Axis::az, raw)) == doctest::Approx(raw).epsilon(1e-12));
  }
  CHECK(validate(c).empty());
  c.el_offset_deg = 45.5;
  REQUIRE_FALSE(validate(c).empty());
  CHECK(validate(c).front() == "elevation offset 45.5 deg: expected -45 to 45");
}
