#include "rotator/controller.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tb::rotator {

namespace {
constexpr Axis kAxes[] = {Axis::az, Axis::el};

double seconds(orbit::UtcTime from, orbit::UtcTime to) { return std::chrono::duration<double>(to - from).count(); }

std::chrono::microseconds micros(double s) {
  return std::chrono::microseconds(static_cast<std::int64_t>(std::llround(s * 1e6)));
}

const char* axis_name(Axis a) { return a == Axis::az ? "azimuth" : "elevation"; }
}  // namespace

const char* to_string(ControlMode m) {
  switch (m) {
    case ControlMode::idle: return "idle";
    case ControlMode::target: return "target";
    case ControlMode::manual: return "manual";
  }
  return "idle";
}

std::string format_monitor_line(int az_counts, double az_deg, int el_counts, double el_deg) {
  // One decimal, as the manual shows; an azimuth that rounds to 360.0 is shown as 0.0.
  double az = std::round(az_deg * 10.0) / 10.0;
  if (az >= 360.0) az -= 360.0;
  double el = std::round(el_deg * 10.0) / 10.0;
  if (el == 0.0) el = 0.0;  // no "-0.0"
  if (az == 0.0) az = 0.0;
  char buf[80];
  std::snprintf(buf, sizeof buf, "AZ=%4d / %.1fdeg EL=%4d / %.1fdeg.", az_counts, az, el_counts, el);
  return buf;
}

std::string format_monitor_line(const Status& s) {
  if (!s.has_position) return "AZ=---- / ---.-deg EL=---- / --.-deg.";
  return format_monitor_line(s.az.counts, s.az.deg, s.el.counts, s.el.deg);
}

Controller::Controller(const RotatorConfig& config, station::RotorStart start, std::unique_ptr<RotatorDriver> driver,
                       ControllerOptions options)
    : model_(config, start), driver_(std::move(driver)), opt_(options) {}

Controller::~Controller() {
  if (driver_) driver_->stop();
}

void Controller::set_config(const RotatorConfig& config, station::RotorStart start) {
  const int piece = model_.az_piece();
  model_ = AdcModel(config, start);
  if (model_.travel_split()) {
    // Limits as barriers: the piece the antenna is in; crossing: the piece chosen before.
    model_.set_az_piece(!config.cross_limit_sector && status_.has_position ? model_.az_piece_of(status_.az.travel)
                                                                            : piece);
  }
  if (status_.target) status_.target = model_.clamp(*status_.target);
  sent_.reset();
}

double Controller::rate_cps(Axis a) const {
  const RotatorConfig& c = model_.config();
  return (a == Axis::az ? c.az_rate_deg_s : c.el_rate_deg_s) * model_.counts_per_deg(a);
}

void Controller::note(std::string message, bool warn) {
  if (warn)
    spdlog::warn("rotator: {}", message);
  else
    spdlog::info("rotator: {}", message);
  status_.message = std::move(message);
}

void Controller::keep_to_piece(double travel) {
  if (model_.config().cross_limit_sector || !model_.travel_split()) return;
  const int p = model_.az_piece_of(travel);
  if (p != model_.az_piece()) use_az_piece(p);
}

void Controller::use_az_piece(int index) {
  model_.set_az_piece(index);
  if (status_.target) status_.target = model_.clamp(*status_.target);
}

bool Controller::select_az_piece(int index) {
  if (!model_.config().cross_limit_sector || !model_.travel_split()) return index == model_.az_piece();
  const std::vector<Range> pieces = model_.az_pieces();
  if (index < 0 || index >= static_cast<int>(pieces.size()) || pieces[static_cast<std::size_t>(index)].empty())
    return false;
  if (index != model_.az_piece()) use_az_piece(index);
  return true;
}

RotatorPosition Controller::set_target(AzEl compass, Piece piece) {
  if (piece == Piece::containing && model_.config().cross_limit_sector)
    if (const auto i = model_.az_piece_for_compass(compass.az)) select_az_piece(*i);
  double current = status_.has_position ? status_.az.travel : (status_.target ? status_.target->az_travel : 0.0);
  const RotatorPosition p = set_target(model_.target_for(compass, current));
  // Limited when the direction it goes is not the direction asked (a flip over the zenith points
  // the same way: az + 180, 180 - el).
  double az = model_.compass_from_travel(p.az_travel), el = p.el;
  if (el > 90.0) az += 180.0, el = 180.0 - el;
  status_.limited = status_.limited || azimuth_distance(az, compass.az) > 0.01 || std::abs(el - compass.el) > 0.01;
  return p;
}

