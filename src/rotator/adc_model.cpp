#include "rotator/adc_model.h"

#include <algorithm>
#include <cmath>

namespace tb::rotator {

namespace {
constexpr double kEps = 1e-9;

Range intersect(Range a, Range b) { return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)}; }

// Width of a span as a divisor: never zero (validate() rejects such spans; this keeps the model
// total so that a bad configuration cannot divide by zero on its way to being reported).
double span_width(const AxisSpan& s) { return s.width() == 0 ? 1.0 : static_cast<double>(s.width()); }
}  // namespace

const char* drive_name(Axis axis, Drive d) {
  switch (d) {
    case Drive::stop: return "STOP";
    case Drive::increase: return axis == Axis::az ? "CW" : "UP";
    case Drive::decrease: return axis == Axis::az ? "CCW" : "DOWN";
  }
  return "STOP";
}

double wrap360(double deg) {
  double r = std::fmod(deg, 360.0);
  if (r < 0.0) r += 360.0;
  if (r >= 360.0) r -= 360.0;  // fmod of a tiny negative number plus 360
  return r;
}

double rotor_start_deg(station::RotorStart start) { return start == station::RotorStart::north ? 0.0 : 180.0; }

double azimuth_distance(double a, double b) {
  double d = wrap360(a - b);
  return d > 180.0 ? 360.0 - d : d;
}

AdcModel::AdcModel(const RotatorConfig& config, station::RotorStart start) : c_(config), start_(start) {}

// The skew in counts, plus the sky calibration's offset in degrees as counts of the axis's span.
double AdcModel::shift(Axis a) const {
  return a == Axis::az ? c_.az_skew + c_.az_offset_deg / deg_per_count(a) : c_.el_skew + c_.el_offset_deg / deg_per_count(a);
}
double AdcModel::corrected(Axis a, double raw) const { return raw + shift(a); }
double AdcModel::raw(Axis a, double corrected) const { return corrected - shift(a); }

double AdcModel::deg_per_count(Axis a) const {
  return a == Axis::az ? c_.az_travel_deg / span_width(c_.az_span) : c_.el_top_deg() / span_width(c_.el_span);
}

double AdcModel::az_travel_from_counts(double counts) const {
  return (counts - c_.az_span.min) * c_.az_travel_deg / span_width(c_.az_span);
}
double AdcModel::counts_from_az_travel(double travel) const {
  return c_.az_span.min + travel * span_width(c_.az_span) / c_.az_travel_deg;
}
double AdcModel::el_from_counts(double counts) const { return (counts - c_.el_span.min) * c_.el_top_deg() / span_width(c_.el_span); }
double AdcModel::counts_from_el(double el) const { return c_.el_span.min + el * span_width(c_.el_span) / c_.el_top_deg(); }
double AdcModel::compass_from_travel(double travel) const { return wrap360(travel + start_deg()); }

std::vector<Range> AdcModel::limit_pieces() const {
  const double T = c_.az_travel_deg;
  const double width = c_.az_limit_max - c_.az_limit_min;
  if (!c_.limits_enabled || width >= 360.0 - kEps) return {{0.0, T}};
  const double w = wrap360(width);
  const double s0 = wrap360(c_.az_limit_min - start_deg());
  std::vector<Range> out;
  for (int n = -1; n <= 2; ++n) {
    Range piece = intersect({s0 + 360.0 * n, s0 + 360.0 * n + w}, {0.0, T});
    if (piece.empty() || piece.width() <= kEps) continue;
    out.push_back(piece);
  }
  if (out.empty()) out.push_back({1.0, 0.0});  // empty: validate() reports it
  return out;
}

Range AdcModel::mech_travel() const {
  // The pot's calibrated ends are the mechanical stops: raw min..max, seen through the skew.
  Range mech{az_travel_from_counts(corrected(Axis::az, c_.az_span.min)),
             az_travel_from_counts(corrected(Axis::az, c_.az_span.max))};
  return intersect(mech, {0.0, c_.az_travel_deg});
}

std::vector<Range> AdcModel::az_pieces() const {
  std::vector<Range> out;
  const Range mech = mech_travel();
  for (const Range& p : limit_pieces()) out.push_back(intersect(p, mech));  // same indices, maybe empty
  return out;
}

bool AdcModel::travel_split() const {
  const std::vector<Range> pieces = az_pieces();
  return std::count_if(pieces.begin(), pieces.end(), [](const Range& r) { return !r.empty(); }) > 1;
}

int AdcModel::az_piece() const {
  const std::vector<Range> pieces = limit_pieces();
  if (piece_ >= 0 && piece_ < static_cast<int>(pieces.size())) return piece_;
  int best = 0;
  for (int i = 1; i < static_cast<int>(pieces.size()); ++i)
    if (pieces[static_cast<std::size_t>(i)].width() > pieces[static_cast<std::size_t>(best)].width() + kEps) best = i;
  return best;
}

int AdcModel::az_piece_of(double travel) const {
  const std::vector<Range> pieces = az_pieces();
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (int i = 0; i < static_cast<int>(pieces.size()); ++i) {
    const Range& p = pieces[static_cast<std::size_t>(i)];
    if (p.empty()) continue;
    const double d = p.contains(travel) ? 0.0 : std::min(std::abs(travel - p.lo), std::abs(travel - p.hi));
    if (d < best_d) {
      best_d = d;
      best = i;
    }
  }
  return best;
}

