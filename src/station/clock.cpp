#include "station/clock.h"

#include <cmath>

namespace tb::station {

orbit::UtcTime system_now() {
  return std::chrono::time_point_cast<std::chrono::microseconds>(std::chrono::system_clock::now());
}

RealTimeClock::RealTimeClock(TimeSource source) : source_(std::move(source)) {}

orbit::UtcTime RealTimeClock::base_now() const {
  const orbit::UtcTime s = source_();
  if (!started_) return s;
  const auto elapsed = (s - source_origin_).count();
  return start_ + std::chrono::microseconds(std::llround(static_cast<double>(elapsed) * rate_));
}

orbit::UtcTime RealTimeClock::now() const { return base_now() + offset_; }

void RealTimeClock::set(orbit::UtcTime t) { offset_ = t - base_now(); }

void RealTimeClock::zero_seconds() {
  const orbit::UtcTime t = now();
  const auto us = t.time_since_epoch().count();
  constexpr std::int64_t minute = 60'000'000;
  std::int64_t rounded = (us / minute) * minute;
  if (us - rounded >= minute / 2) rounded += minute;
  set(orbit::UtcTime(std::chrono::microseconds(rounded)));
}

void RealTimeClock::start_at(orbit::UtcTime t, double rate) {
  source_origin_ = source_();
  start_ = t;
  rate_ = rate;
  started_ = true;
  offset_ = std::chrono::microseconds(0);
}

}  // namespace tb::station
