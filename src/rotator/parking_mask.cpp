#include "rotator/parking_mask.h"

#include "rotator/adc_model.h"
#include "util/exact_number.h"

namespace tb::rotator {

std::optional<std::string> parking_mask_warning(const RotatorConfig& c, const orbit::HorizonMask* mask) {
  if (!c.parking_enabled || !mask) return std::nullopt;
  // Where the antenna looks when parked: over the top for an elevation past 90 (a flip rotator).
  const bool over = c.parking.el > 90.0;
  const double az = over ? wrap360(c.parking.az + 180.0) : wrap360(c.parking.az);
  const double el = over ? 180.0 - c.parking.el : c.parking.el;
  const double there = mask->at(az);
  if (el >= there) return std::nullopt;
  std::string w = "parking at azimuth " + text::one_decimal(c.parking.az) + ", elevation " +
                  text::one_decimal(c.parking.el) + " points into the horizon mask (" + text::one_decimal(there) +
                  " there";
  if (over) w += ", at azimuth " + text::one_decimal(az) + " over the top";
  return w + ")";
}

}  // namespace tb::rotator
