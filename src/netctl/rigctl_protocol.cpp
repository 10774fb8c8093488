#include "netctl/rigctl_protocol.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>

#include "radio/doppler.h"
#include "tracker/operations.h"

namespace tb::netctl {

namespace {
enum Id {
  kSetFreq, kGetFreq, kSetMode, kGetMode, kSetVfo, kGetVfo, kSetSplitVfo, kGetSplitVfo, kSetSplitFreq,
  kGetSplitFreq, kSetSplitMode, kGetSplitMode, kSetPtt, kGetPtt, kGetInfo, kChkVfo, kDumpState, kDumpCaps,
  kGetPowerstat, kGetLockMode,
};

bool iequal(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

// A VFO token: the link it names and how `v` reports it. Nothing for the current VFO.
struct VfoToken {
  bool current = false;
  radio::Link link = radio::Link::downlink;
  const char* name = "VFOA";
};
std::optional<VfoToken> parse_vfo(std::string_view s) {
  using radio::Link;
  struct Entry {
    const char* token;
    VfoToken vfo;
  };
  static const Entry entries[] = {
      {"VFOA", {false, Link::downlink, "VFOA"}}, {"Main", {false, Link::downlink, "Main"}},
      {"MainA", {false, Link::downlink, "Main"}}, {"RX", {false, Link::downlink, "VFOA"}},
      {"VFOB", {false, Link::uplink, "VFOB"}},   {"Sub", {false, Link::uplink, "Sub"}},
      {"SubA", {false, Link::uplink, "Sub"}},     {"TX", {false, Link::uplink, "VFOB"}},
      {"currVFO", {true, Link::downlink, ""}},    {"VFO", {true, Link::downlink, ""}},
  };
  for (const Entry& e : entries)
    if (iequal(s, e.token)) return e.vfo;
  return std::nullopt;
}

// Hamlib's mode tokens trakbox's radios take.
std::optional<radio::Mode> parse_hamlib_mode(std::string_view s) {
  const auto m = radio::parse_mode(s);
  if (!m || *m == radio::Mode::none) return std::nullopt;
  return m;
}

// Hamlib's RIG_MODE_* bits for trakbox's modes: CW 0x2, USB 0x4, LSB 0x8, FM 0x20.
constexpr const char* kModeMask = "0x2e";
// RIG_VFO_A | RIG_VFO_B.
constexpr const char* kVfoMask = "0x3";

std::string hz_text(radio::Hz hz) { return std::to_string(hz); }

std::optional<radio::Hz> parse_hz(std::string_view s) {
  const auto v = parse_double(s);
  if (!v) return std::nullopt;
  const double r = std::round(*v);
  if (r < static_cast<double>(RigctlProtocol::kMinHz) || r > static_cast<double>(RigctlProtocol::kMaxHz))
    return std::nullopt;
  return static_cast<radio::Hz>(r);
}
}  // namespace


const std::vector<LineProtocol::Command>& RigctlProtocol::commands() const {
  static const std::vector<Command> table = {
      {kSetFreq, 'F', "set_freq", false},
      {kGetFreq, 'f', "get_freq", true},
      {kSetMode, 'M', "set_mode", false},
      {kGetMode, 'm', "get_mode", true},
      {kSetVfo, 'V', "set_vfo", false},
      {kGetVfo, 'v', "get_vfo", true},
      {kSetSplitVfo, 'S', "set_split_vfo", false},
      {kGetSplitVfo, 's', "get_split_vfo", true},
      {kSetSplitFreq, 'I', "set_split_freq", false},
      {kGetSplitFreq, 'i', "get_split_freq", true},
      {kSetSplitMode, 'X', "set_split_mode", false},
      {kGetSplitMode, 'x', "get_split_mode", true},
      {kSetPtt, 'T', "set_ptt", false},
      {kGetPtt, 't', "get_ptt", true},
      {kGetInfo, '_', "get_info", true},
      {kChkVfo, 0, "chk_vfo", true},
      {kDumpState, 0, "dump_state", true},
      {kDumpCaps, '1', "dump_caps", true},
      {kGetPowerstat, 0, "get_powerstat", true},
      {kGetLockMode, 0, "get_lock_mode", true},
  };
  return table;
}

Outcome RigctlProtocol::execute(int id, const std::vector<std::string>& args) {
  using radio::Link;
  switch (id) {
    case kSetFreq: return set_freq(current_, args);
    case kSetMode: return set_mode(current_, args);
    case kSetVfo: return set_vfo(args);
    case kSetSplitVfo: return set_split(args);
    case kSetSplitFreq: return set_freq(Link::uplink, args);
    case kSetSplitMode: return set_mode(Link::uplink, args);
    case kSetPtt: return set_ptt(args);
    default: break;
  }
  if (!args.empty()) return Outcome::fail(Error::invalid);
  switch (id) {
    case kGetFreq: return get_freq(current_, "Frequency");
    case kGetMode: return get_mode(current_, "Mode", "Passband");
    case kGetVfo: return Outcome{}.add("VFO", current_name_);
    case kGetSplitVfo: return Outcome{}.add("Split", split_ ? "1" : "0").add("TX VFO", tx_name_);
    case kGetSplitFreq: return get_freq(Link::uplink, "TX Frequency");
    case kGetSplitMode: return get_mode(Link::uplink, "TX Mode", "TX Passband");
    case kGetPtt: return Outcome{}.add("PTT", "0");  // trakbox never keys the transmitter
    case kGetInfo:
      return Outcome{}.add("Info", one_line("trakbox radio (" + station_.radio().describe() + ")"));
    case kChkVfo: return Outcome{}.add("ChkVFO", "0");  // no VFO argument before each command
    case kDumpState: return dump_state();
    case kDumpCaps: return dump_caps();
    case kGetPowerstat: return Outcome{}.add("Power Status", station_.radio().status().connected ? "1" : "0");
    case kGetLockMode: return Outcome{}.add("Locked", "0");
    default: return Outcome::fail(Error::not_available);
  }
}

RigctlProtocol::RigctlProtocol(tracker::StationLoop& station, tracker::HolderKind kind)
    : station_(station), kind_(kind) {}

std::string RigctlProtocol::label(const std::string& peer) const {
  return std::string(tracker::kind_name(kind_)) + " " + peer;
}

void RigctlProtocol::client_line(const std::string& peer) {
  peer_ = peer;
  station_.control().heard(label(peer), station_.now());
}

void RigctlProtocol::client_left(const std::string& peer) {
  station_.apply(station_.control().left(label(peer), station_.now()));
}

Error RigctlProtocol::cannot_set() {
  if (station_.radio().status().fault) return Error::io;
  // The client takes the radio: trakbox's Doppler pauses until it disconnects or falls silent
  // (--handback); standby or another client's --exclusive hold refuses it.
  if (!tracker::StationOps(station_, {kind_, label(peer_)}).take_radio().ok()) return Error::rejected;
  return Error::none;
}

Outcome RigctlProtocol::set_freq(radio::Link link, const std::vector<std::string>& args) {
  if (args.size() != 1) return Outcome::fail(Error::invalid);
  const auto hz = parse_hz(args[0]);
  if (!hz) return Outcome::fail(Error::invalid);
  if (const Error e = cannot_set(); e != Error::none) return Outcome::fail(e);
  station_.radio().set_frequency(link, radio::quantise(static_cast<double>(*hz), radio::kTuningStepHz));
  return {};
}

Outcome RigctlProtocol::get_freq(radio::Link link, const char* key) {
  const radio::RadioStatus st = station_.radio().status();
  const auto hz = link == radio::Link::downlink ? st.downlink_hz : st.uplink_hz;
  // Nothing tuned on this link yet: 0. An error here would break Hamlib's NET client, which reads
  // the frequency when it opens and again inside set_vfo and set_freq, and gives the command up
  // when that read fails.
  return Outcome{}.add(key, hz_text(hz.value_or(0)));
}

Outcome RigctlProtocol::set_mode(radio::Link link, const std::vector<std::string>& args) {
  if (args.size() == 1 && args[0] == "?") return Outcome{}.add("", "USB LSB CW FM");
  if (args.size() != 2) return Outcome::fail(Error::invalid);
  const auto mode = parse_hamlib_mode(args[0]);
  const auto passband = parse_integer(args[1]);
  if (!mode || !passband || *passband < -1) return Outcome::fail(Error::invalid);
  if (const Error e = cannot_set(); e != Error::none) return Outcome::fail(e);
  station_.radio().set_mode(link, *mode);
  return {};
}

Outcome RigctlProtocol::get_mode(radio::Link link, const char* mode_key, const char* passband_key) {
  const radio::RadioStatus st = station_.radio().status();
  const auto mode = link == radio::Link::downlink ? st.downlink_mode : st.uplink_mode;
  if (!mode) return Outcome::fail(Error::io);
  return Outcome{}.add(mode_key, radio::to_string(*mode)).add(passband_key, "0");
}

Outcome RigctlProtocol::set_vfo(const std::vector<std::string>& args) {
  if (args.size() == 1 && args[0] == "?") return Outcome{}.add("", "VFOA VFOB Main Sub currVFO");
  if (args.size() != 1) return Outcome::fail(Error::invalid);
  const auto vfo = parse_vfo(args[0]);
  if (!vfo) return Outcome::fail(Error::bad_vfo);
  if (!vfo->current) {
    current_ = vfo->link;
    current_name_ = vfo->name;
  }
  return {};
}

Outcome RigctlProtocol::set_split(const std::vector<std::string>& args) {
  if (args.size() != 2) return Outcome::fail(Error::invalid);
  const auto split = parse_integer(args[0]);
  if (!split || (*split != 0 && *split != 1)) return Outcome::fail(Error::invalid);
  const auto vfo = parse_vfo(args[1]);
  if (!vfo) return Outcome::fail(Error::bad_vfo);
  const radio::Link tx = vfo->current ? current_ : vfo->link;
  // trakbox transmits on its uplink, VFO B: split to any other VFO is not something it can do.
  if (*split == 1 && tx != radio::Link::uplink) return Outcome::fail(Error::bad_vfo);
  split_ = *split == 1;
  if (tx == radio::Link::uplink) tx_name_ = vfo->current ? current_name_ : vfo->name;
  return {};
}

Outcome RigctlProtocol::set_ptt(const std::vector<std::string>& args) {
  if (args.size() != 1) return Outcome::fail(Error::invalid);
  const auto ptt = parse_integer(args[0]);
  if (!ptt || *ptt < 0 || *ptt > 3) return Outcome::fail(Error::invalid);
  // Receive is the only state trakbox puts the radio in; it has no line to key the transmitter.
  if (*ptt != 0) return Outcome::fail(Error::not_available);
  return {};
}

Outcome RigctlProtocol::dump_state() {
  // Protocol 1 as rigctld 4.5 sends it and Hamlib's NET client (rigctl -m 2) parses it: version,
  // model, ITU region, RX and TX ranges ("start end modes low_power high_power vfos antennas",
  // each list ended by zeros), tuning steps and filters ("modes value", ended by "0 0"), max
  // RIT/XIT/IF shift, announces, preamps, attenuators, the function/level/parm masks, then
  // key=value lines up to "done".
  const std::string range = "10000.000000 100000000000.000000 " + std::string(kModeMask) + " -1 -1 " + kVfoMask + " 0x0";
  Outcome o;
  for (const std::string& line : {
           std::string("1"),  // protocol version
           std::string("1"),  // model (Hamlib's dummy number: trakbox is not a Hamlib backend)
           std::string("0"),  // ITU region
           range, std::string("0 0 0 0 0 0 0"),
           range, std::string("0 0 0 0 0 0 0"),
           std::string(kModeMask) + " 10", std::string("0 0"),  // 10 Hz: trakbox's tuning step
           std::string("0 0"),                                   // no filters
           std::string("0"), std::string("0"), std::string("0"), std::string("0"),
           std::string(""), std::string(""),
           std::string("0x0"), std::string("0x0"), std::string("0x0"), std::string("0x0"), std::string("0x0"),
           std::string("0x0"),
           std::string("vfo_ops=0x0"),
           std::string("ptt_type=0x0"),
           std::string("targetable_vfo=0x0"),  // no VFO argument: a read is always of the current VFO
           std::string("has_set_vfo=1"),
           std::string("has_get_vfo=1"),
           std::string("has_set_freq=1"),
           std::string("has_get_freq=1"),
           std::string("has_set_conf=0"),
           std::string("has_get_conf=0"),
           std::string("has_power2mW=0"),
           std::string("has_mW2power=0"),
           std::string("timeout=0"),
           std::string("done"),
       })
    o.add("", line);
  return o;
}

Outcome RigctlProtocol::dump_caps() {
  Outcome o;
  for (const std::string& line : {
           std::string("Model name:\ttrakbox"),
           std::string("Mfg name:\ttrakbox"),
           one_line("Radio:\t" + station_.radio().describe()),
           std::string("Rig type:\tTransceiver"),
           std::string("PTT type:\tNone"),
           std::string("VFO list:\tVFOA (downlink) VFOB (uplink)"),
           std::string("Mode list:\tCW USB LSB FM"),
           "Frequency range:\t" + std::to_string(kMinHz) + " - " + std::to_string(kMaxHz) + " Hz",
           std::string("Tuning step:\t10 Hz"),
           std::string("Can set Frequency:\tY"),
           std::string("Can get Frequency:\tY"),
           std::string("Can set Mode:\tY"),
           std::string("Can get Mode:\tY"),
           std::string("Can set VFO:\tY"),
           std::string("Can get VFO:\tY"),
           std::string("Can set Split VFO:\tY"),
           std::string("Can get Split VFO:\tY"),
           std::string("Can set Split Freq:\tY"),
           std::string("Can get Split Freq:\tY"),
           std::string("Can set Split Mode:\tY"),
           std::string("Can get Split Mode:\tY"),
           std::string("Can set PTT:\tN"),
           std::string("Can get PTT:\tY"),
       })
    o.add("", line);
  return o;
}

}  // namespace tb::netctl
