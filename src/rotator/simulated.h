// The simulated rotator: trakbox's default rotator, so that the program does something real on a
// machine with no hardware. An ADC rotator like the TrakBox's: two motors with end stops, a small
// spin-up/coast (first-order, time constant coast_s) so that the dead band matters, and two
// potentiometers read through a 10-bit ADC (counts = floor(pot), 0..1023).
//
// It advances in simulated time, read from the injected clock on every call; it never reads the
// wall clock. A clock that steps back is taken as "no time passed".
#pragma once
#include <optional>
#include <string>

#include "rotator/driver.h"
#include "station/clock.h"

namespace tb::rotator {

struct SimulatedRotatorParams {
  // Mechanics: azimuth end stops at travel 0 and az_travel_deg; elevation from el_min_deg to
  // el_max_deg (a 0..180 elevation rotator by default: it can flip, trakbox decides whether to).
  double az_travel_deg = 360.0;
  double el_min_deg = 0.0;
  double el_max_deg = 180.0;
  // Potentiometers: the (fractional) count at two points of each axis, linear in between.
  double az_counts_at_ccw = 0.0;   // at travel 0 (the stop)
  double az_counts_at_cw = 1023.0; // at travel az_travel_deg
  double el_counts_at_0 = 0.0;
  double el_counts_at_90 = 511.0;
  // Motors.
  double az_rate_deg_s = 6.0;
  double el_rate_deg_s = 3.0;
  double coast_s = 0.15;
  // Friction: a coasting motor slower than this share of its rate stops dead (0: it coasts on,
  // exponentially, for ever). matching() gives kMotorStopFraction, the controller's own figure,
  // so that the controller reports an axis still exactly when it is.
  double stop_fraction = 0.0;
  // A mounting error (a slipped mast clamp, a pot's zero; `--rotator simulated:mount=AZ,EL`): the
  // potentiometers read the antenna's position plus these degrees. true_position() is where it points.
  double mount_az_deg = 0.0;
  double mount_el_deg = 0.0;
  // Where the antenna is at power-on (azimuth travel from the stop, elevation).
  RotatorPosition start{0.0, 0.0};

  // A rotator whose potentiometers read exactly the span of `c` (the rotator a calibration of
  // c describes) and whose motors run at c's rates.
  static SimulatedRotatorParams matching(const RotatorConfig& c);
};

class SimulatedRotator final : public AdcRotator {
 public:
  explicit SimulatedRotator(const station::Clock& clock, SimulatedRotatorParams params = {});

  std::string description() const override { return "simulated"; }
  Health health() override;
  AxisMotion motion() override;
  LimitFlags limits() override;
  void stop() override;
  std::optional<Counts> read() override;
  void drive(Axis axis, Drive d, std::chrono::microseconds run_for) override;

  // For tests and demonstrations.
  RotatorPosition true_position();               // azimuth travel and elevation, degrees
  double true_velocity(Axis a);                  // deg/s
  void set_fault(std::string message);           // the ADC stops answering, motors stop
  void clear_fault();
  const SimulatedRotatorParams& params() const { return p_; }

 private:
  struct AxisSim {
    double x = 0.0;  // degrees (az travel / el)
    double v = 0.0;  // deg/s
    Drive drive = Drive::stop;
    orbit::UtcTime deadline{};
    double lo = 0.0, hi = 0.0, rate = 0.0;
  };
  void advance();
  void advance_axis(AxisSim& s, orbit::UtcTime to);
  AxisSim& axis(Axis a) { return a == Axis::az ? az_ : el_; }

  const station::Clock& clock_;
  SimulatedRotatorParams p_;
  orbit::UtcTime t_{};
  AxisSim az_, el_;
  std::optional<std::string> fault_;
  unsigned connects_ = 1;
};

}  // namespace tb::rotator