RotatorPosition Controller::set_target(RotatorPosition p, Approach how) {
  const RotatorPosition asked = p;
  p = model_.clamp(p);
  status_.limited = !(p == asked);
  if (status_.mode != ControlMode::target || !status_.target || !(*status_.target == p)) {
    for (Axis a : kAxes) loop(a).stalled = false;
  }
  status_.target = p;
  status_.mode = ControlMode::target;
  for (Axis a : kAxes) {
    AxisLoop& l = loop(a);
    l.manual_goal.reset();
    l.manual_end.reset();
    l.duty = 1.0;
    l.exact = how == Approach::exact;
    l.exact_driven = false;
  }
  // The status describes the new target at once (goal counts, on target from the last reading),
  // not the previous one until the next tick: a display or a remote client asking "arrived?"
  // right after a GOTO must not see the previous arrival.
  for (Axis a : kAxes) {
    AxisStatus& s = axis_status(a);
    s.goal_counts.reset();
    if (auto g = goal_counts(a)) s.goal_counts = static_cast<int>(std::lround(*g));
  }
  update_on_target();
  return p;
}

bool Controller::park() {
  if (!model_.config().parking_enabled) return false;
  set_target(model_.config().parking, Piece::containing);
  return true;
}

bool Controller::preset(int n) {
  if (n < 1 || n > static_cast<int>(model_.config().presets.size())) return false;
  set_target(model_.config().presets[static_cast<std::size_t>(n - 1)], Piece::containing);
  return true;
}

void Controller::lines_off() {
  driver_->stop();
  for (Axis a : kAxes) loop(a).cmd = Drive::stop;
  sent_.reset();
}

void Controller::stop() {
  lines_off();
  status_.mode = ControlMode::idle;
  status_.target.reset();
  status_.limited = false;
  status_.on_target = false;
  const bool adc = driver_->as_adc() != nullptr;
  for (Axis a : kAxes) {
    AxisLoop& l = loop(a);
    l.manual_goal.reset();
    l.manual_end.reset();
    l.duty = 1.0;
    l.exact = false;
    l.stalled = false;
    axis_status(a).goal_counts.reset();
    axis_status(a).motion = Drive::stop;
    // The lines are off; an axis still coasting says so until it is at rest (ADC rotators; a
    // degree rotator reports its own motion at the next tick).
    axis_status(a).moving = adc && status_.has_position ? motion_of(a) : Drive::stop;
  }
}

Drive Controller::motion_of(Axis a) const {
  const AxisLoop& l = a == Axis::az ? az_ : el_;
  if (l.cmd != Drive::stop) return l.cmd;
  // Half the simulated rotator's friction stop: the model's coast is an estimate (a drive switched
  // off a little later than the tick that decided it, under load), so it says "moving" a little
  // longer than the motor moves (tau * ln 2, 0.1 s at coast 0.15 s), never shorter.
  if (std::abs(l.velocity) > 0.5 * kMotorStopFraction * rate_cps(a)) return l.velocity > 0.0 ? Drive::increase : Drive::decrease;
  return Drive::stop;
}

// The corrected readings of an ADC rotator are whole counts plus the shift (skew and the sky
// calibration's offsets, AdcModel::shift): with a fractional shift a whole-count goal is never read
// exactly, and a dead band of 0 would hunt for ever. The goal is taken on the readings' lattice.
double Controller::lattice(Axis a) const {
  const double f = model_.shift(a);
  return f - std::round(f);
}

int Controller::band(Axis a) const {
  const AxisLoop& l = a == Axis::az ? az_ : el_;
  return l.exact ? 0 : model_.dead_band(a);
}

void Controller::manual(Axis a, Drive d) {
  AxisLoop& l = loop(a);
  if (status_.mode != ControlMode::manual) {
    // Leaving target mode: nothing else keeps moving.
    status_.target.reset();
    status_.limited = false;
    az_.manual_goal.reset();
    el_.manual_goal.reset();
    for (Axis x : kAxes) {
      loop(x).manual_end.reset();
      loop(x).duty = 1.0;
      loop(x).exact = false;
    }
    status_.mode = ControlMode::manual;
  }
  l.stalled = false;
  l.manual_end.reset();
  l.duty = 1.0;
  l.jog_started = false;
  if (d == Drive::stop) {
    l.manual_goal.reset();
    if (AdcRotator* adc = driver_->as_adc()) {
      adc->drive(a, Drive::stop, {});
      l.cmd = Drive::stop;
    } else {
      lines_off();  // a degree rotator stops both axes; the other is sent again on the next tick
    }
    if (!az_.manual_goal && !el_.manual_goal) status_.mode = ControlMode::idle;
    return;
  }
  // The goal is the end of travel that way; tick() recomputes it from the range each time.
  l.manual_goal = static_cast<double>(sign(d));
}

