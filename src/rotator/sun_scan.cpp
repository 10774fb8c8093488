// The sun-noise scan's pattern and fit (rotator/sun_scan.h).
#include "rotator/sun_scan.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "util/format.h"

namespace tb::rotator {
namespace {

constexpr double kScanDegToRad = std::numbers::pi / 180.0;
constexpr double kFourLn2 = 4.0 * std::numbers::ln2;
constexpr double kUsedFraction = 0.1;   // points fitted: excess at least this share of the peak's

double to_power(double db) { return std::pow(10.0, db / 10.0); }
double to_db(double power) { return 10.0 * std::log10(power); }

// Solves the 5x5 system a x = b by Gaussian elimination with partial pivoting; false if singular.
using Matrix5 = std::array<std::array<double, 5>, 5>;
bool solve5(Matrix5 a, std::array<double, 5> b, std::array<double, 5>& x) {
  for (int col = 0; col < 5; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 5; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    if (!(std::abs(a[pivot][col]) > 1e-300)) return false;
    std::swap(a[col], a[pivot]);
    std::swap(b[col], b[pivot]);
    for (int r = col + 1; r < 5; ++r) {
      const double f = a[r][col] / a[col][col];
      for (int c = col; c < 5; ++c) a[r][c] -= f * a[col][c];
      b[r] -= f * b[col];
    }
  }
  for (int r = 4; r >= 0; --r) {
    double s = b[r];
    for (int c = r + 1; c < 5; ++c) s -= a[r][c] * x[c];
    x[r] = s / a[r][r];
  }
  return std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
}

struct Point {
  double x, y, power;
};

// Samples as sky offsets and linear power; the mean body elevation for the azimuth scale.
std::vector<Point> to_points(std::span<const ScanSample> samples, double& mean_el) {
  std::vector<Point> pts;
  mean_el = 0.0;
  for (const ScanSample& s : samples) {
    const double x = std::remainder(s.reading.az - s.body.az, 360.0) * std::cos(s.body.el * kScanDegToRad);
    pts.push_back({x, s.reading.el - s.body.el, to_power(s.level_db)});
    mean_el += s.body.el / static_cast<double>(samples.size());
  }
  return pts;
}

// Mean power of the lowest fifth of the points (at least two).
double cold_sky_power(std::vector<Point> pts) {
  std::sort(pts.begin(), pts.end(), [](const Point& a, const Point& b) { return a.power < b.power; });
  const std::size_t n = std::max<std::size_t>(2, pts.size() / 5);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += pts[i].power;
  return sum / static_cast<double>(n);
}

}  // namespace

ScanPattern scan_pattern(ScanShape shape, double span_deg, double step_deg) {
  ScanPattern p;
  if (!(span_deg > 0.0) || !(step_deg > 0.0) || !std::isfinite(span_deg) || !std::isfinite(step_deg)) {
    p.error = "the scan's span and step must be positive numbers of degrees";
    return p;
  }
  const double ratio = span_deg / step_deg;
  if (ratio > kMaxScanStepsEachSide + 1e-9) {
    p.error = text::printf_string("a span of %.2f deg in steps of %.2f deg is %.0f steps each side, more than %d: "
                                  "take a larger step",
                                  span_deg, step_deg, std::floor(ratio + 1e-9), kMaxScanStepsEachSide);
    return p;
  }
  const int n = static_cast<int>(std::floor(ratio + 1e-9));
  if (n < 1) {
    p.error = text::printf_string("the step %.2f deg is larger than the span %.2f deg", step_deg, span_deg);
    return p;
  }
  if (shape == ScanShape::cross) {
    for (int i = -n; i <= n; ++i) p.points.push_back({i * step_deg, 0.0});
    for (int j = -n; j <= n; ++j)
      if (j != 0) p.points.push_back({0.0, j * step_deg});
    return p;
  }
  for (int j = -n; j <= n; ++j) {
    const bool forward = (j + n) % 2 == 0;  // back and forth: no return sweep between rows
    for (int k = -n; k <= n; ++k) p.points.push_back({(forward ? k : -k) * step_deg, j * step_deg});
  }
  return p;
}

AzEl scan_target(AzEl body, ScanPoint p) {
  const double c = std::cos(body.el * kScanDegToRad);
  double az = std::fmod(body.az + (c > 1e-6 ? p.x_deg / c : 0.0), 360.0);
  if (az < 0.0) az += 360.0;
  return {az, body.el + p.y_deg};
}

double average_level_db(std::span<const double> levels_db) {
  if (levels_db.empty()) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (double l : levels_db) sum += to_power(l);
  return to_db(sum / static_cast<double>(levels_db.size()));
}

ScanFit fit_scan(std::span<const ScanSample> samples) {
  ScanFit fit;
  if (samples.size() < 6) {
    fit.error = text::printf_string("%zu points are too few for a fit (at least 6)", samples.size());
    return fit;
  }
  for (const ScanSample& s : samples) {
    if (!std::isfinite(s.level_db) || !std::isfinite(s.reading.az) || !std::isfinite(s.reading.el) ||
        !std::isfinite(s.body.az) || !std::isfinite(s.body.el)) {
      fit.error = "a sample holds a value that is not a number";
      return fit;
    }
  }
  double mean_el = 0.0;
  const std::vector<Point> pts = to_points(samples, mean_el);
  const double cold = cold_sky_power(pts);
  double peak_excess = 0.0;
  for (const Point& p : pts) peak_excess = std::max(peak_excess, p.power - cold);
  if (!(peak_excess > 0.02 * cold)) {
    fit.error = "no peak: the levels rise less than 0.1 dB over the cold sky";
    return fit;
  }
  // Weighted least squares of ln(excess) = c0 + c1 x + c2 x^2 + c3 y + c4 y^2.
  Matrix5 ata{};
  std::array<double, 5> atb{}, c{};
  double x_lo = 1e9, x_hi = -1e9, y_lo = 1e9, y_hi = -1e9;
  for (const Point& p : pts) {
    x_lo = std::min(x_lo, p.x); x_hi = std::max(x_hi, p.x);
    y_lo = std::min(y_lo, p.y); y_hi = std::max(y_hi, p.y);
    const double excess = p.power - cold;
    if (excess < kUsedFraction * peak_excess) continue;
    const std::array<double, 5> row{1.0, p.x, p.x * p.x, p.y, p.y * p.y};
    const double w = excess * excess, v = std::log(excess);
    for (int i = 0; i < 5; ++i) {
      for (int j = 0; j < 5; ++j) ata[i][j] += w * row[i] * row[j];
      atb[i] += w * row[i] * v;
    }
    ++fit.points_used;
  }
  if (fit.points_used < 5 || !solve5(ata, atb, c)) {
    fit.error = text::printf_string("only %d points stand out of the noise along too few lines: "
                                    "scan a wider span or in smaller steps", fit.points_used);
    return fit;
  }
  if (!(c[2] < 0.0) || !(c[4] < 0.0)) {
    fit.error = text::printf_string("no peak: the level does not fall off on both sides in %s",
                                    !(c[2] < 0.0) ? "azimuth" : "elevation");
    return fit;
  }
  fit.peak_x_deg = -c[1] / (2.0 * c[2]);
  fit.peak_y_deg = -c[3] / (2.0 * c[4]);
  if (fit.peak_x_deg < x_lo || fit.peak_x_deg > x_hi || fit.peak_y_deg < y_lo || fit.peak_y_deg > y_hi) {
    fit.error = text::printf_string("the peak (%+.2f, %+.2f deg from the body) is outside the scan: widen the span",
                                    fit.peak_x_deg, fit.peak_y_deg);
    return fit;
  }
  fit.beamwidth_x_deg = std::sqrt(-kFourLn2 / c[2]);
  fit.beamwidth_y_deg = std::sqrt(-kFourLn2 / c[4]);
  auto model = [&](double x, double y) { return std::exp(c[0] + c[1] * x + c[2] * x * x + c[3] * y + c[4] * y * y); };
  const double amplitude = model(fit.peak_x_deg, fit.peak_y_deg);
  fit.cold_sky_db = to_db(cold);
  fit.peak_over_cold_db = to_db((amplitude + cold) / cold);
  double sq = 0.0;
  for (const Point& p : pts) {
    if (p.power - cold < kUsedFraction * peak_excess) continue;
    const double r = to_db(model(p.x, p.y) + cold) - to_db(p.power);
    sq += r * r;
  }
  fit.rms_db = std::sqrt(sq / fit.points_used);
  const double ce = std::cos(mean_el * kScanDegToRad);
  fit.correction.az_deg = -(ce > 1e-6 ? fit.peak_x_deg / ce : 0.0);
  fit.correction.el_deg = -fit.peak_y_deg;
  return fit;
}

}  // namespace tb::rotator
