#include "logbook/lotw_names.h"

#include <fstream>
#include <sstream>

#include "util/text.h"

namespace tb::logbook {

std::string LotwNames::name(int norad) const {
  const auto it = by_norad.find(norad);
  return it == by_norad.end() ? std::string() : it->second;
}

LotwNames parse_lotw_names(std::string_view text_in) {
  LotwNames r;
  std::size_t line_no = 0;
  for (std::string_view line : text::split(text_in, '\n')) {
    ++line_no;
    if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    line = text::trim(line, text::kWhitespace);
    if (line.empty()) continue;
    const auto blank = line.find_first_of(" \t");
    const auto fail = [&](const std::string& why) {
      LotwNames bad;
      bad.error = "line " + std::to_string(line_no) + ": " + why;
      return bad;
    };
    if (blank == std::string_view::npos) return fail("a NORAD number and a name are needed");
    const auto norad = text::parse_integer<int>(line.substr(0, blank));
    const std::string_view name = text::trim(line.substr(blank), text::kWhitespace);
    if (!norad || *norad <= 0) return fail("'" + std::string(line.substr(0, blank)) + "' is not a NORAD number");
    if (name.empty() || name.find_first_of(" \t") != std::string_view::npos)
      return fail("the name is one word (TQSL's spelling)");
    if (!r.by_norad.emplace(*norad, std::string(name)).second)
      return fail("NORAD " + std::to_string(*norad) + " is named twice");
  }
  return r;
}

LotwNames load_lotw_names(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    LotwNames r;
    r.error = path + ": cannot be read";
    return r;
  }
  std::ostringstream s;
  s << in.rdbuf();
  LotwNames r = parse_lotw_names(s.str());
  if (!r.error.empty()) r.error = path + ": " + r.error;
  return r;
}

}  // namespace tb::logbook
