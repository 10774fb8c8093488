// What one element-set format's reader takes from another's (private to src/orbit): gpredict files
// hold NASA lines, and detection needs to recognise an AMSAT block.
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "orbit/elements.h"
#include "orbit/elements_fields.h"

namespace tb::orbit::detail {

// One element line as the parsers see it: the text, its line number in the file, and how far
// its column 1 is from the file's column 1 (5 for gpredict's "TLE1=").
struct ElementLine {
  std::string_view text;
  int number = 0;
  int column_offset = 0;
  std::string_view file;

  char at(int column) const {
    const auto i = static_cast<std::size_t>(column - 1);
    return i < text.size() ? text[i] : ' ';
  }
  std::string_view raw(int first, int last) const {
    const auto begin = static_cast<std::size_t>(first - 1);
    if (begin >= text.size()) return {};
    return text.substr(begin, static_cast<std::size_t>(last - first + 1));
  }
  ParseProblem problem(int first, int last, std::string field, std::string expected) const {
    return make_problem(file, number, first + column_offset, std::move(field), std::string(raw(first, last)),
                        std::move(expected));
  }
};

// NASA line 1 and line 2 into e (elements_tle.cpp): the first problem, or nothing.
std::optional<ParseProblem> parse_line1(const ElementLine& l, const ParseOptions& options, Elements& e);
std::optional<ParseProblem> parse_line2(const ElementLine& l, const ParseOptions& options, Elements& e);

// Whether the line is an AMSAT "Satellite:" line, which starts a block (elements_amsat.cpp).
bool starts_amsat_block(std::string_view line);

}  // namespace tb::orbit::detail