void Controller::jog(Axis a, double rate_deg_s, std::optional<double> end) {
  if (rate_deg_s == 0.0 || !std::isfinite(rate_deg_s)) {
    manual(a, Drive::stop);
    return;
  }
  manual(a, rate_deg_s > 0.0 ? Drive::increase : Drive::decrease);
  AxisLoop& l = loop(a);
  const double full = a == Axis::az ? model_.config().az_rate_deg_s : model_.config().el_rate_deg_s;
  l.duty = full > 0.0 ? std::min(1.0, std::abs(rate_deg_s) / full) : 1.0;
  if (end) l.manual_end = a == Axis::az ? model_.counts_from_az_travel(*end) : model_.counts_from_el(*end);
}

bool Controller::manual_key(char key) {
  switch (static_cast<ManualKey>(key)) {
    case ManualKey::left: manual(Axis::az, Drive::decrease); return true;
    case ManualKey::right: manual(Axis::az, Drive::increase); return true;
    case ManualKey::up: manual(Axis::el, Drive::increase); return true;
    case ManualKey::down: manual(Axis::el, Drive::decrease); return true;
    case ManualKey::stop: stop(); return true;
  }
  return false;
}

void Controller::set_control_enabled(bool on) {
  status_.control_enabled = on;
  if (!on) lines_off();
}

std::optional<double> Controller::goal_counts(Axis a) const {
  const AxisLoop& l = a == Axis::az ? az_ : el_;
  if (status_.mode == ControlMode::target && status_.target) return model_.target_counts(a, *status_.target);
  if (status_.mode == ControlMode::manual && l.manual_goal) {
    Range r = model_.counts_range(a);
    if (r.empty()) return std::nullopt;
    if (*l.manual_goal > 0) return l.manual_end ? std::clamp(std::floor(*l.manual_end), std::ceil(r.lo), std::floor(r.hi)) : std::floor(r.hi);
    return l.manual_end ? std::clamp(std::ceil(*l.manual_end), std::ceil(r.lo), std::floor(r.hi)) : std::ceil(r.lo);
  }
  return std::nullopt;
}

void Controller::advance_model(orbit::UtcTime now) {
  const double tau = model_.config().coast_s;
  for (Axis a : kAxes) {
    AxisLoop& l = loop(a);
    const double v_cmd = sign(l.cmd) * rate_cps(a);
    double from_s = 0.0;
    const double total = seconds(*last_tick_, now);
    if (l.cmd != Drive::stop && l.cmd_until <= now) {
      double on = std::clamp(seconds(*last_tick_, l.cmd_until), 0.0, total);
      l.velocity = motor_advance({0.0, l.velocity}, v_cmd, tau, on).v;
      from_s = on;
      l.cmd = Drive::stop;
    }
    l.velocity = motor_advance({0.0, l.velocity}, sign(l.cmd) * rate_cps(a), tau, total - from_s).v;
  }
}

void Controller::update_limits(Axis a, double corrected, const LimitFlags& reported) {
  AxisStatus& s = axis_status(a);
  Range r = model_.counts_range(a);
  // At a limit: within the dead band of it (where an axis sent to the limit settles).
  const double band = model_.dead_band(a) + 0.5;
  s.at_low_limit = reported[a].low || (!r.empty() && corrected <= r.lo + band);
  s.at_high_limit = reported[a].high || (!r.empty() && corrected >= r.hi - band);
}

