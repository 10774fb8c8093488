// gpredict's satellite files (INI-like: [NNNNN], NAME=, TLE1=, TLE2=), such as Debian gpredict's
// satellites.dat: NASA lines under a section, the name from NAME=.
#include <optional>
#include <string>

#include "orbit/elements.h"
#include "orbit/elements_internal.h"

namespace tb::orbit {

using namespace detail;

namespace {

struct GpredictSection {
  int header_line = 0;  // 0: keys before any [section]
  std::string title;
  std::string name;
  std::optional<ElementLine> tle[2];
};

void finish_section(const GpredictSection& s, std::string_view file, const ParseOptions& options, ParseResult& result) {
  static constexpr const char* kKeys[2] = {"TLE1", "TLE2"};
  for (int k = 0; k < 2; ++k) {
    if (!s.tle[k]) {
      result.problems.push_back(make_problem(file, s.header_line, 0, kKeys[k], "",
                                             std::string("a ") + kKeys[k] + "= line in section [" + s.title + "]"));
      return;
    }
  }
  Elements e;
  e.source = ElementFormat::nasa;
  e.name = s.name;
  std::optional<ParseProblem> problem = parse_line1(*s.tle[0], options, e);
  if (!problem) problem = parse_line2(*s.tle[1], options, e);
  if (problem) result.problems.push_back(std::move(*problem));
  else result.sets.push_back(std::move(e));
}

}  // namespace

ParseResult parse_gpredict_satdata(std::string_view text, std::string_view file_name, const ParseOptions& options) {
  ParseResult result;
  std::optional<GpredictSection> section;
  for (const TextLine& line : split_lines(text)) {
    const std::string_view t = trim(line.text);
    if (t.empty() || t.front() == '#' || t.front() == ';') continue;
    if (t.front() == '[') {
      if (section) finish_section(*section, file_name, options, result);
      section.emplace();
      section->header_line = line.number;
      section->title = std::string(trim(t.substr(1, t.size() - (t.back() == ']' ? 2 : 1))));
      continue;
    }
    const auto equals = line.text.find('=');
    if (equals == std::string_view::npos) {
      result.problems.push_back(make_problem(file_name, line.number, 1, "line", std::string(t),
                                             "[section], KEY=value, comment or blank line", true));
      continue;
    }
    if (!section) section.emplace();  // keys before any section: read them as one
    const std::string_view key = trim(line.text.substr(0, equals));
    std::size_t value_begin = equals + 1;
    while (value_begin < line.text.size() && is_space(line.text[value_begin])) ++value_begin;
    const std::string_view value = line.text.substr(value_begin);
    if (key == "NAME") {
      section->name = std::string(trim(value));
    } else if (key == "TLE1" || key == "TLE2") {
      section->tle[key == "TLE1" ? 0 : 1] =
          ElementLine{value, line.number, static_cast<int>(value_begin), file_name};
    }
  }
  if (section) finish_section(*section, file_name, options, result);
  return result;
}

}  // namespace tb::orbit
