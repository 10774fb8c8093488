// AMSAT verbose element sets ("Satellite: AO-07", "Catalog number: 07530", ...): the reader, the
// writer and the checksum. docs/element-formats.md has what is accepted and how problems are reported.
#include <charconv>
#include <cstdio>
#include <memory>
#include <optional>
#include <system_error>

#include "orbit/elements.h"
#include "orbit/elements_internal.h"

namespace tb::orbit {

using namespace detail;

int amsat_checksum(const std::vector<std::string_view>& lines) {
  int sum = 0;
  for (const std::string_view line : lines) {
    for (const char c : line) {
      if (is_digit(c)) sum += c - '0';
      else if (c == '-') sum += 1;
      else if (c == '+') sum += 2;
    }
  }
  return sum;
}

namespace {

enum AmsatField {
  kSatellite, kCatalog, kEpochTime, kElementSet, kInclination, kRaan, kEccentricity, kArgPerigee,
  kMeanAnomaly, kMeanMotion, kDecayRate, kEpochRev, kChecksum, kAmsatFieldCount
};

// Labels as the format writes them; matched without regard to case or runs of blanks.
constexpr const char* kAmsatLabels[kAmsatFieldCount] = {
    "Satellite",      "Catalog number", "Epoch time",  "Element set", "Inclination", "RA of node", "Eccentricity",
    "Arg of perigee", "Mean anomaly",   "Mean motion", "Decay rate",  "Epoch rev",   "Checksum",
};

// "Label: value" -> the label folded to lower case with single blanks, and where the value starts.
struct LabelledLine {
  std::string label;                         // empty when the line has no colon
  std::size_t value_begin = 0;               // index of the first character after the blanks
};

LabelledLine split_label(std::string_view line) {
  LabelledLine out;
  const auto colon = line.find(':');
  if (colon == std::string_view::npos) return out;
  for (const char c : trim(line.substr(0, colon))) {
    if (is_space(c)) {
      if (!out.label.empty() && out.label.back() != ' ') out.label += ' ';
    } else {
      out.label += to_lower(c);
    }
  }
  std::size_t v = colon + 1;
  while (v < line.size() && is_space(line[v])) ++v;
  out.value_begin = v;
  if (out.label.empty()) out.label.assign(1, ' ');  // a colon without a label: still a labelled line
  return out;
}

int amsat_field_of(const std::string& label) {
  for (int f = 0; f < kAmsatFieldCount; ++f) {
    if (text::lower(kAmsatLabels[f]) == label) return f;
  }
  return -1;
}

struct AmsatValue {
  bool present = false;
  std::size_t index = 0;   // into the line list
  int line = 0;
  int column = 0;          // 1-based column of the value
  std::string_view token;  // the value up to the first blank (units follow)
  std::string_view rest;   // everything after the colon, trimmed (names have blanks)
};

class AmsatBlock {
 public:
  AmsatBlock(const std::vector<TextLine>& lines, std::size_t start, std::string_view file, const ParseOptions& options)
      : lines_(lines), start_(start), file_(file), options_(options) {}

  // Records a labelled line of the block; false when it is the second line with that label.
  void add(int field, std::size_t index, const LabelledLine& l) {
    AmsatValue& v = values_[field];
    const std::string_view text = lines_[index].text;
    std::string_view value = l.value_begin < text.size() ? text.substr(l.value_begin) : std::string_view{};
    const auto blank = value.find_first_of(text::kBlanks);
    AmsatValue nv{true, index, lines_[index].number, static_cast<int>(l.value_begin) + 1,
                  value.substr(0, blank), trim(value)};
    if (v.present) {
      if (!duplicate_) {
        duplicate_ = make_problem(file_, nv.line, nv.column, kAmsatLabels[field], std::string(nv.token),
                                  std::string("one '") + kAmsatLabels[field] + ":' line in the block");
      }
      return;
    }
    v = nv;
  }

