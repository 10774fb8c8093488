#include "radio/factory.h"

#include <charconv>
#include <vector>

#include "radio/cat_links.h"
#include "radio/simulated.h"
#include "radio/two_radios.h"
#include "util/text.h"

namespace tb::radio {

namespace {

constexpr const char* kForms =
    "sim, icom:DEVICE, kenwood:DEVICE, yaesu:DEVICE, cat:DEVICE, "
    "hamlib:MODEL:DEVICE[:BAUD] or rigctld:HOST:PORT";

std::vector<std::string> split(std::string_view s, char sep) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t p = s.find(sep, start);
    out.emplace_back(s.substr(start, p == std::string_view::npos ? std::string_view::npos : p - start));
    if (p == std::string_view::npos) break;
    start = p + 1;
  }
  return out;
}

// Digits only, as the spec forms print them ("+9600" is not a speed).
std::optional<int> to_int(std::string_view s) {
  if (!s.empty() && s.front() == '+') return std::nullopt;
  return text::parse_integer<int>(s);
}

bool is_baud(int v) {
  for (int b : {300, 600, 1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400})
    if (v == b) return true;
  return false;
}

RadioSpecParse error(std::string message) { return {std::nullopt, std::move(message)}; }

}  // namespace

RadioSpecParse parse_radio_spec(std::string_view text, std::string_view option) {
  const std::string quoted = std::string(option) + " \"" + std::string(text) + "\": ";
  if (text.empty() || text == "sim" || text == "simulated") return {RadioSpec{}, {}};
  const std::size_t colon = text.find(':');
  const std::string kind(text.substr(0, colon));
  const std::string rest = colon == std::string_view::npos ? "" : std::string(text.substr(colon + 1));
  RadioSpec spec;

  auto serial = [&](RadioSpec::Kind k) -> RadioSpecParse {
    if (rest.empty()) return error(quoted + "expected " + kind + ":DEVICE, e.g. " + kind + ":/dev/ttyUSB0");
    spec.kind = k;
    spec.device = rest;
    return {spec, {}};
  };
  if (kind == "icom") return serial(RadioSpec::Kind::icom);
  if (kind == "kenwood") return serial(RadioSpec::Kind::kenwood);
  if (kind == "yaesu") return serial(RadioSpec::Kind::yaesu);
  if (kind == "cat") return serial(RadioSpec::Kind::cat);

  if (kind == "hamlib" || kind == "rigctld") {
    std::vector<std::string> parts = rest.empty() ? std::vector<std::string>{} : split(rest, ':');
    if (!parts.empty() && (parts.back() == "split" || parts.back() == "mainsub")) {
      spec.scheme = parts.back() == "split" ? HamlibVfoScheme::split : HamlibVfoScheme::main_sub;
      parts.pop_back();
    }
    if (kind == "rigctld") {
      spec.kind = RadioSpec::Kind::rigctld;
      if (parts.size() > 2) return error(quoted + "expected rigctld:HOST:PORT");
      spec.host = parts.size() >= 1 && !parts[0].empty() ? parts[0] : "127.0.0.1";
      spec.port = 4532;
      if (parts.size() == 2) {
        auto p = to_int(parts[1]);
        if (!p || *p <= 0 || *p > 65535)
          return error(quoted + "port \"" + parts[1] + "\" is not a TCP port (1-65535)");
        spec.port = *p;
      }
      return {spec, {}};
    }
    spec.kind = RadioSpec::Kind::hamlib;
    if (parts.size() < 2 || parts[1].empty())
      return error(quoted + "expected hamlib:MODEL:DEVICE[:BAUD], e.g. hamlib:3073:/dev/ttyUSB0:19200");
    auto model = to_int(parts[0]);
    if (!model || *model <= 0)
      return error(quoted + "model \"" + parts[0] + "\" is not a Hamlib model number (see rigctl -l)");
    spec.model = *model;
    if (parts.size() >= 3) {
      if (auto b = to_int(parts.back()); b && is_baud(*b)) {
        spec.baud = *b;
        parts.pop_back();
      } else if (b && !parts[1].empty() && parts[1][0] == '/') {
        // After a device path a number can only be a speed; after a host name it is the port.
        return error(quoted + "\"" + parts.back() + "\" is not a serial speed");
      }
    }
    // What is left is the device (it may itself hold ':' for a network backend).
    for (std::size_t i = 1; i < parts.size(); ++i) spec.device += (i > 1 ? ":" : "") + parts[i];
    return {spec, {}};
  }
  return error(quoted + "unknown radio \"" + kind + "\"; expected " + kForms);
}

MakeRadio make_radio(const RadioSpec& spec, const RadioConfig& config, const DriverTiming& timing) {
  MakeRadio out;
  RadioSpec::Kind kind = spec.kind;
  if (kind == RadioSpec::Kind::cat) {
    switch (config.rig) {
      case Rig::icom: kind = RadioSpec::Kind::icom; break;
      case Rig::kenwood: kind = RadioSpec::Kind::kenwood; break;
      case Rig::yaesu: kind = RadioSpec::Kind::yaesu; break;
      case Rig::none:
        out.error = "--radio cat:" + spec.device +
                    ": no CAT rig is configured (menu 6-7: choose Kenwood, Yaesu or Icom)";
        return out;
    }
  }
  switch (kind) {
    case RadioSpec::Kind::simulated:
      out.driver = std::make_unique<SimulatedRadio>();
      break;
    case RadioSpec::Kind::icom:
      out.driver = make_icom_radio(spec.device, IcomOptions::from(config), timing.worker);
      break;
    case RadioSpec::Kind::kenwood:
      out.driver = make_kenwood_radio(spec.device, KenwoodOptions::from(config), timing.worker);
      break;
    case RadioSpec::Kind::yaesu: {
      YaesuOptions o = YaesuOptions::from(config);
      o.byte_gap = timing.yaesu_byte_gap;
      out.driver = make_yaesu_radio(spec.device, o, timing.worker);
      break;
    }
    case RadioSpec::Kind::hamlib: {
      if (hamlib_model_name(spec.model).empty()) {
        out.error = "--radio hamlib:" + std::to_string(spec.model) +
                    ": Hamlib has no rig model " + std::to_string(spec.model) + " (see rigctl -l)";
        return out;
      }
      out.driver = make_hamlib_radio({spec.model, spec.device, spec.baud, spec.scheme}, timing.worker);
      break;
    }
    case RadioSpec::Kind::rigctld:
      out.driver = make_hamlib_radio(
          {2, spec.host + ":" + std::to_string(spec.port), 0, spec.scheme}, timing.worker);
      break;
    case RadioSpec::Kind::cat:
      break;
  }
  return out;
}

MakeRadio make_radio(std::string_view text, const RadioConfig& config, const DriverTiming& timing) {
  auto parsed = parse_radio_spec(text);
  if (!parsed.spec) return {nullptr, parsed.error};
  return make_radio(*parsed.spec, config, timing);
}

}  // namespace tb::radio

namespace tb::radio {

MakeRadio make_radios(const RadioSpec& down, const std::optional<RadioSpec>& up, const RadioConfig& config,
                      const DriverTiming& timing) {
  MakeRadio d = make_radio(down, config, timing);
  if (!d.driver || !up) return d;
  MakeRadio u = make_radio(*up, config, timing);
  if (!u.driver) return {nullptr, "uplink radio: " + u.error};
  return {std::make_unique<TwoRadios>(std::move(d.driver), std::move(u.driver)), {}};
}

}  // namespace tb::radio
