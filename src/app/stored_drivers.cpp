#include "app/stored_drivers.h"

#include "store/drivers.h"
#include "store/owner.h"

namespace tb::app {

std::optional<std::string> apply_stored_drivers(TrackerConfig& c, store::ModelOwner& owner,
                                                std::vector<std::string>& said) {
  const store::Model& m = owner.model();
  // A driver named on the command line is stored through the model's one door.
  auto store_spec = [&owner](const char* key, const std::string& text) -> std::optional<std::string> {
    const store::EditResult r = owner.set(key, text, store::Origin::command_line);
    if (!r.ok()) return *r.refusal;
    return std::nullopt;
  };
  if (c.rotator_text) {
    if (auto err = store_spec("drivers.rotator", *c.rotator_text == "simulated" ? "" : *c.rotator_text))
      return "--rotator: " + *err;
  } else if (!m.rotator_driver.empty()) {
    if (auto err = set_rotator_spec(c, m.rotator_driver))
      return "the stored rotator '" + m.rotator_driver + "': " + *err + " (give --rotator)";
    said.push_back("Rotator: " + m.rotator_driver + " (" + store::driver_label(m.rotator_driver) +
                   ", stored; --rotator simulated to use the simulated one)");
  }
  if (c.radio_text) {
    if (auto err = store_spec("drivers.radio", *c.radio_text == "simulated" ? "" : *c.radio_text))
      return "--radio: " + *err;
  } else if (!m.radio_driver.empty()) {
    if (auto err = set_radio_spec(c, m.radio_driver))
      return "the stored radio '" + m.radio_driver + "': " + *err + " (give --radio)";
    said.push_back("Radio: " + m.radio_driver + " (" + store::driver_label(m.radio_driver) +
                   ", stored; --radio simulated to use the simulated one)");
  }
  // The uplink radio (menu 6-7 keeps it in the model's radio): read once here, driven as read.
  if (c.uplink_radio_text) {
    if (auto err = store_spec("radio.uplink_radio", *c.uplink_radio_text)) return "--uplink-radio: " + *err;
  } else if (!m.radio.uplink_radio.empty()) {
    const auto parsed = radio::parse_radio_spec(m.radio.uplink_radio, "--uplink-radio");
    if (!parsed.spec) return "the stored uplink radio '" + m.radio.uplink_radio + "': " + parsed.error + " (give --uplink-radio)";
    c.uplink_radio = parsed.spec;
  }
  return std::nullopt;
}

}  // namespace tb::app
