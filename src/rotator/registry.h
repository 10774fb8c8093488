// The rotator registry, laid out as the radios' (radio/registry.h): one row per kind `--rotator`
// names (simulated, hamlib, rotctld, easycomm3, easycomm2, pstrotator, satrak), each with its
// spec form, what it is, what it reads back, its link and the protocol's defaults, its parser and
// its factory. tracker_config reads one table instead of choosing a parser by prefix, the station
// makes the driver the row names without asking which kind it is, and `trakbox --rotator list`
// prints the table. The codecs and links stay with their families (rotator/easycomm/,
// rotator/pst/, rotator/satrak/, rotator/hamlib.h).
#pragma once
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "rotator/factory.h"
#include "rotator/satrak/client.h"

namespace tb::rotator {

struct RotatorKind;

// A parsed --rotator: the row that read it, and what it read (a rotator driver spec, or another
// Satrak ACU).
struct RotatorChoice {
  const RotatorKind* kind = nullptr;
  std::optional<RotatorSpec> rotator;
  std::optional<satrak::SatrakRotatorOptions> satrak;
};

// What a factory may need beyond the spec: the station's clock and the simulated rotator's
// parameters (matching the configured limits).
struct RotatorContext {
  const station::Clock& clock;
  SimulatedRotatorParams simulated;
};

struct RotatorKind {
  std::string_view name;       // what --rotator takes before the first ':'
  std::string_view form;       // "hamlib:MODEL:DEVICE[:BAUD]"
  std::string_view what;
  // Capabilities, as --rotator list shows them.
  std::string_view link;       // "serial", "TCP", "UDP", "Hamlib" (the backend's port), "none"
  std::string_view defaults;   // the protocol's: "19200 baud", "port 4533"
  std::string_view reads;      // what is read back: "az/el", "az/el, limits", "ADC counts"
  // Fills choice, or returns what is wrong.
  std::optional<std::string> (*parse)(std::string_view text, RotatorChoice& choice);
  // The driver for a choice this row parsed.
  std::unique_ptr<RotatorDriver> (*make)(const RotatorChoice& choice, const RotatorContext& context);
};

std::span<const RotatorKind> rotator_kinds();

struct RotatorParse {
  RotatorChoice choice;
  std::string error;   // set when nothing was chosen
};
RotatorParse parse_rotator(std::string_view text);

// The driver for a parsed choice, by its row's factory.
std::unique_ptr<RotatorDriver> make_rotator(const RotatorChoice& choice, const RotatorContext& context);

// `trakbox --rotator list`.
std::string rotator_list_text();

}  // namespace tb::rotator
