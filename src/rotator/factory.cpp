#include "rotator/factory.h"

#include <hamlib/rotator.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "rotator/easycomm_rotator.h"
#include "rotator/pst/link.h"
#include "rotator/hamlib.h"
#include "util/exact_number.h"
#include "util/host_port.h"
#include "util/text.h"

namespace tb::rotator {

namespace {

constexpr int kBauds[] = {300, 600, 1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400};

std::optional<int> number(std::string_view s) {
  if (s.empty() || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; })) return std::nullopt;
  int v = 0;
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || p != s.data() + s.size()) return std::nullopt;
  return v;
}

SpecResult fail(std::string_view text, std::string why) {
  return {std::nullopt, "bad --rotator '" + std::string(text) + "': " + why};
}

// What follows "NAME:" ("" when nothing does).
std::string_view after_name(std::string_view text) {
  const auto colon = text.find(':');
  return colon == std::string_view::npos ? std::string_view{} : text.substr(colon + 1);
}

}  // namespace

SpecResult parse_hamlib_spec(std::string_view text) {
  const std::string_view rest = after_name(text);
  const std::string usage = "expected hamlib:MODEL:DEVICE[:BAUD], e.g. hamlib:603:/dev/ttyUSB0:9600";
  auto f = text::split(rest, ':');
  if (rest.empty() || f[0].empty()) return fail(text, "missing MODEL; " + usage);
  auto model = number(f[0]);
  if (!model) model = hamlib_rotator_model_by_name(f[0]);   // hamlib:GS-232B, as for radios
  if (!model)
    return fail(text, "MODEL '" + std::string(f[0]) + "' is neither a Hamlib rotator model number nor the name of one "
                      "(see `rotctl -l`); " + usage);
  if (f.size() < 2 || f[1].empty()) return fail(text, "missing DEVICE; " + usage);
  RotatorSpec s;
  s.kind = RotatorSpec::Kind::hamlib;
  s.model = *model;
  std::size_t dev_end = f.size();
  if (f.size() >= 3 && number(f.back())) {
    int baud = *number(f.back());
    if (std::find(std::begin(kBauds), std::end(kBauds), baud) == std::end(kBauds))
      return fail(text, "BAUD " + std::to_string(baud) +
                            " is not a serial speed (300..230400); for a rotctld use rotctld:HOST:PORT");
    s.baud = baud;
    dev_end = f.size() - 1;
  } else if (f.size() >= 3 && f.back().empty()) {
    return fail(text, "empty BAUD; " + usage);
  } else if (f.size() >= 4 && number(f[f.size() - 2])) {
    // DEVICE:9600:x: something after the speed is no part of the device.
    return fail(text, "'" + std::string(f.back()) + "' after BAUD " + std::string(f[f.size() - 2]) + "; " + usage);
  }
  for (std::size_t i = 1; i < dev_end; ++i) s.device += (i > 1 ? ":" : "") + std::string(f[i]);
  if (!hamlib_rotator_model_exists(s.model))
    return fail(text, "Hamlib has no rotator model " + std::to_string(s.model) + " (see `rotctl -l`)");
  return {s, {}};
}

SpecResult parse_rotctld_spec(std::string_view text) {
  std::string why;
  const auto hp = inet::parse_host_port(after_name(text), why, 4533);
  if (!hp) return fail(text, why + "; expected rotctld:HOST[:PORT], e.g. rotctld:localhost:4533");
  RotatorSpec s;
  s.kind = RotatorSpec::Kind::rotctld;
  s.model = ROT_MODEL_NETROTCTL;
  s.host = inet::host_text(hp->host);   // Hamlib's pathname form
  s.port = hp->port;
  s.device = s.host + ":" + std::to_string(s.port);
  return {s, {}};
}

SpecResult parse_easycomm_spec(std::string_view text) {
  const std::string_view name = text.substr(0, text.find(':'));
  const bool three = name == "easycomm3";
  const std::string usage = "expected " + std::string(name) + ":DEVICE[:BAUD], e.g. " + std::string(name) +
                            ":/dev/ttyUSB0" + (three ? ":19200" : ":9600");
  const std::string_view rest = after_name(text);
  auto f = text::split(rest, ':');
  if (rest.empty() || f[0].empty()) return fail(text, "missing DEVICE; " + usage);
  RotatorSpec s;
  s.kind = three ? RotatorSpec::Kind::easycomm3 : RotatorSpec::Kind::easycomm2;
  s.model = three ? 204 : 202;   // Hamlib's number of the same protocol, for the record
  if (f.size() > 2) return fail(text, "too many fields; " + usage);
  if (f.size() == 2) {
    const auto baud = number(f[1]);
    if (!baud || std::find(std::begin(kBauds), std::end(kBauds), *baud) == std::end(kBauds) || *baud < 1200 || *baud > 115200)
      return fail(text, "BAUD '" + std::string(f[1]) + "' is not a serial speed (1200..115200); " + usage);
    s.baud = *baud;
  }
  s.device = std::string(f[0]);
  return {s, {}};
}

