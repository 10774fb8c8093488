#include "rotator/factory.h"

#include <hamlib/rotator.h>

#include <algorithm>
#include <charconv>
#include <vector>

#include "util/text.h"

namespace tb::rotator {

namespace {

constexpr const char* kExpected = "expected simulated, hamlib:MODEL:DEVICE[:BAUD] or rotctld:HOST[:PORT]";
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

SpecResult parse_hamlib(std::string_view text, std::string_view rest) {
  const std::string usage = "expected hamlib:MODEL:DEVICE[:BAUD], e.g. hamlib:603:/dev/ttyUSB0:9600";
  auto f = text::split(rest, ':');
  if (rest.empty() || f[0].empty()) return fail(text, "missing MODEL; " + usage);
  auto model = number(f[0]);
  if (!model) return fail(text, "MODEL '" + std::string(f[0]) + "' is not a Hamlib model number (see `rotctl -l`); " + usage);
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
  }
  for (std::size_t i = 1; i < dev_end; ++i) s.device += (i > 1 ? ":" : "") + std::string(f[i]);
  if (!hamlib_rotator_model_exists(s.model))
    return fail(text, "Hamlib has no rotator model " + std::to_string(s.model) + " (see `rotctl -l`)");
  return {s, {}};
}

SpecResult parse_rotctld(std::string_view text, std::string_view rest) {
  const std::string usage = "expected rotctld:HOST[:PORT], e.g. rotctld:localhost:4533";
  RotatorSpec s;
  s.kind = RotatorSpec::Kind::rotctld;
  s.model = ROT_MODEL_NETROTCTL;
  std::string_view host, port;
  if (!rest.empty() && rest.front() == '[') {  // [IPv6]:PORT
    auto close = rest.find(']');
    if (close == std::string_view::npos) return fail(text, "unclosed '[' in the host; " + usage);
    host = rest.substr(0, close + 1);
    std::string_view after = rest.substr(close + 1);
    if (!after.empty()) {
      if (after.front() != ':') return fail(text, "expected ':' after ']'; " + usage);
      port = after.substr(1);
      if (port.empty()) return fail(text, "empty PORT; " + usage);
    }
  } else {
    auto f = text::split(rest, ':');
    if (f.size() > 2) return fail(text, "too many ':' (an IPv6 address goes in brackets); " + usage);
    host = f[0];
    if (f.size() == 2) {
      port = f[1];
      if (port.empty()) return fail(text, "empty PORT; " + usage);
    }
  }
  if (host.empty() || host == "[]") return fail(text, "missing HOST; " + usage);
  s.host = std::string(host);
  s.port = 4533;
  if (!port.empty()) {
    auto p = number(port);
    if (!p || *p < 1 || *p > 65535) return fail(text, "PORT '" + std::string(port) + "' is not a TCP port (1..65535)");
    s.port = *p;
  }
  s.device = s.host + ":" + std::to_string(s.port);
  return {s, {}};
}

}  // namespace

SpecResult parse_rotator_spec(std::string_view text) {
  if (text.empty()) return fail(text, std::string("empty; ") + kExpected);
  auto colon = text.find(':');
  std::string_view kind = text.substr(0, colon);
  std::string_view rest = colon == std::string_view::npos ? std::string_view{} : text.substr(colon + 1);
  if (kind == "simulated") {
    if (colon != std::string_view::npos) return fail(text, "simulated takes no parameters");
    return {RotatorSpec{}, {}};
  }
  if (kind == "hamlib") return parse_hamlib(text, rest);
  if (kind == "rotctld") return parse_rotctld(text, rest);
  return fail(text, "unknown rotator '" + std::string(kind) + "'; " + kExpected);
}

std::string to_string(const RotatorSpec& s) {
  switch (s.kind) {
    case RotatorSpec::Kind::simulated: return "simulated";
    case RotatorSpec::Kind::hamlib:
      return "hamlib:" + std::to_string(s.model) + ":" + s.device + (s.baud ? ":" + std::to_string(s.baud) : "");
    case RotatorSpec::Kind::rotctld: return "rotctld:" + s.host + ":" + std::to_string(s.port);
  }
  return "simulated";
}

std::unique_ptr<RotatorDriver> make_rotator(const RotatorSpec& spec, const station::Clock& clock,
                                            const SimulatedRotatorParams& sim, HamlibOptions hamlib) {
  if (spec.kind == RotatorSpec::Kind::simulated) return std::make_unique<SimulatedRotator>(clock, sim);
  hamlib.model = spec.model;
  hamlib.pathname = spec.device;
  hamlib.baud = spec.baud;
  return std::make_unique<HamlibRotator>(std::move(hamlib));
}

}  // namespace tb::rotator