std::optional<int> AdcModel::az_piece_for_compass(double compass_az) const {
  const std::vector<Range> pieces = az_pieces();
  const double base = wrap360(compass_az - start_deg());
  for (int i = 0; i < static_cast<int>(pieces.size()); ++i)
    for (int n = -1; n <= 2; ++n)
      if (pieces[static_cast<std::size_t>(i)].contains(base + 360.0 * n)) return i;
  return std::nullopt;
}

Range AdcModel::az_limit_travel() const {
  const std::vector<Range> pieces = limit_pieces();
  return pieces[static_cast<std::size_t>(az_piece())];
}

Range AdcModel::az_travel_range() const { return intersect(az_limit_travel(), mech_travel()); }

Range AdcModel::el_range() const {
  Range r{0.0, c_.el_top_deg()};
  if (c_.limits_enabled) r = intersect(r, {c_.el_limit_min, c_.el_limit_max});
  // Raw counts the elevation may reach: the span (0..90, or 0..180 in flip mode); never outside
  // the ADC.
  const double raw_hi = std::min<double>(c_.el_span.max, kAdcMaxCount);
  double raw_lo = std::max(0, c_.el_span.min);
  Range mech{el_from_counts(corrected(Axis::el, raw_lo)), el_from_counts(corrected(Axis::el, raw_hi))};
  return intersect(r, mech);
}

Range AdcModel::counts_range(Axis a) const {
  if (a == Axis::az) {
    Range t = az_travel_range();
    return {counts_from_az_travel(t.lo), counts_from_az_travel(t.hi)};
  }
  Range e = el_range();
  return {counts_from_el(e.lo), counts_from_el(e.hi)};
}

double AdcModel::travel_for(double compass_az, double current_travel) const {
  const Range r = az_travel_range();
  if (r.empty()) return current_travel;
  const double base = wrap360(compass_az - start_deg());
  bool found = false;
  double best = 0.0;
  for (int n = -2; n <= 2; ++n) {
    double t = base + 360.0 * n;
    if (t < r.lo - kEps || t > r.hi + kEps) continue;
    if (!found || std::abs(t - current_travel) < std::abs(best - current_travel)) best = t;
    found = true;
  }
  if (found) return r.clamp(best);
  // Outside the limits: the limit nearest the wanted azimuth.
  double dlo = azimuth_distance(compass_from_travel(r.lo), compass_az);
  double dhi = azimuth_distance(compass_from_travel(r.hi), compass_az);
  if (std::abs(dlo - dhi) < kEps)
    return std::abs(r.lo - current_travel) <= std::abs(r.hi - current_travel) ? r.lo : r.hi;
  return dlo < dhi ? r.lo : r.hi;
}

std::optional<double> AdcModel::unwound_travel(double travel) const {
  // Half a degree beyond the turn, so that the stop's own 360 (north on a North-stop rotator) is not
  // wound; the travel in force must hold the turn back (a split travel's piece may not).
  if (travel <= 360.5) return std::nullopt;
  const double back = travel - 360.0;
  if (!az_travel_range().contains(back)) return std::nullopt;
  return back;
}

RotatorPosition AdcModel::target_for(AzEl compass, double current_travel) const {
  return clamp({travel_for(compass.az, current_travel), compass.el});
}

RotatorPosition AdcModel::clamp(RotatorPosition p) const {
  Range az = az_travel_range(), el = el_range();
  if (!az.empty()) p.az_travel = az.clamp(p.az_travel);
  if (!el.empty()) p.el = el.clamp(p.el);
  return p;
}

int AdcModel::target_counts(Axis a, const RotatorPosition& p) const {
  double c = a == Axis::az ? counts_from_az_travel(p.az_travel) : counts_from_el(p.el);
  Range r = counts_range(a);
  double n = std::round(c);
  if (!r.empty()) {
    // Whole counts inside the range (rounding must not step over a limit).
    double lo = std::ceil(r.lo - kEps), hi = std::floor(r.hi + kEps);
    if (lo <= hi) n = std::clamp(n, lo, hi);
  }
  return static_cast<int>(n);
}

MotorState motor_advance(MotorState s, double v_cmd, double tau_s, double dt_s) {
  if (dt_s <= 0.0) return s;
  if (tau_s <= 0.0) return {s.x + v_cmd * dt_s, v_cmd};
  const double k = std::exp(-dt_s / tau_s);
  MotorState out;
  out.x = s.x + v_cmd * dt_s + (s.v - v_cmd) * tau_s * (1.0 - k);
  out.v = v_cmd + (s.v - v_cmd) * k;
  if (std::abs(out.v) < 1e-9) out.v = 0.0;
  return out;
}

AxisCommand decide(const AxisLoopInput& in) {
  const double e_now = in.target - in.reading;
  const double e = e_now - in.velocity * in.coast_s;
  Drive d;
  if (in.driving == Drive::stop) {
    // Inside the dead band now, or coasting into it: leave it. (A reading inside the band is never
    // driven on the strength of a predicted coast: a motor that coasts further than modelled would
    // otherwise hunt around the band.)
    if (std::abs(e_now) <= in.dead_band || std::abs(e) <= in.dead_band) return {};
    d = e > 0.0 ? Drive::increase : Drive::decrease;
  } else {
    d = in.driving;
    if (e * sign(d) <= 0.0) return {};
  }
  if (d == Drive::increase && in.reading >= in.range.hi) return {Drive::stop, 0.0, true};
  if (d == Drive::decrease && in.reading <= in.range.lo) return {Drive::stop, 0.0, true};
  const double rate = in.rate > 0.0 ? in.rate : 1.0;
  return {d, e * sign(d) / rate, false};
}

}  // namespace tb::rotator
