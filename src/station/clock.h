// The real-time clock. TrakBox keeps a battery-backed RTC; trakbox keeps system time plus a stored
// offset (menu 5 sets the offset, never the system clock). Everything that needs "now" takes a
// Clock, so tests and demonstrations can run on a fixed or accelerated time base.
#pragma once
#include <algorithm>
#include <chrono>
#include <functional>

#include "orbit/time.h"

namespace tb::station {

class Clock {
 public:
  virtual ~Clock() = default;
  virtual orbit::UtcTime now() const = 0;
};

// The fastest --clock-rate: up to it the tracker and the simulated rotator follow simulated time
// (the event loop ticks in simulated time, at least kMinWallTick of wall time apart).
inline constexpr double kMaxClockRate = 200.0;
inline constexpr std::chrono::microseconds kMinWallTick{5000};

// A wait of `simulated` clock time as wall time on a clock running `rate` times faster than real
// time, never shorter than kMinWallTick (a zero wait stays zero: "at once").
inline std::chrono::microseconds wall_wait(std::chrono::microseconds simulated, double rate) {
  if (simulated.count() <= 0) return std::chrono::microseconds(0);
  if (!(rate > 1.0)) return simulated;
  const auto w = std::chrono::microseconds(static_cast<long long>(static_cast<double>(simulated.count()) / rate));
  return std::max(w, kMinWallTick);
}

// The source of "system time": the real clock in the program, a function in tests.
using TimeSource = std::function<orbit::UtcTime()>;
orbit::UtcTime system_now();

// RTC = start_utc + rate * (source() - source_at_start) + offset.
// With rate 1 and no start given it is system time plus the offset.
class RealTimeClock final : public Clock {
 public:
  explicit RealTimeClock(TimeSource source = system_now);

  orbit::UtcTime now() const override;

  // Menu 5 "set": from now on now() reads t (kept as an offset from the running base).
  void set(orbit::UtcTime t);
  // Menu 5 / realtime 'Y': round the seconds to zero (to the nearest minute, as a time signal).
  void zero_seconds();
  // --clock ISO8601 --clock-rate R: start at t and run R times faster than the source.
  void start_at(orbit::UtcTime t, double rate = 1.0);

  // The stored part (persisted in the state document).
  std::chrono::microseconds offset() const { return offset_; }
  void set_offset(std::chrono::microseconds o) { offset_ = o; }
  double rate() const { return rate_; }

 private:
  orbit::UtcTime base_now() const;  // start/rate applied, offset not
  TimeSource source_;
  orbit::UtcTime source_origin_{};
  orbit::UtcTime start_{};
  bool started_ = false;
  double rate_ = 1.0;
  std::chrono::microseconds offset_{0};
};

// A clock a test moves by hand.
class ManualClock final : public Clock {
 public:
  explicit ManualClock(orbit::UtcTime t) : t_(t) {}
  orbit::UtcTime now() const override { return t_; }
  void set(orbit::UtcTime t) { t_ = t; }
  void advance(std::chrono::microseconds d) { t_ += d; }

 private:
  orbit::UtcTime t_;
};

}  // namespace tb::station
