// The OMM encodings read as text: JSON (CelesTrak's numbers, Space-Track's strings), CSV and KVN.
// Each turns its text into objects of keywords (elements_omm_internal.h); elements_omm.cpp makes the
// element sets.
#include "util/json_limits.h"
#include <nlohmann/json.hpp>

#include "orbit/elements_fields.h"
#include "orbit/elements_omm_internal.h"

namespace tb::orbit {

using detail::OmmField;
using detail::OmmObject;

namespace {

// ---------------------------------------------------------------------------------------------
// JSON

// Where each object of the top level starts: the '{' of each element of a top-level array, or the
// top-level object itself. nlohmann-json keeps no positions; this scan gives problems their lines.
std::vector<std::size_t> json_object_offsets(std::string_view text) {
  std::vector<std::size_t> offsets;
  int depth = 0;
  bool in_string = false, array_root = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (depth == 0) array_root = c == '[';
      if (c == '{' && depth == (array_root ? 1 : 0)) offsets.push_back(i);
      ++depth;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return offsets;
}

// The value of a JSON keyword as text: a string as it is, a number as the shortest text that reads
// back to the same double (the same digits as CelesTrak's when they were the shortest), null as
// nothing. Other types: nothing, and `bad` is set.
std::string json_value_text(const nlohmann::json& v, bool& bad) {
  if (v.is_string()) return std::string(text::trim(v.get_ref<const std::string&>()));
  if (v.is_number()) return v.dump();
  if (!v.is_null()) bad = true;
  return {};
}

OmmObject json_object(const nlohmann::json& j, std::string_view text, std::size_t start, std::size_t end,
                      std::string_view file) {
  OmmObject o;
  o.line = detail::line_of_offset(text, start);
  const std::string_view span = text.substr(std::min(start, text.size()), end - std::min(start, end));
  if (!j.is_object()) {
    o.structural = detail::make_problem(file, o.line, 0, "JSON object", std::string("a JSON ") + j.type_name(),
                                        "an object of OMM keywords such as {\"OBJECT_NAME\": ...}");
    return o;
  }
  for (const auto& [key, value] : j.items()) {
    const auto at = span.find("\"" + key + "\"");
    const int line = at == std::string_view::npos ? o.line : detail::line_of_offset(text, start + at);
    bool bad = false;
    o.fields.push_back({key, json_value_text(value, bad), line});
    if (bad && o.structural.field.empty())
      o.structural = detail::make_problem(file, line, 0, key, std::string("a JSON ") + value.type_name(),
                                          "a number or a string");
  }
  return o;
}

// ---------------------------------------------------------------------------------------------
// CSV

struct CsvRow {
  std::vector<std::string> cells;
  int line = 0;
};

// RFC 4180 rows: cells separated by commas, a cell in double quotes may hold commas, line breaks
// and doubled quotes. Blank lines are skipped. `unclosed_line` is where a quote that is never closed
// opened (0: none).
std::vector<CsvRow> csv_rows(std::string_view text, int& unclosed_line) {
  std::vector<CsvRow> rows;
  CsvRow row;
  std::string cell;
  bool quoted = false, any = false;
  int line = 1;
  unclosed_line = 0;
  auto end_row = [&] {
    row.cells.push_back(std::string(text::trim(cell)));
    if (any || row.cells.size() > 1 || !row.cells.front().empty()) rows.push_back(std::move(row));
    row = CsvRow{};
    cell.clear();
    any = false;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (row.cells.empty() && cell.empty() && !any) row.line = line;
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') cell += text[++i];
      else if (c == '"') quoted = false;
      else cell += c;
      if (c == '\n') ++line;
      continue;
    }
    if (c == '"') {
      quoted = any = true;
    } else if (c == ',') {
      row.cells.push_back(std::string(text::trim(cell)));
      cell.clear();
      any = true;
    } else if (c == '\n' || c == '\r') {
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      end_row();
      ++line;
    } else {
      cell += c;
    }
  }
  if (quoted) unclosed_line = row.line;
  end_row();
  return rows;
}

// ---------------------------------------------------------------------------------------------
// KVN

// "15.49291753 [rev/day]" -> "15.49291753".
std::string_view without_units(std::string_view v) {
  v = text::trim(v);
  if (v.ends_with(']')) {
    if (const auto open = v.rfind('['); open != std::string_view::npos) v = text::trim(v.substr(0, open));
  }
  return v;
}

}  // namespace

