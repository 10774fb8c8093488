// The rotator driver interface the controller uses. Two kinds of rotator sit behind it:
//
//  * ADC rotators (AdcRotator): the TrakBox hardware and the simulated rotator. The controller reads
//    the raw potentiometer counts and switches the CW/CCW/UP/DOWN lines itself; the dead band, skew,
//    limits and parking are all applied by the controller through the AdcModel.
//  * Degree rotators (DegreeRotator): rotators with their own controller that take and report
//    degrees (everything Hamlib drives). The controller converts their degrees through the same
//    AdcModel span, so dead band and skew are counts of that span exactly as for an ADC rotator
//    (docs/rotator.md, "Degree rotators").
//
// No call on this interface blocks: a driver that talks to slow or absent hardware does that on a
// thread of its own and answers from what it last heard.
#pragma once
#include <chrono>
#include <optional>
#include <string>

#include "rotator/adc_model.h"
#include "rotator/config.h"

namespace tb::rotator {

struct Counts {
  int az = 0;
  int el = 0;
  friend bool operator==(const Counts&, const Counts&) = default;
};

enum class LinkState { ok, connecting, fault };
const char* to_string(LinkState s);  // "ok", "connecting", "fault"

// The connection/fault state of a driver.
struct Health {
  LinkState state = LinkState::ok;
  std::string message;    // what is wrong (empty when ok)
  unsigned connects = 0;  // successful connections so far (a reconnect makes it > 1)
  bool ok() const { return state == LinkState::ok; }
};

// Which way each axis is moving.
struct AxisMotion {
  Drive az = Drive::stop;
  Drive el = Drive::stop;
  Drive& operator[](Axis a) { return a == Axis::az ? az : el; }
  Drive operator[](Axis a) const { return a == Axis::az ? az : el; }
};

// End-of-travel flags per axis (low = CCW / DOWN end, high = CW / UP end).
struct AxisLimits {
  bool low = false;
  bool high = false;
};
struct LimitFlags {
  AxisLimits az, el;
  AxisLimits& operator[](Axis a) { return a == Axis::az ? az : el; }
  const AxisLimits& operator[](Axis a) const { return a == Axis::az ? az : el; }
};

class AdcRotator;
class DegreeRotator;

class RotatorDriver {
 public:
  virtual ~RotatorDriver() = default;
  // "simulated", "rotctld 127.0.0.1:4533", "hamlib 603 /dev/ttyUSB0 9600", ...
  virtual std::string description() const = 0;
  virtual Health health() = 0;
  // Which way each axis is moving now.
  virtual AxisMotion motion() = 0;
  // End-of-travel as the rotator itself reports it (limit switches, Hamlib status); the
  // controller adds its own from the configured limits.
  virtual LimitFlags limits() { return {}; }
  // Every motor off, at once. Never blocks; safe to call in any state, also when faulted.
  virtual void stop() = 0;

  virtual AdcRotator* as_adc() { return nullptr; }
  virtual DegreeRotator* as_degrees() { return nullptr; }
};

// The TrakBox interface: two potentiometers read through a 10-bit ADC, four drive lines.
class AdcRotator : public RotatorDriver {
 public:
  AdcRotator* as_adc() override { return this; }
  // Raw counts now (0..1023), or nothing when the ADC cannot be read.
  virtual std::optional<Counts> read() = 0;
  // Switches one axis: driven `d` for at most run_for, then off by itself (a watchdog, so a stalled
  // event loop never leaves a motor running). Drive::stop switches the axis off at once.
  virtual void drive(Axis axis, Drive d, std::chrono::microseconds run_for) = 0;
  AxisMotion motion() override = 0;
};

// A rotator with its own position controller that speaks degrees.
class DegreeRotator : public RotatorDriver {
 public:
  DegreeRotator* as_degrees() override { return this; }
  // The rotator's position as it reports it (azimuth in its own convention: may be negative or
  // beyond 360 on overlap rotators), or nothing when unknown (not connected, no reading yet).
  virtual std::optional<AzEl> read() = 0;
  // Go to a position (rotator azimuth convention). The latest command wins; commands given while
  // the link is down are dropped, not replayed later.
  virtual void set_position(AzEl p) = 0;
  // The azimuth values the rotator accepts, e.g. -180..180, 0..360 or 0..450.
  virtual Range az_range() = 0;
};

}  // namespace tb::rotator
