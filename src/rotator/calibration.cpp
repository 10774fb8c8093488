#include "rotator/calibration.h"

#include <string>

namespace tb::rotator {

SpanCalibration::Result SpanCalibration::result() const {
  Result r;
  if (!min_ || !max_) {
    r.error = !min_ ? "the CCW/minimum position has not been recorded" : "the CW/maximum position has not been recorded";
    return r;
  }
  AxisSpan az{min_->az, max_->az}, el{min_->el, max_->el};
  RotatorConfig probe;
  probe.az_span = az;
  probe.el_span = el;
  std::string err;
  for (const std::string& e : validate(probe))
    if (e.find("ADC span") != std::string::npos) err += (err.empty() ? "" : "; ") + e;
  if (!err.empty()) {
    r.error = err;
    return r;
  }
  r.az = az;
  r.el = el;
  return r;
}

RotatorConfig SpanCalibration::apply(RotatorConfig c) const {
  Result r = result();
  if (r.ok()) {
    c.az_span = *r.az;
    c.el_span = *r.el;
  }
  return c;
}

}  // namespace tb::rotator
