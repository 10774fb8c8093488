#include "app/stored_drivers.h"

#include "store/drivers.h"

namespace tb::app {

std::optional<std::string> apply_stored_drivers(TrackerConfig& c, store::Model& m, std::vector<std::string>& said) {
  if (c.rotator_text) m.rotator_driver = *c.rotator_text == "simulated" ? "" : *c.rotator_text;
  else if (!m.rotator_driver.empty()) {
    if (auto err = set_rotator_spec(c, m.rotator_driver))
      return "the stored rotator '" + m.rotator_driver + "': " + *err + " (give --rotator)";
    said.push_back("Rotator: " + m.rotator_driver + " (" + store::driver_label(m.rotator_driver) +
                   ", stored; --rotator simulated to use the simulated one)");
  }
  if (c.radio_text) m.radio_driver = *c.radio_text == "simulated" ? "" : *c.radio_text;
  else if (!m.radio_driver.empty()) {
    if (auto err = set_radio_spec(c, m.radio_driver))
      return "the stored radio '" + m.radio_driver + "': " + *err + " (give --radio)";
    said.push_back("Radio: " + m.radio_driver + " (" + store::driver_label(m.radio_driver) +
                   ", stored; --radio simulated to use the simulated one)");
  }
  return std::nullopt;
}

}  // namespace tb::app