  // Appends the set or the problems to the result.
  void finish(ParseResult& result) {
    Elements e;
    if (auto p = decode(e)) {
      result.problems.push_back(std::move(*p));
      return;
    }
    // The checksum: digits of the lines from "Satellite:" to "Epoch rev:", '-' 1, '+' 2.
    std::vector<std::string_view> summed;
    for (std::size_t i = start_; i <= values_[kEpochRev].index; ++i) summed.push_back(lines_[i].text);
    const int sum = amsat_checksum(summed);
    const AmsatValue& c = values_[kChecksum];
    std::optional<ParseProblem> checksum_problem;
    if (!c.present) {
      checksum_problem = make_problem(file_, lines_[start_].number, 0, kAmsatLabels[kChecksum], "",
                                      "a 'Checksum:' line (" + std::to_string(sum) + " for this block)");
    } else if (const auto given = parse_unsigned(c.token); !given || *given != sum) {
      checksum_problem = make_problem(file_, c.line, c.column, kAmsatLabels[kChecksum], std::string(c.token),
                                      "checksum " + std::to_string(sum));
    }
    if (checksum_problem) {
      // Strict (a serial upload) rejects a wrong checksum; a block without a "Checksum:" line, which
      // the TrakBox manual never mentions, is accepted with a warning either way.
      const bool reject = options_.strict_amsat_checksum && c.present;
      checksum_problem->warning = !reject;
      result.problems.push_back(std::move(*checksum_problem));
      if (reject) return;
    }
    result.sets.push_back(std::move(e));
  }

 private:
  ParseProblem problem(int field, std::string expected) const {
    const AmsatValue& v = values_[field];
    return make_problem(file_, v.line, v.column, kAmsatLabels[field], std::string(v.token), std::move(expected));
  }

  std::optional<ParseProblem> number(int field, double low, double high, bool high_inclusive, double& out) const {
    const auto v = parse_general(values_[field].token);
    if (!v) return problem(field, "decimal number");
    if (auto range = out_of_range(*v, low, high, high_inclusive)) return problem(field, std::move(*range));
    out = *v;
    return std::nullopt;
  }

  std::optional<ParseProblem> count(int field, long& out) const {
    const auto v = parse_unsigned(values_[field].token);
    if (!v) return problem(field, "digits 0-9");
    out = *v;
    return std::nullopt;
  }

  std::optional<ParseProblem> decode(Elements& e) const {
    for (int f = kCatalog; f <= kEpochRev; ++f) {
      if (!values_[f].present) {
        return make_problem(file_, lines_[start_].number, 0, kAmsatLabels[f], "",
                            std::string("a '") + kAmsatLabels[f] + ":' line in the block");
      }
    }
    if (duplicate_) return duplicate_;

    e.source = ElementFormat::amsat;
    e.name = std::string(values_[kSatellite].rest);

    const std::string_view catalog = values_[kCatalog].token;
    if (const auto digits = parse_unsigned(catalog)) e.catalog_number = static_cast<int>(*digits);
    else e.catalog_number = decode_catalog_number(catalog);
    if (e.catalog_number < 0) return problem(kCatalog, "digits or Alpha-5 (letter A-Z without I and O, 4 digits)");

    // YYDDD.DDDDDDDD; leading zeros of the year may have been dropped by a generator.
    const std::string_view epoch = values_[kEpochTime].token;
    const auto point = epoch.find('.');
    const std::string_view whole = epoch.substr(0, point);
    const std::string_view fraction = point == std::string_view::npos ? std::string_view{} : epoch.substr(point + 1);
    if (!all_digits(whole) || whole.size() > 5 || (!fraction.empty() && !all_digits(fraction)))
      return problem(kEpochTime, "YYDDD.DDDDDDDD");
    const long yyddd = *parse_unsigned(whole);
    e.epoch_year = expand_two_digit_year(static_cast<int>(yyddd / 1000));
    const std::string day_text = std::to_string(yyddd % 1000) + "." + (fraction.empty() ? "0" : std::string(fraction));
    e.epoch_day = *text::parse_double(day_text);
    const double day_limit = is_leap_year(e.epoch_year) ? 367.0 : 366.0;
    if (e.epoch_day < 1.0 || e.epoch_day >= day_limit)
      return problem(kEpochTime, "day of year in [1, " + std::to_string(int(day_limit)) + ")");

    long element_set = 0;
    if (auto p = count(kElementSet, element_set)) return p;
    e.element_set_number = static_cast<int>(element_set);
    if (auto p = number(kInclination, 0.0, 180.0, true, e.inclination_deg)) return p;
    if (auto p = number(kRaan, 0.0, 360.0, false, e.raan_deg)) return p;
    if (auto p = number(kEccentricity, 0.0, 1.0, false, e.eccentricity)) return p;
    if (auto p = number(kArgPerigee, 0.0, 360.0, false, e.arg_perigee_deg)) return p;
    if (auto p = number(kMeanAnomaly, 0.0, 360.0, false, e.mean_anomaly_deg)) return p;
    const auto n = parse_general(values_[kMeanMotion].token);
    if (!n) return problem(kMeanMotion, "decimal number");
    if (!(*n > 0.0)) return problem(kMeanMotion, "number > 0");
    e.mean_motion_rev_per_day = *n;
    const auto decay = parse_general(values_[kDecayRate].token);
    if (!decay) return problem(kDecayRate, "decimal number such as -4.5e-07");
    e.ndot_over_2 = *decay;
    if (auto p = count(kEpochRev, e.revolution_number)) return p;
    return std::nullopt;
  }

