#include "rotator/pst/codec.h"

#include <cstdio>

#include "util/safe_text.h"
#include "util/text.h"

namespace tb::rotator::pst {

namespace {

std::string one_decimal(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

std::string tag(const char* name, const std::string& value) {
  return std::string("<PST><") + name + ">" + value + "</" + name + "></PST>";
}

Datagram refuse(std::string why) { return {{}, std::move(why)}; }

}  // namespace

std::string set_azimuth(double az) { return tag("AZIMUTH", one_decimal(az)); }
std::string set_elevation(double el) { return tag("ELEVATION", one_decimal(el)); }
std::string stop() { return tag("STOP", "1"); }
std::string park() { return tag("PARK", "1"); }
std::string ask_azimuth() { return "<PST>AZ?</PST>"; }
std::string ask_elevation() { return "<PST>EL?</PST>"; }
std::string azimuth_reply(double az) { return "AZ:" + one_decimal(az); }
std::string elevation_reply(double el) { return "EL:" + one_decimal(el); }

Datagram parse_command(std::string_view d) {
  if (d.size() > kMaxDatagram) return refuse("longer than " + std::to_string(kMaxDatagram) + " bytes");
  std::string_view s = text::trim(d, text::kWhitespace);
  if (s.substr(0, 5) != "<PST>" || s.size() < 11 || s.substr(s.size() - 6) != "</PST>")
    return refuse("not a PstRotator command (<PST>...</PST>): \"" + text::visible_bytes(s.substr(0, 40)) + "\"");
  s = text::trim(s.substr(5, s.size() - 11), text::kWhitespace);
  Datagram out;
  if (s == "AZ?" || s == "EL?") {
    out.commands.push_back({s == "AZ?" ? Command::Kind::ask_azimuth : Command::Kind::ask_elevation});
    return out;
  }
  if (s.empty()) return refuse("an empty <PST></PST>");
  while (!s.empty()) {
    if (s.front() != '<') return refuse("text outside a tag: \"" + text::visible_bytes(s.substr(0, 40)) + "\"");
    const auto close = s.find('>');
    if (close == std::string_view::npos) return refuse("a tag that does not end");
    const std::string_view name = s.substr(1, close - 1);
    const std::string end = "</" + std::string(name) + ">";
    const auto end_at = s.find(end, close + 1);
    if (name.empty() || end_at == std::string_view::npos)
      return refuse("<" + text::visible_bytes(name.substr(0, 20)) + "> without its end tag");
    const std::string_view value = text::trim(s.substr(close + 1, end_at - close - 1), text::kWhitespace);
    const auto number = text::parse_double(value);
    Command c{Command::Kind::stop};
    if (name == "AZIMUTH" || name == "ELEVATION") {
      const bool az = name == "AZIMUTH";
      if (!number) return refuse("<" + std::string(name) + "> \"" + text::visible_bytes(value.substr(0, 20)) + "\" is not a number");
      if (az ? (*number < -360.0 || *number > 720.0) : (*number < -90.0 || *number > 180.0))
        return refuse("<" + std::string(name) + "> " + text::visible_bytes(value) + " is out of range");
      c = {az ? Command::Kind::azimuth : Command::Kind::elevation, *number};
    } else if (name == "STOP" || name == "PARK") {
      if (!number) return refuse("<" + std::string(name) + "> \"" + text::visible_bytes(value.substr(0, 20)) + "\" is not a number");
      if (*number == 0.0) {   // <STOP>0</STOP>: nothing asked
        s = text::trim_left(s.substr(end_at + end.size()), text::kWhitespace);
        continue;
      }
      c = {name == "STOP" ? Command::Kind::stop : Command::Kind::park};
    } else {
      return refuse("<" + text::visible_bytes(name.substr(0, 20)) + "> is not a command trakbox takes "
                    "(AZIMUTH, ELEVATION, STOP, PARK, AZ?, EL?)");
    }
    if (out.commands.size() >= 4) return refuse("more than 4 commands in one datagram");
    out.commands.push_back(c);
    s = text::trim_left(s.substr(end_at + end.size()), text::kWhitespace);
  }
  return out;
}

Reading parse_reply(std::string_view d) {
  std::string_view s = text::trim(d, text::kWhitespace);
  if (s.substr(0, 5) == "<PST>" && s.size() >= 11 && s.substr(s.size() - 6) == "</PST>")
    s = text::trim(s.substr(5, s.size() - 11), text::kWhitespace);
  Reading r;
  // "AZ:297.0", "EL:25.0", or both on lines of their own.
  for (std::string_view rest = s; !rest.empty();) {
    const auto nl = rest.find_first_of("\r\n");
    const std::string_view line = text::trim(rest.substr(0, nl));
    rest = nl == std::string_view::npos ? std::string_view{} : text::trim_left(rest.substr(nl), text::kWhitespace);
    if (line.size() < 4 || line[2] != ':') continue;
    const auto v = text::parse_double(text::trim(line.substr(3)));
    if (!v) continue;
    if (line.substr(0, 2) == "AZ" && *v >= -360.0 && *v <= 720.0) r.az = *v;
    if (line.substr(0, 2) == "EL" && *v >= -90.0 && *v <= 180.0) r.el = *v;
  }
  return r;
}

}  // namespace tb::rotator::pst
