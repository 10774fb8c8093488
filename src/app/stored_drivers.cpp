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
  // The uplink radio (menu 6-7 keeps it in the model's radio): read once here, driven as read.
  if (c.uplink_radio_text) m.radio.uplink_radio = *c.uplink_radio_text;
  else if (!m.radio.uplink_radio.empty()) {
    const auto parsed = radio::parse_radio_spec(m.radio.uplink_radio, "--uplink-radio");
    if (!parsed.spec) return "the stored uplink radio '" + m.radio.uplink_radio + "': " + parsed.error + " (give --uplink-radio)";
    c.uplink_radio = parsed.spec;
  }
  return std::nullopt;
}

}  // namespace tb::app
