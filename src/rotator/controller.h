// The rotator controller: owns the ADC model and a driver, and makes the per-tick control decision.
// The tracker, the menus and host mode call it; nothing else moves the antenna.
//
//   Controller rot(config, station.rotor_start, make_hamlib_rotator(spec));   // or any RotatorDriver
//   rot.set_target({az, el});        // every second while tracking
//   rot.tick(clock.now());           // from the event loop, once a second or faster
//   menu 6-5: format_monitor_line(rot.status())  ->  "AZ= 519 / 32.8deg EL= 462 / 90.0deg."
//
// Nothing here blocks: drivers that talk to slow devices do that on their own threads.
// Everything moves only in tick(); stop() and disabling control switch the motors off at once.
#pragma once
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "orbit/time.h"
#include "rotator/adc_model.h"
#include "rotator/config.h"
#include "rotator/driver.h"
#include "station/station.h"

namespace tb::rotator {

enum class ControlMode {
  idle,    // holding still
  target,  // pointing at a target (tracking, park, preset, 6-6-2)
  manual,  // keyboard control (6-6-1)
};
const char* to_string(ControlMode m);

struct AxisStatus {
  int counts = 0;        // raw ADC counts (degree rotators: their position through the span)
  double deg = 0.0;      // skew applied; azimuth as a compass bearing [0, 360), elevation degrees
  double travel = 0.0;   // azimuth: degrees from the rotor stop; elevation: same as deg
  Drive motion = Drive::stop;  // the drive in force (degree rotators: the motion they report)
  // What the axis does: `motion`, or after the drive ends the way it still coasts until the
  // modelled motor is at rest (below kMotorStopFraction of its rate: the simulated rotator stops
  // there too). The Satrak STATUS? motion flags and the status line's "moving".
  Drive moving = Drive::stop;
  bool at_low_limit = false;   // at the CCW / DOWN end of where it may go (limits, span, switches)
  bool at_high_limit = false;  // at the CW / UP end
  bool stalled = false;        // driven without moving for stall_s: stopped, waits for a new command
  std::optional<int> goal_counts;  // corrected counts the axis is being brought to
};

struct Status {
  bool has_position = false;  // the axis fields below are valid
  AxisStatus az, el;
  Health link;                // the driver's connection/fault state
  bool control_enabled = true;
  ControlMode mode = ControlMode::idle;
  std::optional<RotatorPosition> target;  // clamped target, rotator coordinates
  bool on_target = false;     // mode target, both axes inside the dead band and not moving
  // The target asked for lay outside the limits and was clamped to them: on target means "as near
  // as the limits let it", said so (issue 60: "on target" at 0.0 deg with 349.4 wanted).
  bool limited = false;
  std::string message;        // the latest thing the operator should know ("" when nothing)
};

// The monitor line of menus 6-5 and 6-6: "AZ= 519 / 32.8deg EL= 462 / 90.0deg."
std::string format_monitor_line(int az_counts, double az_deg, int el_counts, double el_deg);
// The same from a status; "AZ=---- / ---.-deg EL=---- / --.-deg." when there is no position.
std::string format_monitor_line(const Status& s);

// Keys of menu 6-6-1: Left(4), Right(6), Up(8), Dwn(2), Stop(5).
enum class ManualKey : char { left = '4', right = '6', up = '8', down = '2', stop = '5' };

struct ControllerOptions {
  // Longest a drive line stays on without a tick renewing it (a watchdog: if the event loop stalls
  // the motors stop). Must exceed the tick interval.
  std::chrono::milliseconds watchdog{2500};
  // The clock's rate (--clock-rate): the event loop ticks in clock time, but the watchdog guards
  // against a loop stalled in wall time, so a drive may last watchdog * clock_rate of clock time
  // (at 100x a 120-degree slew is one 20 s pulse, renewed each tick, never cut short by a tick
  // that came a few wall milliseconds late).
  double clock_rate = 1.0;
  // Degree rotators: an unchanged target is sent again this often while the rotator sits idle
  // outside the dead band (a command lost on the way).
  std::chrono::milliseconds resend{2000};
};

class Controller {
 public:
  Controller(const RotatorConfig& config, station::RotorStart start, std::unique_ptr<RotatorDriver> driver,
             ControllerOptions options = {});
  ~Controller();
  Controller(const Controller&) = delete;
  Controller& operator=(const Controller&) = delete;

  // Menus 4, 6-1..6-4 and 6-9 change these; the current target is kept and clamped again.
  void set_config(const RotatorConfig& config, station::RotorStart start);
  const RotatorConfig& config() const { return model_.config(); }
  const AdcModel& model() const { return model_; }
  RotatorDriver& driver() { return *driver_; }