ParseResult parse_omm_json(std::string_view text, std::string_view file_name) {
  ParseResult r;
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  std::string why;
  json_limits::ParseFailure failed;
  const nlohmann::json doc = json_limits::parse_bounded<nlohmann::json>(text, why, json_limits::kMaxDepth, &failed);
  if (failed.too_deep) {
    r.problems.push_back(detail::make_problem(file_name, 1, 0, "JSON", std::string(text.substr(0, 20)),
                                              "JSON nested at most " + std::to_string(json_limits::kMaxDepth) +
                                                  " levels deep (an OMM document has 2)"));
    return r;
  }
  if (failed.located) {
    const std::size_t at = failed.byte > 0 ? failed.byte - 1 : 0;
    r.problems.push_back(detail::make_problem(file_name, detail::line_of_offset(text, at), 0, "JSON",
                                              std::string(text.substr(std::min(at, text.size()), 20)),
                                              "JSON text (" + failed.what + ")"));
    return r;
  }
  if (doc.is_discarded()) {  // e.g. a number beyond double: out_of_range
    r.problems.push_back(detail::make_problem(file_name, 0, 0, "JSON", "", "JSON text (" + failed.what + ")"));
    return r;
  }
  const std::vector<std::size_t> offsets = json_object_offsets(text);
  auto span_of = [&](std::size_t i) {
    const std::size_t start = i < offsets.size() ? offsets[i] : 0;
    const std::size_t end = i + 1 < offsets.size() ? offsets[i + 1] : text.size();
    return std::pair{start, end};
  };
  if (doc.is_object()) {
    detail::add_omm_object(json_object(doc, text, 0, text.size(), file_name), 1, file_name, ElementFormat::omm_json, r);
  } else if (doc.is_array()) {
    // Elements that are not objects have no offset: a mismatch only makes the lines less exact.
    for (std::size_t i = 0; i < doc.size(); ++i) {
      const auto [start, end] = span_of(i);
      detail::add_omm_object(json_object(doc[i], text, start, end, file_name), static_cast<int>(i + 1), file_name,
                             ElementFormat::omm_json, r);
    }
  } else {
    r.problems.push_back(detail::make_problem(file_name, 1, 0, "JSON", std::string("a JSON ") + doc.type_name(),
                                              "an array of OMM objects, or one object"));
  }
  return r;
}

ParseResult parse_omm_csv(std::string_view text, std::string_view file_name) {
  ParseResult r;
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  int unclosed = 0;
  const std::vector<CsvRow> rows = csv_rows(text, unclosed);
  if (unclosed)
    r.problems.push_back(detail::make_problem(file_name, unclosed, 0, "CSV quote", "\"", "a closing double quote"));
  if (rows.empty()) {
    r.problems.push_back(detail::make_problem(file_name, 1, 0, "CSV header", "", "a header line of OMM keywords"));
    return r;
  }
  const std::vector<std::string>& header = rows.front().cells;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const CsvRow& row = rows[i];
    OmmObject o;
    o.line = row.line;
    for (std::size_t k = 0; k < header.size() && k < row.cells.size(); ++k)
      o.fields.push_back({header[k], row.cells[k], row.line});
    if (row.cells.size() != header.size())
      o.structural = detail::make_problem(file_name, row.line, 0, "CSV columns", std::to_string(row.cells.size()),
                                          std::to_string(header.size()) + " cells as in the header line");
    detail::add_omm_object(o, static_cast<int>(i), file_name, ElementFormat::omm_csv, r);
  }
  return r;
}

ParseResult parse_omm_kvn(std::string_view text, std::string_view file_name) {
  ParseResult r;
  std::vector<OmmObject> objects;
  for (const detail::TextLine& l : detail::split_lines(text)) {
    const std::string_view t = text::trim(l.text, text::kWhitespace);
    if (t.empty() || t.starts_with("COMMENT")) continue;
    const auto eq = t.find('=');
    const std::string_view key = eq == std::string_view::npos ? t : text::trim(t.substr(0, eq));
    if (text::iequals(key, "CCSDS_OMM_VERS")) objects.push_back(OmmObject{{}, l.number, {}});
    if (objects.empty()) {
      r.problems.push_back(detail::make_problem(file_name, l.number, 0, "CCSDS_OMM_VERS", std::string(t.substr(0, 40)),
                                                "each object to start with a line CCSDS_OMM_VERS = 2.0"));
      objects.push_back(OmmObject{{}, l.number, {}});  // what follows is still one object, reported once
      objects.back().structural = r.problems.back();
      r.problems.pop_back();
    }
    OmmObject& o = objects.back();
    if (eq == std::string_view::npos || key.empty()) {
      if (o.structural.field.empty())
        o.structural = detail::make_problem(file_name, l.number, 0, "KVN line", std::string(t.substr(0, 40)),
                                            "KEYWORD = value");
      continue;
    }
    o.fields.push_back({std::string(key), std::string(without_units(t.substr(eq + 1))), l.number});
  }
  for (std::size_t i = 0; i < objects.size(); ++i)
    detail::add_omm_object(objects[i], static_cast<int>(i + 1), file_name, ElementFormat::omm_kvn, r);
  return r;
}

}  // namespace tb::orbit
