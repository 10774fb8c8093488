#include "store/drivers.h"

namespace tb::store {

std::string driver_label(std::string_view spec) {
  if (spec.empty() || spec == "simulated") return "SIM";
  const std::size_t colon = spec.find(':');
  const std::string kind(spec.substr(0, colon));
  if (colon == std::string_view::npos) return kind;
  const std::string_view rest = spec.substr(colon + 1);
  const std::string first(rest.substr(0, rest.find(':')));
  if (kind == "hamlib" || kind == "rotctld" || kind == "rigctld" || kind == "satrak")
    return first.empty() ? kind : kind + " " + first;
  return kind;
}

}  // namespace tb::store
