// Hamlib rig models by name: `hamlib:IC-9700:/dev/ttyUSB0` as well as `hamlib:3081:...`. The name is
// matched against Hamlib's own rig list (rig_list_foreach over every backend) ignoring case and
// punctuation, so IC-9700, ic9700 and "Icom IC-9700" all name model 3081.
#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace tb::radio {

struct HamlibModelLookup {
  std::optional<int> model;
  std::string error;   // no model: what was not found, with the nearest names ("did you mean ...")
};
HamlibModelLookup hamlib_rig_by_name(std::string_view name);

// "IC-9700" -> "ic9700": lower case letters and digits only.
std::string model_key(std::string_view name);

}  // namespace tb::radio
