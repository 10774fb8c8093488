#include "rotator/easycomm.h"

#include <cstdio>

#include "util/safe_text.h"
#include "util/text.h"

namespace tb::rotator::easycomm {

std::string set_position(AzEl p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "AZ%.1f EL%.1f\n", p.az, p.el);
  return buf;
}

std::string read_position() { return "AZ EL \n"; }

std::string stop() { return "SA SE \n"; }

namespace {

// "AZ" or "EL" and its number, blanks around it allowed; nullopt when the word is not there.
std::optional<double> field(std::string_view word, std::string_view prefix, bool& ok) {
  word = text::trim(word);
  if (word.substr(0, 2) != prefix) return std::nullopt;
  const auto v = text::parse_double(text::trim(word.substr(2)));
  ok = ok && v.has_value();
  return v;
}

}  // namespace

Line parse_line(std::string_view raw) {
  const std::string_view s = text::trim(raw, text::kWhitespace);
  Line out;
  out.text = text::visible_bytes(s);
  if (s.substr(0, 2) == "AL") {
    out.kind = Line::Kind::alarm;
    return out;
  }
  if (s.substr(0, 2) != "AZ") return out;
  // "AZ123.4 EL45.6" (Hamlib reads it with sscanf "AZ%f EL%f"): the EL word after blanks.
  const auto el_at = s.find("EL");
  bool ok = el_at != std::string_view::npos;
  const auto az = field(s.substr(0, el_at == std::string_view::npos ? s.size() : el_at), "AZ", ok);
  const auto el = ok ? field(s.substr(el_at), "EL", ok) : std::nullopt;
  if (!ok || !az || !el) {
    out.kind = s == "AZ EL" || s == "AZ" ? Line::Kind::other : Line::Kind::bad;   // an echo of the query
    if (out.kind == Line::Kind::bad) out.text = "not a position: \"" + out.text + "\"";
    return out;
  }
  if (*az < -360.0 || *az > 720.0 || *el < -90.0 || *el > 180.0) {
    out.kind = Line::Kind::bad;
    out.text = "a position out of any rotator's range: \"" + out.text + "\"";
    return out;
  }
  out.kind = Line::Kind::position;
  out.position = {*az, *el};
  return out;
}

}  // namespace tb::rotator::easycomm
