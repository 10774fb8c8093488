#include "rotator/registry.h"

#include <algorithm>

#include <fmt/format.h>

#include "util/text.h"

namespace tb::rotator {

namespace {

template <SpecResult (*Parse)(std::string_view)>
std::optional<std::string> parse_driver(std::string_view text, RotatorChoice& choice) {
  SpecResult r = Parse(text);
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

std::unique_ptr<RotatorDriver> make_simulated(const RotatorChoice& choice, const RotatorContext& c) {
  SimulatedRotatorParams p = c.simulated;
  if (choice.rotator) {  // simulated:mount=AZ,EL
    p.mount_az_deg = choice.rotator->mount_az_deg;
    p.mount_el_deg = choice.rotator->mount_el_deg;
  }
  return make_simulated_rotator(c.clock, p);
}

std::unique_ptr<RotatorDriver> make_hamlib(const RotatorChoice& choice, const RotatorContext&) {
  return make_hamlib_rotator(*choice.rotator);
}

std::unique_ptr<RotatorDriver> make_easycomm(const RotatorChoice& choice, const RotatorContext&) {
  return make_easycomm_rotator(*choice.rotator);
}

std::unique_ptr<RotatorDriver> make_pst(const RotatorChoice& choice, const RotatorContext&) {
  return make_pst_rotator(*choice.rotator);
}

std::unique_ptr<RotatorDriver> make_satrak(const RotatorChoice& choice, const RotatorContext&) {
  return std::make_unique<satrak::SatrakRotator>(*choice.satrak);
}

constexpr RotatorKind kKinds[] = {
    {.name = "simulated", .form = "simulated[:mount=AZ,EL]", .what = "the simulated rotator (the default)", .link = "none",
     .defaults = "-", .reads = "ADC counts (10 bit)", .parse = parse_driver<parse_simulated_spec>,
     .make = make_simulated},
    {.name = "hamlib", .form = "hamlib:MODEL:DEVICE[:BAUD]", .what = "any rotator Hamlib drives (MODEL: rotctl -l)",
     .link = "Hamlib", .defaults = "the backend's", .reads = "az/el", .parse = parse_driver<parse_hamlib_spec>,
     .make = make_hamlib},
    {.name = "rotctld", .form = "rotctld:HOST[:PORT]", .what = "a rotctld daemon (Hamlib NET rotctl)", .link = "TCP",
     .defaults = "port 4533", .reads = "az/el", .parse = parse_driver<parse_rotctld_spec>, .make = make_hamlib},
    {.name = "easycomm3", .form = "easycomm3:DEVICE[:BAUD]", .what = "Easycomm III natively (SatNOGS rotator)",
     .link = "serial", .defaults = "19200 baud", .reads = "az/el, alarms", .parse = parse_driver<parse_easycomm_spec>,
     .make = make_easycomm},
    {.name = "easycomm2", .form = "easycomm2:DEVICE[:BAUD]", .what = "Easycomm II natively (SARCNET, REF, K3NG)",
     .link = "serial", .defaults = "9600 baud", .reads = "az/el", .parse = parse_driver<parse_easycomm_spec>,
     .make = make_easycomm},
    {.name = "pstrotator", .form = "pstrotator:HOST[:PORT]", .what = "PstRotator's UDP (CSN S.A.T.)", .link = "UDP",
     .defaults = "port 12000, replies 12001", .reads = "az/el", .parse = parse_driver<parse_pstrotator_spec>,
     .make = make_pst},
    {.name = "satrak", .form = "satrak:HOST[:PORT]", .what = "another Satrak ACU", .link = "TCP",
     .defaults = "port 4001", .reads = "az/el, limits, motion", .parse = parse_satrak, .make = make_satrak},
};

}  // namespace

std::span<const RotatorKind> rotator_kinds() { return kKinds; }

RotatorParse parse_rotator(std::string_view text) {
  const std::string_view name = text.substr(0, text.find(':'));
  // The kind in any case ("Hamlib:603:...", as --radio takes "IC9700:..."); parsed as written lower.
  const std::string lower = text::lower(name);
  const std::string spelled = lower + std::string(text.substr(name.size()));
  for (const RotatorKind& k : kKinds) {
    if (k.name != lower) continue;
    RotatorParse out;
    if (auto e = k.parse(spelled, out.choice)) return {{}, *e};
    out.choice.kind = &k;
    return out;
  }
  std::string forms;
  for (const RotatorKind& k : kKinds) forms += (forms.empty() ? "" : ", ") + std::string(k.form);
  return {{}, "bad --rotator '" + std::string(text) + "': unknown rotator '" + std::string(name) + "'; expected " +
                  forms + " (trakbox --rotator list)"};
}

std::unique_ptr<RotatorDriver> make_rotator(const RotatorChoice& choice, const RotatorContext& context) {
  const RotatorKind& kind = choice.kind ? *choice.kind : kKinds[0];   // nothing chosen: the simulated one
  return kind.make(choice, context);
}

std::string rotator_list_text() {
  // Two lines a row, within 80 columns: the form and what it is; then its link, the protocol's
  // defaults and what trakbox reads back from it.
  std::string out = "rotator spec                 rotator\n";
  for (const RotatorKind& k : kKinds)
    out += fmt::format("{:<28} {}\n{:<28} {}{}; reads back {}\n", k.form, k.what, "", k.link,
                       k.defaults == "-" ? std::string() : ", " + std::string(k.defaults), k.reads);
  // The controllers most stations own, by Hamlib's number (rotctl -l, Hamlib 4.5) for hamlib:MODEL.
  out += "\nHamlib's numbers (hamlib:MODEL:DEVICE[:BAUD]) of common controllers:\n"
         "  GS-232A 601, GS-232B 603 (az only 611), SPID Rot2Prog 901, Rot1Prog 902,\n"
         "  SPID MD-01/02 in Rot2Prog mode 903, Easycomm I 201, II 202, III 204;\n"
         "  a K3NG controller answers GS-232B (603) and Easycomm (202, 204).\n";
  return out;
}

}  // namespace tb::rotator
