// The rotator and radio drivers as the operator named them (--rotator, --radio), kept in the state
// like --uplink-radio so that a later plain `trakbox` drives the same hardware (issue 30), and
// their short names for the status bar and menu 6-0.
#pragma once
#include <string>
#include <string_view>

namespace tb::store {

// "SIM" for the simulated driver (or none given); else the spec's name and its first field unless
// that is a device path: "hamlib 603" for hamlib:603:/dev/ttyUSB0, "rotctld localhost" for
// rotctld:localhost:4533, "satrak acu" for satrak:acu, "icom" for icom:/dev/ttyUSB1.
std::string driver_label(std::string_view spec);

}  // namespace tb::store
