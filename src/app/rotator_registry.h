// The rotator registry: one table of the rotators --rotator names (simulated, hamlib, rotctld,
// satrak), each with its spec form, what it is and its parser, so tracker_config reads one table
// instead of choosing a parser by prefix, and `trakbox --rotator list` prints it. The parsers stay
// with their drivers (rotator/factory.h for simulated/hamlib/rotctld, satrak/client.h for a Satrak
// ACU); the table is here because it spans both modules.
#pragma once
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "rotator/factory.h"
#include "satrak/client.h"

namespace tb::app {

// A parsed --rotator: a rotator driver spec, or another Satrak ACU.
struct RotatorChoice {
  std::optional<rotator::RotatorSpec> rotator;
  std::optional<satrak::SatrakRotatorOptions> satrak;
};

struct RotatorKind {
  std::string_view name;   // what --rotator takes before the first ':'
  std::string_view form;   // "hamlib:MODEL:DEVICE[:BAUD]"
  std::string_view what;
  // Fills choice, or returns what is wrong.
  std::optional<std::string> (*parse)(std::string_view text, RotatorChoice& choice);
};

std::span<const RotatorKind> rotator_kinds();

struct RotatorParse {
  RotatorChoice choice;
  std::string error;   // set when nothing was chosen
};
RotatorParse parse_rotator(std::string_view text);

// `trakbox --rotator list`.
std::string rotator_list_text();

}  // namespace tb::app
