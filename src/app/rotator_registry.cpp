#include "app/rotator_registry.h"

namespace tb::app {

namespace {

std::optional<std::string> parse_driver(std::string_view text, RotatorChoice& choice) {
  rotator::SpecResult r = rotator::parse_rotator_spec(text);
  if (!r.spec) return r.error;
  choice.rotator = r.spec;
  return std::nullopt;
}

std::optional<std::string> parse_satrak(std::string_view text, RotatorChoice& choice) {
  std::string error;
  choice.satrak = satrak::parse_rotator_spec(text, error);
  if (!choice.satrak) return error;
  return std::nullopt;
}

constexpr RotatorKind kKinds[] = {
    {"simulated", "simulated", "the simulated rotator (the default)", parse_driver},
    {"hamlib", "hamlib:MODEL:DEVICE[:BAUD]", "any rotator Hamlib drives (MODEL: rotctl -l)", parse_driver},
    {"rotctld", "rotctld:HOST[:PORT]", "a rotctld daemon (Hamlib NET rotctl; PORT 4533)", parse_driver},
    {"satrak", "satrak:HOST[:PORT]", "another Satrak ACU over its TCP protocol (PORT 4001)", parse_satrak},
};

}  // namespace

std::span<const RotatorKind> rotator_kinds() { return kKinds; }

RotatorParse parse_rotator(std::string_view text) {
  const std::string_view name = text.substr(0, text.find(':'));
  for (const RotatorKind& k : kKinds) {
    if (k.name != name) continue;
    RotatorParse out;
    if (auto e = k.parse(text, out.choice)) return {{}, *e};
    return out;
  }
  std::string forms;
  for (const RotatorKind& k : kKinds) forms += (forms.empty() ? "" : ", ") + std::string(k.form);
  return {{}, "bad --rotator '" + std::string(text) + "': unknown rotator '" + std::string(name) + "'; expected " +
                  forms + " (trakbox --rotator list)"};
}

std::string rotator_list_text() {
  std::string out = "rotator spec                 rotator\n";
  for (const RotatorKind& k : kKinds) {
    std::string form(k.form);
    form.resize(std::max<std::size_t>(form.size(), 28), ' ');
    out += form + " " + std::string(k.what) + "\n";
  }
  return out;
}

}  // namespace tb::app