void Controller::tick(orbit::UtcTime now) {
  double dt = 0.0;
  bool driven_full[2] = {false, false};
  if (last_tick_) {
    if (now < *last_tick_) {
      // The clock stepped back (menu 5): no time passed; keep the drive deadlines relative.
      auto back = *last_tick_ - now;
      for (Axis a : kAxes) loop(a).cmd_until -= back;
      last_tick_ = now;
    }
    dt = seconds(*last_tick_, now);
    for (Axis a : kAxes) {
      AxisLoop& l = loop(a);
      driven_full[a == Axis::az ? 0 : 1] = l.cmd != Drive::stop && l.cmd_until >= now;
      // A jog's drive time delivered since the last tick.
      if (l.jog_started && l.cmd != Drive::stop)
        l.jog_on_s += std::clamp(seconds(*last_tick_, std::min(now, l.cmd_until)), 0.0, dt);
    }
    advance_model(now);
  }
  last_tick_ = now;

  Health h = driver_->health();
  status_.link = h;
  if (h.state != last_link_) {
    if (h.state == LinkState::fault)
      note("rotator fault: " + h.message + " (motors stopped)", true);
    else if (h.state == LinkState::ok)
      note("rotator link restored (" + driver_->description() + ")", false);
    last_link_ = h.state;
  }
  if (!h.ok()) {
    lines_off();
    status_.has_position = false;
    status_.on_target = false;
    for (Axis a : kAxes) axis_status(a).motion = axis_status(a).moving = Drive::stop;
    return;
  }
  if (AdcRotator* adc = driver_->as_adc()) {
    for (Axis a : kAxes) {
      AxisLoop& l = loop(a);
      if (!driven_full[a == Axis::az ? 0 : 1]) l.driven_still_s = 0.0;
    }
    tick_adc(*adc, now, dt);
  } else if (DegreeRotator* dr = driver_->as_degrees()) {
    tick_degrees(*dr, now);
  }
  update_on_target();
}

void Controller::update_on_target() {
  // On target: pointing, both axes inside the dead band and still.
  status_.on_target = status_.mode == ControlMode::target && status_.has_position;
  for (Axis a : kAxes) {
    const AxisStatus& s = axis_status(a);
    const double corr = loop(a).last_reading;
    if (!s.goal_counts || std::abs(*s.goal_counts + lattice(a) - corr) > band(a) || s.motion != Drive::stop)
      status_.on_target = false;
  }
}

void Controller::tick_adc(AdcRotator& adc, orbit::UtcTime now, double dt) {
  std::optional<Counts> r = adc.read();
  if (!r) {
    lines_off();
    status_.has_position = false;
    if (status_.message != "ADC not answering") note("ADC not answering", true);
    return;
  }
  raw_ = *r;
  status_.has_position = true;
  const LimitFlags reported = adc.limits();
  const RotatorConfig& c = model_.config();
  keep_to_piece(model_.az_travel_from_counts(model_.corrected(Axis::az, r->az)));
  for (Axis a : kAxes) {
    AxisLoop& l = loop(a);
    AxisStatus& s = axis_status(a);
    const int raw = a == Axis::az ? r->az : r->el;
    const double corr = model_.corrected(a, raw);
    s.counts = raw;
    s.travel = a == Axis::az ? model_.az_travel_from_counts(corr) : model_.el_from_counts(corr);
    s.deg = a == Axis::az ? model_.compass_from_travel(s.travel) : s.travel;
    update_limits(a, corr, reported);

    // Stall watch: driven for the whole interval and the reading did not change.
    if (std::abs(corr - l.last_reading) >= 1.0)
      l.driven_still_s = 0.0;
    else if (l.cmd != Drive::stop)
      l.driven_still_s += dt;
    l.last_reading = corr;

    s.goal_counts.reset();
    if (auto g = goal_counts(a)) s.goal_counts = static_cast<int>(std::lround(*g));
    if (!status_.control_enabled) continue;

    AxisCommand cmd;
    // An exact approach is over once its drive has ended: the dead band holds the axis from then.
    if (l.exact && l.exact_driven && l.cmd == Drive::stop) l.exact = false;
    if (s.goal_counts && !l.stalled) {
      AxisLoopInput in;
      in.reading = corr;
      in.target = *s.goal_counts + lattice(a);
      in.dead_band = band(a);
      in.range = model_.counts_range(a);
      in.driving = l.cmd;
      // A jog under way is driving between its pulses: it goes on to the centre of the dead band
      // at its end, as a key does, rather than stopping at the band's edge.
      const bool jogging = status_.mode == ControlMode::manual && l.manual_goal && l.duty < 1.0 && l.jog_started;
      if (jogging) in.driving = *l.manual_goal > 0 ? Drive::increase : Drive::decrease;
      // The coast ends where friction stops the motor (kMotorStopFraction of its rate), a little
      // short of where the first-order model alone would put it.
      const double v_stop = kMotorStopFraction * rate_cps(a);
      in.velocity = std::abs(l.velocity) <= v_stop ? 0.0 : l.velocity - std::copysign(v_stop, l.velocity);
      in.rate = rate_cps(a);
      in.coast_s = c.coast_s;
      cmd = decide(in);
      if (l.exact) {
        if (cmd.drive != Drive::stop)
          l.exact_driven = true;
        else
          l.exact = false;  // nothing to do, or arrived
      }
      // A jog never drives against its own direction (its end may lie behind the axis).
      if (cmd.drive != Drive::stop && status_.mode == ControlMode::manual && l.manual_goal &&
          sign(cmd.drive) * *l.manual_goal < 0.0)
        cmd = {};
      // A jog slower than the motor: pulses (jog_pulse).
      if (jogging && cmd.drive == Drive::stop) l.jog_started = false;  // at its end: held there
      if (cmd.drive != Drive::stop && status_.mode == ControlMode::manual && l.manual_goal && l.duty < 1.0)
        jog_pulse(l, cmd, now, dt);
    }
    apply_adc(adc, a, cmd, raw, now);
  }
  for (Axis a : kAxes) {
    axis_status(a).motion = loop(a).cmd;
    axis_status(a).moving = motion_of(a);
    axis_status(a).stalled = loop(a).stalled;
  }
  if (!status_.control_enabled) lines_off();
}