SpecResult parse_pstrotator_spec(std::string_view text) {
  std::string why;
  const auto hp = inet::parse_host_port(after_name(text), why, 12000);
  if (!hp) return fail(text, why + "; expected pstrotator:HOST[:PORT], e.g. pstrotator:192.168.1.20:12000");
  if (hp->port >= 65535) return fail(text, "PORT " + std::to_string(hp->port) + ": its replies come to PORT+1, so at most 65534");
  RotatorSpec s;
  s.kind = RotatorSpec::Kind::pstrotator;
  s.host = inet::host_text(hp->host);
  s.port = hp->port;
  s.device = s.host + ":" + std::to_string(s.port);
  return {s, {}};
}

SpecResult parse_simulated_spec(std::string_view text) {
  if (text == "simulated") return {RotatorSpec{}, {}};
  const std::string usage =
      "expected simulated or simulated:mount=AZ,EL (a mounting error in degrees: the rotator reads that much more "
      "than where the antenna points), e.g. simulated:mount=2.0,-1.0";
  constexpr std::string_view kMount = "simulated:mount=";
  if (text.rfind(kMount, 0) != 0) return fail(text, usage);
  const auto f = text::split(text.substr(kMount.size()), ',');
  const auto az = f.size() == 2 ? text::parse_double(f[0]) : std::nullopt;
  const auto el = f.size() == 2 ? text::parse_double(f[1]) : std::nullopt;
  if (!az || !el || std::abs(*az) > limits::kSkyOffsetMaxDeg || std::abs(*el) > limits::kSkyOffsetMaxDeg)
    return fail(text, usage + fmt::format(", each within {:.0f} deg", limits::kSkyOffsetMaxDeg));
  RotatorSpec s;
  s.mount_az_deg = *az;
  s.mount_el_deg = *el;
  return {s, {}};
}

std::string to_string(const RotatorSpec& s) {
  switch (s.kind) {
    case RotatorSpec::Kind::simulated:
      if (s.mount_az_deg == 0.0 && s.mount_el_deg == 0.0) return "simulated";
      return "simulated:mount=" + text::exact_number(s.mount_az_deg) + "," + text::exact_number(s.mount_el_deg);
    case RotatorSpec::Kind::hamlib:
      return "hamlib:" + std::to_string(s.model) + ":" + s.device + (s.baud ? ":" + std::to_string(s.baud) : "");
    case RotatorSpec::Kind::rotctld: return "rotctld:" + s.host + ":" + std::to_string(s.port);
    case RotatorSpec::Kind::pstrotator: return "pstrotator:" + s.host + ":" + std::to_string(s.port);
    case RotatorSpec::Kind::easycomm2:
    case RotatorSpec::Kind::easycomm3:
      return std::string(s.kind == RotatorSpec::Kind::easycomm3 ? "easycomm3:" : "easycomm2:") + s.device +
             (s.baud ? ":" + std::to_string(s.baud) : "");
  }
  return "simulated";
}

std::unique_ptr<RotatorDriver> make_simulated_rotator(const station::Clock& clock, const SimulatedRotatorParams& sim) {
  return std::make_unique<SimulatedRotator>(clock, sim);
}

std::unique_ptr<RotatorDriver> make_easycomm_rotator(const RotatorSpec& spec) {
  EasycommOptions o;
  o.version = spec.kind == RotatorSpec::Kind::easycomm3 ? easycomm::Version::three : easycomm::Version::two;
  o.device = spec.device;
  o.baud = spec.baud;
  return std::make_unique<EasycommRotator>(o);
}

std::unique_ptr<RotatorDriver> make_pst_rotator(const RotatorSpec& spec) {
  PstRotatorOptions o;
  o.host = spec.host;
  o.port = spec.port;
  return std::make_unique<PstRotator>(o);
}

std::unique_ptr<RotatorDriver> make_hamlib_rotator(const RotatorSpec& spec, HamlibOptions hamlib) {
  hamlib.model = spec.model;
  hamlib.pathname = spec.device;
  hamlib.baud = spec.baud;
  return std::make_unique<HamlibRotator>(std::move(hamlib));
}

}  // namespace tb::rotator
