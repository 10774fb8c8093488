#include "radio/factory.h"

#include <charconv>
#include <vector>

#include "radio/hamlib/hamlib_models.h"
#include "radio/two_radios.h"
#include "util/host_port.h"
#include "util/text.h"

namespace tb::radio {

namespace {

// The ':'-separated fields of a spec after its name, as strings (none for an empty rest).
std::vector<std::string> fields(std::string_view rest) {
  if (rest.empty()) return {};
  const auto parts = text::split(rest, ':');
  return {parts.begin(), parts.end()};
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

// gqrx[:HOST[:PORT]]: the row's port unless given, on this computer unless named.
RadioSpecParse receiver_spec(const RadioModel& m, const std::string& rest, const std::string& quoted, RadioSpec spec) {
  spec.host = "127.0.0.1";
  spec.port = m.port;
  if (rest.empty()) return {spec, {}};
  std::string why;
  const auto hp = inet::parse_host_port(rest, why, m.port);
  if (!hp) return error(quoted + why + "; expected " + spec_form(m));
  spec.host = inet::host_text(hp->host);
  spec.port = hp->port;
  return {spec, {}};
}

// flex[:HOST[:PORT]][:duplex]: ":duplex" last (an IPv6 HOST is in brackets), then as a receiver's.
RadioSpecParse flex_spec(const RadioModel& m, std::string rest, const std::string& quoted, RadioSpec spec) {
  constexpr std::string_view kDuplex = "duplex";
  if (rest == kDuplex || (rest.size() > kDuplex.size() && rest.ends_with(":duplex"))) {
    spec.full_duplex = true;
    rest.resize(rest == kDuplex ? 0 : rest.size() - kDuplex.size() - 1);
  }
  return receiver_spec(m, rest, quoted, std::move(spec));
}

}  // namespace

RadioSpecParse parse_radio_spec(std::string_view text, std::string_view option) {
  const std::string quoted = std::string(option) + " \"" + std::string(text) + "\": ";
  if (text.empty() || text == "sim" || text == "simulated") return {RadioSpec{}, {}};
  const std::size_t colon = text.find(':');
  const std::string kind(text.substr(0, colon));
  const std::string rest = colon == std::string_view::npos ? "" : std::string(text.substr(colon + 1));
  const RadioModel* m = find_radio_model(kind);
  if (!m) return error(quoted + "unknown radio \"" + kind + "\"; expected one of " + radio_model_names() +
                       " (trakbox --radio list shows their forms, e.g. ic9700:/dev/ttyUSB0 or rigctld:HOST:PORT)");
  RadioSpec spec;
  spec.name = std::string(m->name);

  switch (m->form) {
    case SpecForm::none:
      if (!rest.empty() || colon != std::string_view::npos) return error(quoted + kind + " takes no device");
      return {spec, {}};
    case SpecForm::device:
      if (rest.empty()) return error(quoted + "expected " + kind + ":DEVICE, e.g. " + kind + ":/dev/ttyUSB0");
      spec.device = rest;
      return {spec, {}};
    case SpecForm::device_baud: {
      const std::string usage = "expected " + spec_form(*m) + ", e.g. " + kind + ":/dev/ttyUSB0";
      std::vector<std::string> parts = fields(rest);
      if (!parts.empty() && parts.back() == "xvtr") {
        if (m->xvtr_from == 0)
          return error(quoted + "\"xvtr\": the " + std::string(m->label) + " has no transverter band trakbox drives");
        spec.transverter = true;
        parts.pop_back();
      }
      if (!parts.empty() && (parts.back() == "maindown" || parts.back() == "mainup")) {
        if (m->satmode == SatCommand::kenwood_sa && parts.back() == "mainup")
          return error(quoted + "\"mainup\": the " + std::string(m->label) +
                       "'s satellite mode is driven with the downlink on Main (FA) and the uplink on Sub (FB) only");
        if (!m->caps.satellite_mode || (m->protocol != Protocol::icom && m->satmode != SatCommand::kenwood_sa))
          return error(quoted + "\"" + parts.back() + "\": the " + std::string(m->label) +
                       " has no Main/Sub satellite mode to choose bands for");
        spec.main_link = parts.back() == "maindown" ? Link::downlink : Link::uplink;
        parts.pop_back();
      }
      if (parts.empty() || parts[0].empty()) return error(quoted + "missing DEVICE; " + usage);
      if (parts.size() >= 2) {
        auto b = to_int(parts.back());
        if (!b) return error(quoted + "\"" + parts.back() + "\" is not a serial speed (nor maindown/mainup); " + usage);
        if (!is_baud(*b)) return error(quoted + "BAUD " + parts.back() + " is not a serial speed (300..230400)");
        spec.baud = *b;
        parts.pop_back();
      }
      if (parts.size() > 1) return error(quoted + "too many fields; " + usage);
      spec.device = parts[0];
      return {spec, {}};
    }
    case SpecForm::receiver: return receiver_spec(*m, rest, quoted, spec);
    case SpecForm::flex: return flex_spec(*m, rest, quoted, spec);
    case SpecForm::hamlib:
    case SpecForm::rigctld:
      break;
  }

  std::vector<std::string> parts = fields(rest);
  if (!parts.empty() && (parts.back() == "split" || parts.back() == "mainsub")) {
    spec.scheme = parts.back() == "split" ? HamlibVfoScheme::split : HamlibVfoScheme::main_sub;
    parts.pop_back();
  }
  if (m->form == SpecForm::rigctld) {
    std::string peer;   // HOST[:PORT] as given, the scheme taken off
    for (std::size_t i = 0; i < parts.size(); ++i) peer += (i ? ":" : "") + parts[i];
    spec.host = "127.0.0.1";
    spec.port = 4532;
    if (peer.empty()) return {spec, {}};
    std::string why;
    const auto hp = inet::parse_host_port(peer, why, 4532);
    if (!hp) return error(quoted + why + "; expected rigctld[:HOST[:PORT]][:split|:mainsub]");
    spec.host = inet::host_text(hp->host);   // Hamlib's pathname form
    spec.port = hp->port;
    return {spec, {}};
  }
  if (parts.size() < 2 || parts[1].empty())
    return error(quoted + "expected hamlib:MODEL:DEVICE[:BAUD], e.g. hamlib:3081:/dev/ttyUSB0:19200 or hamlib:IC-9700:/dev/ttyUSB0");
  if (auto model = to_int(parts[0])) {
    if (*model <= 0) return error(quoted + "model \"" + parts[0] + "\" is not a Hamlib model number (see rigctl -l)");
    spec.model = *model;
  } else {
    const HamlibModelLookup byname = hamlib_rig_by_name(parts[0]);
    if (!byname.model) return error(quoted + byname.error);
    spec.model = *byname.model;
  }
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

MakeRadio make_radio(const RadioSpec& spec, const RadioConfig& config, const DriverTiming& timing, RadioRole role) {
  const RadioModel* m = find_radio_model(spec.name);
  if (!m) return {nullptr, "no radio \"" + spec.name + "\" in the registry (trakbox --radio list)"};
  return m->make(*m, spec, config, timing, role);
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
  MakeRadio d = make_radio(down, config, timing, up ? RadioRole::downlink : RadioRole::both);
  if (!d.driver || !up) return d;
  MakeRadio u = make_radio(*up, config, timing, RadioRole::uplink);
  if (!u.driver) return {nullptr, "uplink radio: " + u.error};
  return {std::make_unique<TwoRadios>(std::move(d.driver), std::move(u.driver)), {}};
}

}  // namespace tb::radio