// A jog slower than the motor: pulses whose share of the time is the duty, counted from the jog's
// start so that late or early ticks do not change the rate; each pulse covers the time to the next
// tick, taken to be as long as the last interval (100 ms while moving, next_tick_in, in the
// clock's time: longer under a fast clock). A loop that stalled does not make up for the lost time
// in one burst.
void Controller::jog_pulse(AxisLoop& l, AxisCommand& cmd, orbit::UtcTime now, double dt) {
  const double kPeriod = dt > 0.0 ? std::clamp(dt, 0.02, 1.0) : 0.1;
  if (!l.jog_started) {
    l.jog_started = true;
    l.jog_t0 = now;
    l.jog_on_s = 0.0;
  }
  const double want = l.duty * (seconds(l.jog_t0, now) + kPeriod);
  l.jog_on_s = std::max(l.jog_on_s, want - 3.0 * l.duty * kPeriod);
  const double run = want - l.jog_on_s;
  if (run < 1e-4)
    cmd = {};
  else
    cmd.run_for_s = std::min(cmd.run_for_s, run);
}

// Sends one axis's decision to an ADC rotator: the stall watch first when error detection is on
// (driven stall_s without the reading changing: stopped and reported), then the drive with its run-for capped by the watchdog.
void Controller::apply_adc(AdcRotator& adc, Axis a, AxisCommand cmd, int raw, orbit::UtcTime now) {
  AxisLoop& l = loop(a);
  const RotatorConfig& c = model_.config();
  if (error_detection_ && cmd.drive != Drive::stop && l.cmd != Drive::stop && l.driven_still_s >= c.stall_s &&
      rate_cps(a) * c.stall_s >= 3.0) {
    l.stalled = true;
    cmd = {};
    note(std::string(axis_name(a)) + " stalled at " + std::to_string(raw) + " counts: driven " +
             std::to_string(static_cast<int>(c.stall_s)) + " s without moving, drive stopped",
         true);
  }
  if (cmd.drive == Drive::stop) {
    if (l.cmd != Drive::stop) adc.drive(a, Drive::stop, {});
    l.cmd = Drive::stop;
  } else {
    const double max_s = std::chrono::duration<double>(opt_.watchdog).count() * std::max(1.0, opt_.clock_rate);
    const double run = std::clamp(cmd.run_for_s, 1e-6, max_s);
    adc.drive(a, cmd.drive, micros(run));
    l.cmd = cmd.drive;
    l.cmd_until = now + micros(run);
  }
}