  // Point at a compass az/el (degrees), clamped to the limits. Where the azimuth can be reached two
  // ways, the way nearest the antenna. Returns the target as it will be commanded.
  //   Piece::in_force: inside the piece of travel in force (limits that split the travel).
  //   Piece::containing: an explicit move (park, presets, the operator's GOTO): when the limits are
  //                      pointing limits only (cross_limit_sector), into the piece that contains
  //                      the azimuth, crossing the excluded sector; barriers keep the piece.
  enum class Piece { in_force, containing };
  RotatorPosition set_target(AzEl compass, Piece piece = Piece::in_force);
  // Limits that split the travel and may be crossed (cross_limit_sector): make a piece of
  // AdcModel::az_pieces() the one in force (the pass planner, between passes); the target is
  // clamped into it. With barriers only the piece the antenna is in: false for another.
  bool select_az_piece(int index);
  // How a target is approached.
  //   dead_band: the configured dead band (tracking, park, presets, the menus): an axis within it
  //              of the target does not move.
  //   exact:     an explicit move (a Satrak STEP or GOTO): each axis is brought to the target count
  //              once, however small the move (to the sensor's resolution, not the dead band's);
  //              once it has been driven there (or had nothing to do) the dead band holds it as
  //              for any target. Degree rotators are sent the target when it is a count or more
  //              away.
  enum class Approach { dead_band, exact };
  // Point at a position in rotator coordinates (what a PassPlan maps targets to), clamped.
  RotatorPosition set_target(RotatorPosition p, Approach how = Approach::dead_band);
  // To the parking position; false (and nothing changes) when parking is disabled.
  bool park();
  // To preset 1..5 (menu 6-6-3); false for another number.
  bool preset(int n);
  // Abort: motors off now, target and manual motion dropped.
  void stop();
  // Keyboard control (6-6-1): drive an axis towards its end of travel until stopped; Drive::stop
  // stops that axis.
  void manual(Axis axis, Drive d);
  // 4/6/8/2/5 as in the manual; false for any other key.
  bool manual_key(char key);
  // Drives an axis steadily at rate_deg_s (signed, capped at the axis's motor rate) until stop(),
  // a target, a key, or `end` (azimuth travel / elevation degrees; clamped into the axis's range,
  // whose end is the default) is reached. Rate 0 stops the axis. A rate below the motor's is made
  // of drive pulses every tick whose share of the time is rate / motor rate (the motor's inertia,
  // coast_s, smooths them into steady motion); docs/rotator.md "Jogging".
  void jog(Axis axis, double rate_deg_s, std::optional<double> end = std::nullopt);

  // The E key: when off nothing moves (tracking, park, presets and keyboard control alike); the
  // target is kept and resumed when control is switched on again.
  void set_control_enabled(bool on);
  bool control_enabled() const { return status_.control_enabled; }
  void toggle_control() { set_control_enabled(!control_enabled()); }

  // Rotator error detection (the later firmware's STATION.DAT line 6, second digit): on, an axis
  // driven stall_s without its reading changing is stopped and reported; off, it is driven on (for a
  // rotator whose sensor lags or sticks) and only the drive watchdog bounds each pulse.
  void set_error_detection(bool on) { error_detection_ = on; }
  bool error_detection() const { return error_detection_; }

  // The control step. Call from the event loop once a second or faster; `now` only moves forward
  // (a step back counts as no time passed).
  void tick(orbit::UtcTime now);
  // How soon the next tick would help: 100 ms while anything moves or is off target, else 1 s.
  std::chrono::milliseconds next_tick_in() const;

  const Status& status() const { return status_; }
  // The latest raw counts (menu 6-1 calibration records these), nothing before the first reading.
  // (Degree rotators: their position through the span.)
  std::optional<Counts> raw_counts() const { return raw_; }

 private:
  struct AxisLoop {
    std::optional<double> manual_goal;  // the sign of the range end the axis is being driven to
    std::optional<double> manual_end;   // counts: where a jog stops short of that end
    double duty = 1.0;                  // jog: share of the time the drive is on (1: keys)
    bool jog_started = false;           // jog: the pulse accounting below has begun
    orbit::UtcTime jog_t0{};
    double jog_on_s = 0.0;              // jog: drive time delivered since jog_t0
    bool exact = false;                 // Approach::exact: not yet driven to the target count
    bool exact_driven = false;          // ... and a drive towards it has been issued
    Drive cmd = Drive::stop;            // the drive in force (ADC rotators)
    orbit::UtcTime cmd_until{};
    double velocity = 0.0;              // modelled, counts/s
    double last_reading = 0.0;
    double driven_still_s = 0.0;        // driven without the reading changing
    bool stalled = false;
  };
  AxisLoop& loop(Axis a) { return a == Axis::az ? az_ : el_; }
  AxisStatus& axis_status(Axis a) { return a == Axis::az ? status_.az : status_.el; }
  double rate_cps(Axis a) const;
  void advance_model(orbit::UtcTime now);
  void lines_off();
  void note(std::string message, bool warn);
  std::optional<double> goal_counts(Axis a) const;
  double lattice(Axis a) const;  // the shift's fraction of a count, which every corrected reading has
  void tick_adc(AdcRotator& adc, orbit::UtcTime now, double dt);
  void jog_pulse(AxisLoop& l, AxisCommand& cmd, orbit::UtcTime now, double dt);
  void apply_adc(AdcRotator& adc, Axis a, AxisCommand cmd, int raw, orbit::UtcTime now);
  void tick_degrees(DegreeRotator& dr, orbit::UtcTime now);
  void update_on_target();  // status_.on_target from the goals, the last readings and the motion
  int band(Axis a) const;   // the dead band in force: 0 while an exact approach is pending
  // What an axis does: driven, or still coasting (the modelled motor faster than kMotorStopFraction
  // of its rate); ADC rotators.
  Drive motion_of(Axis a) const;
  void update_limits(Axis a, double corrected, const LimitFlags& reported);
  // Limits that split the travel, as barriers: the piece in force is the one the antenna is in
  // (or nearest, when it is outside the limits), the target clamped into it.
  void keep_to_piece(double travel);
  // Makes a piece of travel the one in force and clamps the target into it.
  void use_az_piece(int index);

  AdcModel model_;
  std::unique_ptr<RotatorDriver> driver_;
  ControllerOptions opt_;
  Status status_;
  bool error_detection_ = true;
  AxisLoop az_, el_;
  std::optional<Counts> raw_;
  std::optional<orbit::UtcTime> last_tick_;
  LinkState last_link_ = LinkState::ok;
  // Degree rotators: what was last sent, and when.
  std::optional<AzEl> sent_;
  double travel_raw_ = 0.0;  // the rotator's last azimuth as travel from the stop, skew not applied
  orbit::UtcTime sent_at_{};
};

}  // namespace tb::rotator
