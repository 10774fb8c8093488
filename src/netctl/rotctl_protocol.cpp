#include "netctl/rotctl_protocol.h"

#include <cstdio>

#include "rotator/adc_model.h"
#include "tracker/operations.h"

namespace tb::netctl {

namespace {
enum Id { kSetPos, kGetPos, kStop, kPark, kMove, kGetInfo, kDumpState, kDumpCaps, kReset, kSetConf, kSendCmd };

// Hamlib's ROT_MOVE_* bits.
constexpr long long kMoveUp = 2, kMoveDown = 4, kMoveCcw = 8, kMoveCw = 16;

std::string six(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.6f", v);
  return b;
}
}  // namespace

RotctlProtocol::RotctlProtocol(tracker::StationLoop& station, tracker::HolderKind kind)
    : station_(station), kind_(kind) {}

std::string RotctlProtocol::label(const std::string& peer) const {
  return std::string(tracker::kind_name(kind_)) + " " + peer;
}

void RotctlProtocol::client_line(const std::string& peer) {
  peer_ = peer;
  station_.control().heard(label(peer), station_.now());
}

void RotctlProtocol::client_left(const std::string& peer) {
  station_.apply(station_.control().left(label(peer), station_.now()));
}

tracker::StationOps RotctlProtocol::ops() { return tracker::StationOps(station_, {kind_, label(peer_)}); }

const std::vector<LineProtocol::Command>& RotctlProtocol::commands() const {
  static const std::vector<Command> table = {
      {kSetPos, 'P', "set_pos", false},
      {kGetPos, 'p', "get_pos", true},
      {kStop, 'S', "stop", false},
      {kPark, 'K', "park", false},
      {kMove, 'M', "move", false},
      {kGetInfo, '_', "get_info", true},
      {kDumpState, 0, "dump_state", true},
      {kDumpCaps, '1', "dump_caps", true},
      // Hamlib has these; trakbox does not offer them (RPRT -11).
      {kReset, 'R', "reset", false},
      {kSetConf, 'C', "set_conf", false},
      {kSendCmd, 'w', "send_cmd", false},
  };
  return table;
}

double RotctlProtocol::max_el() const { return station_.rotator().config().el_top_deg(); }

double RotctlProtocol::in_frame(double compass_az, double frame_lo) {
  return frame_lo < 0.0 && compass_az > 180.0 ? compass_az - 360.0 : compass_az;
}

Outcome RotctlProtocol::execute(int id, const std::vector<std::string>& args) {
  switch (id) {
    case kSetPos:
      return set_pos(args);
    case kMove:
      return move(args);
    case kReset:
    case kSetConf:
    case kSendCmd:
      return Outcome::fail(Error::not_available);
    default:
      break;
  }
  if (!args.empty()) return Outcome::fail(Error::invalid);
  switch (id) {
    case kGetPos: return get_pos();
    case kStop: return stop();
    case kPark: return park();
    case kGetInfo: return info();
    case kDumpState: return dump_state();
    case kDumpCaps: return dump_caps();
    default: return Outcome::fail(Error::not_available);
  }
}

Error RotctlProtocol::cannot_move() {
  // The client takes the antenna first (its tracking suspended), unless standby or another
  // client's --exclusive hold refuses it: then nothing changes, rotor control included.
  tracker::Control::Answer a = station_.control().request(tracker::Resource::antenna, {kind_, label(peer_)}, station_.now());
  station_.apply(a.changes);
  if (!a.granted) return Error::rejected;
  if (!station_.rotor_control()) tracker::StationOps(station_).rotor_control(true);
  if (!station_.rotator().status().link.ok()) return Error::io;
  return Error::none;
}

Outcome RotctlProtocol::set_pos(const std::vector<std::string>& args) {
  if (args.size() != 2) return Outcome::fail(Error::invalid);
  const auto az = parse_double(args[0]);
  const auto el = parse_double(args[1]);
  if (!az || !el || *az < kMinAz || *az > kMaxAz || *el < 0.0 || *el > max_el()) return Outcome::fail(Error::invalid);
  if (const Error e = cannot_move(); e != Error::none) return Outcome::fail(e);
  // The client's frame, as far as this azimuth tells it (0..180 is the same in both).
  if (*az < 0.0) az_frame_lo_ = -180.0;
  if (*az > 180.0) az_frame_lo_ = 0.0;
  const tracker::OpResult r = ops().go_to(rotator::wrap360(*az), *el);
  if (!r.ok()) return Outcome::fail(Error::rejected);  // held: standby, --exclusive
  return {};
}

Outcome RotctlProtocol::get_pos() {
  const auto& s = station_.rotator().status();
  if (!s.link.ok() || !s.has_position) return Outcome::fail(Error::io);
  return Outcome{}.add("Azimuth", fixed2(in_frame(s.az.deg, az_frame_lo_))).add("Elevation", fixed2(s.el.deg));
}

Outcome RotctlProtocol::stop() {
  ops().stop();  // always: the motors stop whoever holds the antenna
  return {};
}

Outcome RotctlProtocol::park() {
  if (const Error e = cannot_move(); e != Error::none) return Outcome::fail(e);
  if (!ops().park().ok()) return Outcome::fail(Error::rejected);  // parking is off, or held
  return {};
}

Outcome RotctlProtocol::move(const std::vector<std::string>& args) {
  if (args.size() != 2) return Outcome::fail(Error::invalid);
  const auto dir = parse_integer(args[0]);
  const auto speed = parse_integer(args[1]);
  if (!dir || !speed) return Outcome::fail(Error::invalid);
  if (*speed != -1 && (*speed < 1 || *speed > 100)) return Outcome::fail(Error::invalid);
  rotator::Axis axis;
  rotator::Drive drive;
  switch (*dir) {
    case kMoveUp: axis = rotator::Axis::el; drive = rotator::Drive::increase; break;
    case kMoveDown: axis = rotator::Axis::el; drive = rotator::Drive::decrease; break;
    case kMoveCcw: axis = rotator::Axis::az; drive = rotator::Drive::decrease; break;
    case kMoveCw: axis = rotator::Axis::az; drive = rotator::Drive::increase; break;
    default: return Outcome::fail(Error::invalid);
  }
  if (const Error e = cannot_move(); e != Error::none) return Outcome::fail(e);
  // trakbox's motors have one speed: the axis runs at the rotator's rate until S. The client holds
  // the antenna (its tracking suspended), as a P would.
  station_.rotator().manual(axis, drive);
  return {};
}

Outcome RotctlProtocol::info() {
  return Outcome{}.add("Info", one_line("trakbox rotator (" + station_.rotator().driver().description() + ")"));
}

Outcome RotctlProtocol::dump_state() {
  // Protocol 1, as rotctld 4.5 sends it: version, model, then key=value lines up to "done".
  // Hamlib's NET client takes its limits from here and refuses positions outside them itself.
  Outcome o;
  for (const std::string& line :
       {std::string("1"), std::string("1"), "min_az=" + six(kMinAz), "max_az=" + six(kMaxAz), "min_el=" + six(0.0),
        "max_el=" + six(max_el()), std::string("south_zero=0"), std::string("rot_type=AzEl"), std::string("done")})
    o.add("", line);
  return o;
}

Outcome RotctlProtocol::dump_caps() {
  const bool park = station_.rotator().config().parking_enabled;
  Outcome o;
  for (const std::string& line : {
           std::string("Model name:\ttrakbox"),
           std::string("Mfg name:\ttrakbox"),
           one_line("Rotator:\t" + station_.rotator().driver().description()),
           std::string("Rot type:\tAz-El"),
           "Min Azimuth:\t" + fixed2(kMinAz),
           "Max Azimuth:\t" + fixed2(kMaxAz),
           "Min Elevation:\t" + fixed2(0.0),
           "Max Elevation:\t" + fixed2(max_el()),
           std::string("Can set Position:\tY"),
           std::string("Can get Position:\tY"),
           std::string("Can Stop:\tY"),
           std::string("Can Park:\t") + (park ? "Y" : "N"),
           std::string("Can Reset:\tN"),
           std::string("Can Move:\tY"),
           std::string("Can get Info:\tY"),
       })
    o.add("", line);
  return o;
}

}  // namespace tb::netctl
