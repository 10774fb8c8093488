// Parking into the horizon mask (issue 57): the parking position (menu 6-4, rotator.parking) is the
// operator's stow position and trakbox never moves it; when it lies below the station's horizon
// mask (station.horizon_mask) at its azimuth, that is said loudly instead: in the log when the
// antenna parks, among the status's problems, and by every front end that changes the mask or the
// parking into that state. Pure. docs/rotator.md "Horizon mask".
#pragma once
#include <optional>
#include <string>

#include "orbit/horizon_mask.h"
#include "rotator/config.h"

namespace tb::rotator {

// "parking at azimuth 230.0, elevation 0.0 points into the horizon mask (25.0 there)" when parking
// is on and the parking position points below the mask where it points (a parking elevation over
// 90 on a flip rotator points over the top: azimuth + 180, elevation 180 - el); nothing otherwise
// (parking off, no mask, or at or above it).
std::optional<std::string> parking_mask_warning(const RotatorConfig& c, const orbit::HorizonMask* mask);

}  // namespace tb::rotator