  const std::vector<TextLine>& lines_;
  std::size_t start_;
  std::string_view file_;
  const ParseOptions& options_;
  AmsatValue values_[kAmsatFieldCount];
  std::optional<ParseProblem> duplicate_;
};

}  // namespace

namespace detail {

bool starts_amsat_block(std::string_view line) {
  const LabelledLine label = split_label(line);
  return !label.label.empty() && amsat_field_of(label.label) == kSatellite;
}

}  // namespace detail

ParseResult parse_amsat(std::string_view text, std::string_view file_name, const ParseOptions& options) {
  ParseResult result;
  const std::vector<TextLine> lines = split_lines(text);
  std::unique_ptr<AmsatBlock> block;  // the block being read
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string_view line = lines[i].text;
    const LabelledLine l = is_blank(line) ? LabelledLine{} : split_label(line);
    const int field = l.label.empty() ? -1 : amsat_field_of(l.label);
    if (block) {
      // A block ends at a blank line, a line without a colon (free text, "/EX"), the next
      // "Satellite:" or after its "Checksum:". Other labelled lines ("Beacon:") are ignored.
      if (l.label.empty() || field == kSatellite) {
        block->finish(result);
        block.reset();
      } else {
        if (field >= 0) block->add(field, i, l);
        if (field == kChecksum) {
          block->finish(result);
          block.reset();
        }
        continue;
      }
    }
    if (field == kSatellite) {
      block = std::make_unique<AmsatBlock>(lines, i, file_name, options);
      block->add(kSatellite, i, l);
    }
  }
  if (block) block->finish(result);
  return result;
}

namespace {

// Shortest scientific text that gives back the value, in the AMSAT style "-4.5e-07".
std::string decay_rate_text(double v) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
  std::string t(buf, end);
  if (t.find('.') == std::string::npos) t.insert(t.find('e'), ".0");
  return t;
}

}  // namespace

std::string format_amsat(const Elements& e) {
  // The layout AMSAT's bulletins use: four values left-aligned at column 17/18, the others
  // right-aligned to end at column 26, then the unit.
  auto right = [](const char* label, const std::string& value, const char* unit) {
    std::string line = std::string(label) + ":";
    const std::size_t used = line.size() + value.size();
    line += std::string(used < 26 ? 26 - used : 1, ' ') + value;
    if (*unit) line += std::string(" ") + unit;
    return line;
  };
  std::vector<std::string> lines;
  lines.push_back(e.name.empty() ? "Satellite:" : "Satellite: " + e.name);
  lines.push_back("Catalog number: " + (e.catalog_number >= 0 && e.catalog_number <= 99999
                                            ? printf_string("%05d", e.catalog_number)
                                            : std::to_string(e.catalog_number)));
  lines.push_back("Epoch time:      " + epoch_text(e.epoch_year, e.epoch_day, true));
  lines.push_back("Element set:     " + std::to_string(e.element_set_number));
  lines.push_back(right("Inclination", round_trip_fixed(e.inclination_deg, 4), "deg"));
  lines.push_back(right("RA of node", round_trip_fixed(e.raan_deg, 4), "deg"));
  lines.push_back(right("Eccentricity", round_trip_fixed(e.eccentricity, 7), ""));
  lines.push_back(right("Arg of perigee", round_trip_fixed(e.arg_perigee_deg, 4), "deg"));
  lines.push_back(right("Mean anomaly", round_trip_fixed(e.mean_anomaly_deg, 4), "deg"));
  lines.push_back(right("Mean motion", round_trip_fixed(e.mean_motion_rev_per_day, 8), "rev/day"));
  lines.push_back(right("Decay rate", decay_rate_text(e.ndot_over_2), "rev/day^2"));
  lines.push_back(right("Epoch rev", std::to_string(e.revolution_number), ""));
  const std::vector<std::string_view> summed(lines.begin(), lines.end());
  lines.push_back(right("Checksum", std::to_string(amsat_checksum(summed)), ""));
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

}  // namespace tb::orbit
