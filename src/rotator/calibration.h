// Menu 6-1's calibration of the ADC span: the raw counts read at both ends of travel become the
// rotator's span (pure: readings in, a span or the reason there is none out). The menu takes the
// readings from rotator::Controller::raw_counts().
#pragma once
#include <optional>
#include <string>

#include "rotator/config.h"
#include "rotator/driver.h"

namespace tb::rotator {

// Menu 6-1: record the raw counts with the antenna fully CCW at the horizon, then fully CW and
// straight up; the result is the new ADC span.
class SpanCalibration {
 public:
  void record_min(Counts raw) { min_ = raw; }
  void record_max(Counts raw) { max_ = raw; }
  bool complete() const { return min_ && max_; }
  // The spans, or an error saying what is wrong (a point missing, the readings not rising).
  struct Result {
    std::optional<AxisSpan> az, el;
    std::string error;
    bool ok() const { return error.empty(); }
  };
  Result result() const;
  // c with the measured spans, when result() is ok; c unchanged otherwise.
  RotatorConfig apply(RotatorConfig c) const;

 private:
  std::optional<Counts> min_, max_;
};

}  // namespace tb::rotator
