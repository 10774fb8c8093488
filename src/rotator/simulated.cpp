#include "rotator/simulated.h"

#include <algorithm>
#include <cmath>

namespace tb::rotator {

namespace {
double sim_seconds(orbit::UtcTime from, orbit::UtcTime to) {
  return std::chrono::duration<double>(to - from).count();
}
}  // namespace

SimulatedRotatorParams SimulatedRotatorParams::matching(const RotatorConfig& c) {
  SimulatedRotatorParams p;
  p.az_travel_deg = c.az_travel_deg;
  p.az_counts_at_ccw = c.az_span.min;
  p.az_counts_at_cw = c.az_span.max;
  p.el_counts_at_0 = c.el_span.min;
  // The span covers 0..el_top_deg() (180 in flip mode): 90 degrees reads at its share of it.
  p.el_counts_at_90 = c.el_span.min + c.el_span.width() * 90.0 / c.el_top_deg();
  p.el_max_deg = c.el_top_deg();
  p.az_rate_deg_s = c.az_rate_deg_s;
  p.el_rate_deg_s = c.el_rate_deg_s;
  p.coast_s = c.coast_s;
  p.stop_fraction = kMotorStopFraction;
  return p;
}

SimulatedRotator::SimulatedRotator(const station::Clock& clock, SimulatedRotatorParams params)
    : clock_(clock), p_(params), t_(clock.now()) {
  az_.lo = 0.0;
  az_.hi = p_.az_travel_deg;
  az_.rate = p_.az_rate_deg_s;
  el_.lo = p_.el_min_deg;
  el_.hi = p_.el_max_deg;
  el_.rate = p_.el_rate_deg_s;
  az_.x = std::clamp(p_.start.az_travel, az_.lo, az_.hi);
  el_.x = std::clamp(p_.start.el, el_.lo, el_.hi);
}

void SimulatedRotator::advance_axis(AxisSim& s, orbit::UtcTime to) {
  auto step = [&](double v_cmd, double dt) {
    const double v_stop = p_.stop_fraction * s.rate;
    MotorState m;
    if (v_cmd == 0.0 && v_stop > 0.0 && dt > 0.0 && std::abs(s.v) <= v_stop) {
      m = {s.x, 0.0};  // at rest: friction holds it
    } else if (v_cmd == 0.0 && v_stop > 0.0 && dt > 0.0 && p_.coast_s > 0.0 &&
               dt >= p_.coast_s * std::log(std::abs(s.v) / v_stop)) {
      // Coasts down to the stopping speed within dt, and stops there.
      m = {s.x + (s.v - std::copysign(v_stop, s.v)) * p_.coast_s, 0.0};
    } else {
      m = motor_advance({s.x, s.v}, v_cmd, p_.coast_s, dt);
    }
    s.x = m.x;
    s.v = m.v;
    if (s.x <= s.lo) {  // against the end stop
      s.x = s.lo;
      s.v = std::max(s.v, 0.0);
      if (v_cmd <= 0.0) s.v = 0.0;
    } else if (s.x >= s.hi) {
      s.x = s.hi;
      s.v = std::min(s.v, 0.0);
      if (v_cmd >= 0.0) s.v = 0.0;
    }
  };
  orbit::UtcTime t = t_;
  if (s.drive != Drive::stop && s.deadline <= to) {
    step(sign(s.drive) * s.rate, sim_seconds(t, std::max(t, s.deadline)));
    t = std::max(t, s.deadline);
    s.drive = Drive::stop;
  }
  step(sign(s.drive) * s.rate, sim_seconds(t, to));
}

void SimulatedRotator::advance() {
  const orbit::UtcTime now = clock_.now();
  if (now > t_) {
    advance_axis(az_, now);
    advance_axis(el_, now);
  } else if (now < t_) {
    // A clock stepped back: nothing moved; drive deadlines stay as far ahead as they were.
    az_.deadline -= t_ - now;
    el_.deadline -= t_ - now;
  }
  t_ = now;
}

Health SimulatedRotator::health() {
  if (fault_) return {LinkState::fault, *fault_, connects_};
  return {LinkState::ok, {}, connects_};
}

AxisMotion SimulatedRotator::motion() {
  advance();
  return {az_.drive, el_.drive};
}

LimitFlags SimulatedRotator::limits() {
  advance();
  LimitFlags f;
  f.az = {az_.x <= az_.lo, az_.x >= az_.hi};
  f.el = {el_.x <= el_.lo, el_.x >= el_.hi};
  return f;
}

void SimulatedRotator::stop() {
  advance();
  az_.drive = Drive::stop;
  el_.drive = Drive::stop;
}

std::optional<Counts> SimulatedRotator::read() {
  advance();
  if (fault_) return std::nullopt;
  auto adc = [](double c) { return std::clamp(static_cast<int>(std::floor(c)), 0, kAdcMaxCount); };
  const double az_read = az_.x + p_.mount_az_deg, el_read = el_.x + p_.mount_el_deg;
  const double az = p_.az_counts_at_ccw + az_read * (p_.az_counts_at_cw - p_.az_counts_at_ccw) / p_.az_travel_deg;
  const double el = p_.el_counts_at_0 + el_read * (p_.el_counts_at_90 - p_.el_counts_at_0) / 90.0;
  return Counts{adc(az), adc(el)};
}

void SimulatedRotator::drive(Axis a, Drive d, std::chrono::microseconds run_for) {
  advance();
  AxisSim& s = axis(a);
  if (fault_ || d == Drive::stop || run_for <= std::chrono::microseconds::zero()) {
    s.drive = Drive::stop;
    return;
  }
  s.drive = d;
  s.deadline = t_ + run_for;
}

RotatorPosition SimulatedRotator::true_position() {
  advance();
  return {az_.x, el_.x};
}

double SimulatedRotator::true_velocity(Axis a) {
  advance();
  return axis(a).v;
}

void SimulatedRotator::set_fault(std::string message) {
  stop();
  fault_ = std::move(message);
}

void SimulatedRotator::clear_fault() {
  if (fault_) ++connects_;
  fault_.reset();
}

}  // namespace tb::rotator
