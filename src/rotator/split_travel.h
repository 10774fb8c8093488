// Limits that split the travel: what the operator is told when the rotation limits leave two pieces
// of travel (the rotor stop inside the allowed sector, e.g. a South start with limits 10..350), and
// the compass form of a piece. Pure. docs/rotator.md "Limits that split the travel".
#pragma once
#include <optional>
#include <string>

#include "rotator/adc_model.h"

namespace tb::rotator {

// A piece of travel as the compass sector it covers, "180.0-350.0".
std::string compass_sector_text(station::RotorStart start, const Range& travel);

// The warning menu 6-4 and the station-file upload give when the configuration's limits split the
// travel, naming both pieces and the excluded sector; nothing when they do not. Two texts:
// barriers (cross_limit_sector false) and crossing between passes.
std::optional<std::string> split_travel_warning(const RotatorConfig& c, station::RotorStart start);

}  // namespace tb::rotator
