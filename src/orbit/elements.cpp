// Element sets: the small public pieces, format detection and files. The formats have their own
// files: elements_tle.cpp (NASA two/three-line), elements_amsat.cpp (AMSAT verbose),
// elements_gpredict.cpp (gpredict satdata), elements_omm*.cpp (CCSDS OMM in JSON, XML, CSV, KVN),
// over the field parsers of elements_fields.h. See docs/element-formats.md for what is accepted
// and how problems are reported.
#include "orbit/elements.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>

#include "orbit/elements_internal.h"
#include "orbit/elements_omm_internal.h"
#include "util/safe_text.h"

namespace tb::orbit {

using detail::make_problem;

const char* describe(ElementFormat format) {
  switch (format) {
    case ElementFormat::nasa: return "NASA TLE";
    case ElementFormat::amsat: return "AMSAT";
    case ElementFormat::omm_json: return "OMM JSON";
    case ElementFormat::omm_xml: return "OMM XML";
    case ElementFormat::omm_csv: return "OMM CSV";
    case ElementFormat::omm_kvn: return "OMM KVN";
  }
  return "?";
}

std::string Elements::label() const { return name.empty() ? std::to_string(catalog_number) : name; }

std::string ParseProblem::message() const {
  std::string m = file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
  if (!object.empty()) m += object + ": ";
  m += field + ": found ";
  // What the text had may be anything: shown as bytes when it is not printable UTF-8.
  m += found.empty() ? std::string("nothing") : "'" + (text::is_safe_text(found) ? found : text::visible_bytes(found)) + "'";
  m += ", expected " + expected;
  if (warning) m += " (warning: set accepted)";
  return text::safe_text(m);  // an object's name, a file's name: for a terminal, whatever they hold
}

bool ParseResult::ok() const {
  return std::none_of(problems.begin(), problems.end(), [](const ParseProblem& p) { return !p.warning; });
}

namespace {

enum class Detected { nasa, amsat, gpredict, omm_json, omm_xml, omm_csv, omm_kvn };

// A CSV header line: comma-separated keywords among which NORAD_CAT_ID and EPOCH.
bool is_omm_csv_header(std::string_view line) {
  bool catalog = false, epoch = false;
  for (std::string_view cell : text::split(line, ',')) {
    cell = text::trim(text::trim(cell), "\"");
    catalog = catalog || text::iequals(cell, "NORAD_CAT_ID");
    epoch = epoch || text::iequals(cell, "EPOCH");
  }
  return catalog && epoch;
}

Detected detect(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // UTF-8 byte-order mark
  const std::string_view start = text::trim_left(text, text::kWhitespace);
  // '{', or '[' then '{' or ']': an INI section such as gpredict's "[25544]" is not JSON.
  if (start.starts_with('{')) return Detected::omm_json;
  if (start.starts_with('[')) {
    const std::string_view inside = text::trim_left(start.substr(1), text::kWhitespace);
    if (inside.starts_with('{') || inside.starts_with(']')) return Detected::omm_json;
  }
  if (start.starts_with('<')) return Detected::omm_xml;
  bool first = true;
  for (const detail::TextLine& l : detail::split_lines(text)) {
    const std::string_view t = detail::trim_left(l.text);
    if (t.empty() || t.front() == '#') continue;
    if (first && is_omm_csv_header(t)) return Detected::omm_csv;
    first = false;
    if (t.starts_with("CCSDS_OMM_VERS")) return Detected::omm_kvn;
    if (t.starts_with("TLE1=") || t.starts_with("TLE1 =")) return Detected::gpredict;
    if (detail::starts_amsat_block(t)) return Detected::amsat;
  }
  return Detected::nasa;
}

// An empty text, or one that is not text: NUL bytes, or more than a tenth of its first 4 KiB control
// characters other than line breaks, tabs, form feeds and the Ctrl-Z that ends an ASCII upload.
std::optional<ParseProblem> not_text(std::string_view text, std::string_view file_name) {
  if (text::trim(text, text::kWhitespace).empty())
    return make_problem(file_name, 0, 0, "file", text.empty() ? "" : "only blanks",
                        "element sets (the file is empty)");
  if (const auto nul = text.find('\0'); nul != std::string_view::npos)
    return make_problem(file_name, detail::line_of_offset(text, nul), 0, "file",
                        "a NUL byte at offset " + std::to_string(nul), "text (this is not a text file)");
  const std::string_view head = text.substr(0, 4096);
  const auto control = std::count_if(head.begin(), head.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return (u < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\f' && c != '\x1a') || u == 0x7f;
  });
  if (control * 10 > static_cast<std::ptrdiff_t>(head.size()))
    return make_problem(file_name, 0, 0, "file", std::to_string(control) + " control bytes in the first " +
                        std::to_string(head.size()), "text (this is not a text file)");
  return std::nullopt;
}

ParseResult parse_any(std::string_view text, std::string_view file_name, const ParseOptions& options);

}  // namespace

ParseResult clean_names(ParseResult r, std::string_view text, std::string_view file_name) {
  for (Elements& e : r.sets) {
    if (text::is_safe_text(e.name)) continue;
    const std::size_t at = e.name.empty() ? std::string_view::npos : text.find(e.name);
    ParseProblem p = make_problem(file_name, at == std::string_view::npos ? 0 : detail::line_of_offset(text, at), 0, "name",
                                  e.name, "printable UTF-8 (kept as '" + text::safe_text(e.name) + "')");
    p.warning = true;
    r.problems.push_back(std::move(p));
    e.name = text::safe_text(e.name);
  }
  return r;
}

ParseResult parse_elements(std::string_view text, std::string_view file_name, const ParseOptions& options) {
  if (auto problem = not_text(text, file_name)) {
    ParseResult r;
    r.problems.push_back(std::move(*problem));
    return r;
  }
  return clean_names(parse_any(text, file_name, options), text, file_name);
}

namespace {
ParseResult parse_any(std::string_view text, std::string_view file_name, const ParseOptions& options) {
  switch (detect(text)) {
    case Detected::amsat:
      return parse_amsat(text, file_name, options);
    case Detected::gpredict:
      return parse_gpredict_satdata(text, file_name, options);
    case Detected::omm_json:
      return parse_omm_json(text, file_name);
    case Detected::omm_xml:
      return parse_omm_xml(text, file_name);
    case Detected::omm_csv:
      return parse_omm_csv(text, file_name);
    case Detected::omm_kvn:
      return parse_omm_kvn(text, file_name);
    case Detected::nasa:
      break;
  }
  return parse_nasa(text, file_name, options);
}
}  // namespace

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
