#include "store/drivers.h"

namespace tb::store {

std::string driver_label(std::string_view spec) {
  if (spec.empty() || spec == "simulated") return "SIM";
  // NAME, then its first field unless that is a device path: a Hamlib model number, a daemon's or
  // an ACU's host. The kinds themselves are the registries' (rotator/registry.h, radio/registry.h).
  const std::size_t colon = spec.find(':');
  const std::string name(spec.substr(0, colon));
  if (colon == std::string_view::npos) return name;
  const std::string_view rest = spec.substr(colon + 1);
  const std::string_view first = rest.substr(0, rest.find(':'));
  if (first.empty() || first.front() == '/') return name;
  return name + " " + std::string(first);
}

}  // namespace tb::store