void Controller::tick_degrees(DegreeRotator& dr, orbit::UtcTime now) {
  std::optional<AzEl> p = dr.read();
  if (!p) {
    status_.has_position = false;
    return;
  }
  const RotatorConfig& c = model_.config();
  // The rotator's azimuth as travel from the stop (its own, skew not applied), unwrapped into
  // 0..az_travel_deg nearest the last reading.
  const double base = p->az - model_.start_deg();
  const double last = travel_raw_;
  double travel_raw = base;
  bool found = false;
  for (int n = -3; n <= 3; ++n) {
    double t = base + 360.0 * n;
    if (t < -0.5 || t > c.az_travel_deg + 0.5) continue;
    if (!found || std::abs(t - last) < std::abs(travel_raw - last)) travel_raw = t;
    found = true;
  }
  travel_raw_ = travel_raw;
  const double raw_c[2] = {model_.counts_from_az_travel(travel_raw), model_.counts_from_el(p->el)};
  double corr[2];
  const AxisMotion motion = dr.motion();
  const LimitFlags reported = dr.limits();
  status_.has_position = true;
  raw_ = Counts{static_cast<int>(std::lround(raw_c[0])), static_cast<int>(std::lround(raw_c[1]))};
  keep_to_piece(model_.az_travel_from_counts(model_.corrected(Axis::az, raw_c[0])));
  for (Axis a : kAxes) {
    const int i = a == Axis::az ? 0 : 1;
    AxisStatus& s = axis_status(a);
    corr[i] = model_.corrected(a, raw_c[i]);
    loop(a).last_reading = corr[i];
    s.counts = static_cast<int>(std::lround(raw_c[i]));
    s.travel = a == Axis::az ? model_.az_travel_from_counts(corr[i]) : model_.el_from_counts(corr[i]);
    s.deg = a == Axis::az ? model_.compass_from_travel(s.travel) : s.travel;
    s.motion = motion[a];
    s.moving = motion[a];
    s.stalled = false;
    update_limits(a, corr[i], reported);
    s.goal_counts.reset();
    if (auto g = goal_counts(a)) s.goal_counts = static_cast<int>(std::lround(*g));
  }
  if (!status_.control_enabled || (!status_.az.goal_counts && !status_.el.goal_counts)) return;

  // Each axis outside its dead band goes to its goal; one inside holds where it is.
  bool outside = false;
  double want_raw[2];
  for (Axis a : kAxes) {
    const int i = a == Axis::az ? 0 : 1;
    const AxisStatus& s = axis_status(a);
    want_raw[i] = raw_c[i];
    // An exact target is sent when it is more than half a count away; the rotator positions itself.
    const double b = loop(a).exact ? 0.5 : static_cast<double>(model_.dead_band(a));
    if (s.goal_counts && std::abs(*s.goal_counts - corr[i]) > b) {
      want_raw[i] = model_.raw(a, *s.goal_counts);
      outside = true;
    }
  }
  if (!outside) return;
  const double want_travel = model_.az_travel_from_counts(want_raw[0]);
  AzEl cmd{model_.start_deg() + want_travel, model_.el_from_counts(want_raw[1])};
  // Into the rotator's own azimuth convention (e.g. -180..180 or 0..450).
  Range ar = dr.az_range();
  if (!ar.empty() && !ar.contains(cmd.az)) {
    double best = cmd.az;
    bool ok = false;
    for (int n = -3; n <= 3; ++n) {
      double v = cmd.az + 360.0 * n;
      if (!ar.contains(v)) continue;
      if (!ok || std::abs(v - cmd.az) < std::abs(best - cmd.az)) best = v;
      ok = true;
    }
    cmd.az = ok ? best : ar.clamp(cmd.az);
  }
  // Sent only when it moved beyond the dead band from the last sent (half a count when exact): a GS-232B
  // rounding to whole degrees had been sent the same W again and again.
  auto band_deg = [&](Axis a) { return (loop(a).exact ? 0.5 : std::max(0.5, 1.0 * model_.dead_band(a))) * model_.deg_per_count(a); };
  const bool changed = !sent_ || std::abs(cmd.az - sent_->az) > band_deg(Axis::az) ||
                       std::abs(cmd.el - sent_->el) > band_deg(Axis::el);
  const bool idle = motion.az == Drive::stop && motion.el == Drive::stop;
  if (changed || (idle && now - sent_at_ >= opt_.resend)) {
    dr.set_position(cmd);
    sent_ = cmd;
    sent_at_ = now;
  }
}

std::chrono::milliseconds Controller::next_tick_in() const {
  // Bringing the antenna to a target is busy; no target, or rotor control off, is not (issue 49).
  const bool to_target = status_.mode == ControlMode::target && !status_.on_target && status_.target &&
                         status_.control_enabled;
  bool busy = status_.az.moving != Drive::stop || status_.el.moving != Drive::stop || to_target ||
              status_.mode == ControlMode::manual;
  return busy ? std::chrono::milliseconds(100) : std::chrono::milliseconds(1000);
}

}  // namespace tb::rotator
