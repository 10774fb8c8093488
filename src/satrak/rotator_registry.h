// The rotator registry: one table of the rotators --rotator names (simulated, hamlib, rotctld,
// satrak), each row with its spec form, what it is, its parser and its factory, so tracker_config
// reads one table instead of choosing a parser by prefix, build_station makes the driver the row
// names without asking which kind it is, and `trakbox --rotator list` prints it. The parsers and
// drivers stay with their modules (rotator/factory.h for simulated/hamlib/rotctld, satrak/client.h
// for a Satrak ACU); the table is here because it spans both.
#pragma once
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "rotator/factory.h"
#include "satrak/client.h"

namespace tb::app {

struct RotatorKind;

// A parsed --rotator: the row that read it, and what it read (a rotator driver spec, or another
// Satrak ACU).
struct RotatorChoice {
  const RotatorKind* kind = nullptr;
  std::optional<rotator::RotatorSpec> rotator;
  std::optional<satrak::SatrakRotatorOptions> satrak;
};

// What a factory may need beyond the spec: the station's clock and the simulated rotator's
// parameters (matching the configured limits).
struct RotatorContext {
  const station::Clock& clock;
  rotator::SimulatedRotatorParams simulated;
};

struct RotatorKind {
  std::string_view name;   // what --rotator takes before the first ':'
  std::string_view form;   // "hamlib:MODEL:DEVICE[:BAUD]"
  std::string_view what;
  // Fills choice, or returns what is wrong.
  std::optional<std::string> (*parse)(std::string_view text, RotatorChoice& choice);
  // The driver for a choice this row parsed.
  std::unique_ptr<rotator::RotatorDriver> (*make)(const RotatorChoice& choice, const RotatorContext& context);
};

std::span<const RotatorKind> rotator_kinds();

struct RotatorParse {
  RotatorChoice choice;
  std::string error;   // set when nothing was chosen
};
RotatorParse parse_rotator(std::string_view text);

// The driver for a parsed choice, by its row's factory.
std::unique_ptr<rotator::RotatorDriver> make_rotator(const RotatorChoice& choice, const RotatorContext& context);

// `trakbox --rotator list`.
std::string rotator_list_text();

}  // namespace tb::app
