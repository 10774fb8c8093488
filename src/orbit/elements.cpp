// Element sets: the small public pieces, format detection and files. The formats have their own
// files: elements_tle.cpp (NASA two/three-line), elements_amsat.cpp (AMSAT verbose),
// elements_gpredict.cpp (gpredict satdata), over the field parsers of elements_fields.h. See
// docs/element-formats.md for what is accepted and how problems are reported.
#include "orbit/elements.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "orbit/elements_internal.h"

namespace tb::orbit {

using detail::make_problem;

std::string Elements::label() const { return name.empty() ? std::to_string(catalog_number) : name; }

std::string ParseProblem::message() const {
  std::string m = file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + field + ": found ";
  m += found.empty() ? std::string("nothing") : "'" + found + "'";
  m += ", expected " + expected;
  if (warning) m += " (warning: set accepted)";
  return m;
}

bool ParseResult::ok() const {
  return std::none_of(problems.begin(), problems.end(), [](const ParseProblem& p) { return !p.warning; });
}

namespace {

enum class Detected { nasa, amsat, gpredict };

Detected detect(std::string_view text) {
  for (const detail::TextLine& l : detail::split_lines(text)) {
    const std::string_view t = detail::trim_left(l.text);
    if (t.empty() || t.front() == '#') continue;
    if (t.starts_with("TLE1=") || t.starts_with("TLE1 =")) return Detected::gpredict;
    if (detail::starts_amsat_block(t)) return Detected::amsat;
  }
  return Detected::nasa;
}

}  // namespace

ParseResult parse_elements(std::string_view text, std::string_view file_name, const ParseOptions& options) {
  switch (detect(text)) {
    case Detected::amsat:
      return parse_amsat(text, file_name, options);
    case Detected::gpredict:
      return parse_gpredict_satdata(text, file_name, options);
    case Detected::nasa:
      break;
  }
  return parse_nasa(text, file_name, options);
}

ParseResult load_elements_file(const std::string& path, const ParseOptions& options) {
  std::string text;
  int error = 0;
  errno = 0;
  if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
    char buf[65536];
    std::size_t got = 0;
    while ((got = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, got);
    if (std::ferror(f)) error = errno ? errno : EIO;  // e.g. EISDIR for a folder
    std::fclose(f);
  } else {
    error = errno ? errno : ENOENT;
  }
  if (error) {
    ParseResult r;
    r.problems.push_back(make_problem(path, 0, 0, "file", std::strerror(error), "a readable file of element sets"));
    return r;
  }
  return parse_elements(text, path, options);
}

}  // namespace tb::orbit
