// NASA two-line and three-line element sets: the reader, the writer, checksums and Alpha-5 catalog
// numbers. docs/element-formats.md has what is accepted and how problems are reported.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <utility>

#include "orbit/elements.h"
#include "orbit/elements_internal.h"

namespace tb::orbit {
namespace detail {
namespace {

// The TLE's implied-decimal exponent field, 8 columns: sign (blank, + or -), five digits with an
// implied leading point, exponent sign (+ or -), one exponent digit. "-11606-4" = -0.11606e-4.
std::optional<double> parse_implied_exponent(std::string_view f) {
  if (f.size() != 8) return std::nullopt;
  const char sign = f[0];
  if (sign != ' ' && sign != '+' && sign != '-') return std::nullopt;
  const std::string_view mantissa = f.substr(1, 5);
  if (!all_digits(mantissa) || (f[6] != '+' && f[6] != '-') || !is_digit(f[7])) return std::nullopt;
  std::string number = "0.";
  number += mantissa;
  number += 'e';
  if (f[6] == '-') number += '-';
  number += f[7];
  const auto v = text::parse_double(number);
  if (!v) return std::nullopt;
  return sign == '-' ? -*v : *v;
}

struct FieldSpec {
  int first;
  int last;
  const char* name;
};

constexpr FieldSpec kLine1Fields[] = {
    {1, 1, "line number"},      {3, 7, "catalog number"},   {8, 8, "classification"},
    {10, 17, "international designator"}, {19, 20, "epoch year"}, {21, 32, "epoch day"},
    {34, 43, "ndot/2"},         {45, 52, "nddot/6"},        {54, 61, "BSTAR"},
    {63, 63, "ephemeris type"}, {65, 68, "element set number"}, {69, 69, "checksum"},
};
constexpr FieldSpec kLine2Fields[] = {
    {1, 1, "line number"},        {3, 7, "catalog number"}, {9, 16, "inclination"},
    {18, 25, "RAAN"},             {27, 33, "eccentricity"}, {35, 42, "argument of perigee"},
    {44, 51, "mean anomaly"},     {53, 63, "mean motion"},  {64, 68, "revolution number"},
    {69, 69, "checksum"},
};

// A line shorter than the format: the first field it cuts is reported.
template <std::size_t N>
std::optional<ParseProblem> check_length(const ElementLine& l, const FieldSpec (&fields)[N], bool with_checksum) {
  const int needed = with_checksum ? 69 : 68;
  const int length = static_cast<int>(l.text.size());
  if (length >= needed) return std::nullopt;
  for (const FieldSpec& f : fields) {
    if (f.last > length) {
      return l.problem(f.first, f.last, f.name,
                       std::to_string(needed) + " columns (the line ends at column " + std::to_string(length) + ")");
    }
  }
  return std::nullopt;  // not reached: the checksum field always lies beyond a short line
}

std::optional<ParseProblem> check_blank(const ElementLine& l, int column) {
  if (l.at(column) == ' ') return std::nullopt;
  return l.problem(column, column, "separator", "blank");
}

std::optional<ParseProblem> check_checksum(const ElementLine& l) {
  const int sum = nasa_checksum(l.text);
  if (l.at(69) - '0' == sum) return std::nullopt;
  return l.problem(69, 69, "checksum", "checksum " + std::to_string(sum));
}

std::optional<ParseProblem> parse_catalog(const ElementLine& l, int& number) {
  number = decode_catalog_number(l.raw(3, 7));
  if (number >= 0) return std::nullopt;
  return l.problem(3, 7, "catalog number", "5 digits or Alpha-5 (letter A-Z without I and O, 4 digits)");
}

// Decimal field with a range check; blank is not allowed.
std::optional<ParseProblem> parse_decimal_field(const ElementLine& l, const FieldSpec& f, double low, double high,
                                                bool high_inclusive, double& out) {
  const auto v = parse_fixed(l.raw(f.first, f.last));
  if (!v) return l.problem(f.first, f.last, f.name, "decimal number");
  if (auto range = out_of_range(*v, low, high, high_inclusive))
    return l.problem(f.first, f.last, f.name, std::move(*range));
  out = *v;
  return std::nullopt;
}

// A field that may be all blank, read as 0; otherwise `parse` reads it, `expected` naming what it takes.
template <class T, class Parse>
std::optional<ParseProblem> parse_blank_or(const ElementLine& l, const FieldSpec& f, T& out, Parse parse,
                                           const char* expected) {
  const std::string_view raw = l.raw(f.first, f.last);
  if (is_blank(raw)) {
    out = T{};
    return std::nullopt;
  }
  const auto v = parse(raw);
  if (!v) return l.problem(f.first, f.last, f.name, expected);
  out = *v;
  return std::nullopt;
}

// Unsigned integer field, blank allowed (0).
std::optional<ParseProblem> parse_count_field(const ElementLine& l, const FieldSpec& f, long& out) {
  return parse_blank_or(l, f, out, parse_unsigned, "digits 0-9");
}

// Implied-decimal exponent field; all blank is read as 0.
std::optional<ParseProblem> parse_exponent_field(const ElementLine& l, const FieldSpec& f, double& out) {
  return parse_blank_or(l, f, out, parse_implied_exponent, "implied-decimal exponent field such as -11606-4");
}

}  // namespace

std::optional<ParseProblem> parse_line1(const ElementLine& l, const ParseOptions& options, Elements& e) {
  const auto& F = kLine1Fields;
  if (auto p = check_length(l, F, options.verify_checksums)) return p;
  if (l.at(1) != '1') return l.problem(1, 1, F[0].name, "1");
  if (auto p = check_blank(l, 2)) return p;
  if (auto p = parse_catalog(l, e.catalog_number)) return p;

  const char cls = l.at(8);
  if (cls != ' ' && !is_upper(cls)) return l.problem(8, 8, F[2].name, "letter such as U, C or S");
  e.classification = cls == ' ' ? 'U' : cls;
  if (auto p = check_blank(l, 9)) return p;

  const std::string_view designator = l.raw(10, 17);
  if (!std::all_of(designator.begin(), designator.end(), [](char c) { return c == ' ' || is_digit(c) || is_upper(c); }))
    return l.problem(10, 17, F[3].name, "digits, capital letters and blanks, such as 98067A");
  e.international_designator = std::string(trim(designator));
  if (auto p = check_blank(l, 18)) return p;

  const std::string_view year = l.raw(19, 20);
  const auto yy = parse_unsigned(year);
  if (!yy || year[1] == ' ') return l.problem(19, 20, F[4].name, "two digits 00-99");
  e.epoch_year = expand_two_digit_year(static_cast<int>(*yy));
  const double day_limit = is_leap_year(e.epoch_year) ? 367.0 : 366.0;
  if (auto p = parse_decimal_field(l, F[5], 1.0, day_limit, false, e.epoch_day)) {
    if (p->expected != "decimal number") p->expected = "day of year in [1, " + std::to_string(int(day_limit)) + ")";
    return p;
  }
  if (auto p = check_blank(l, 33)) return p;

  const auto ndot = parse_fixed(l.raw(34, 43));
  if (!ndot) return l.problem(34, 43, F[6].name, "decimal number such as -.00002182");
  e.ndot_over_2 = *ndot;
  if (auto p = check_blank(l, 44)) return p;
  if (auto p = parse_exponent_field(l, F[7], e.nddot_over_6)) return p;
  if (auto p = check_blank(l, 53)) return p;
  if (auto p = parse_exponent_field(l, F[8], e.bstar)) return p;
  if (auto p = check_blank(l, 62)) return p;

  const char eph = l.at(63);
  if (eph != ' ' && !is_digit(eph)) return l.problem(63, 63, F[9].name, "digit 0-9 or blank");
  e.ephemeris_type = eph == ' ' ? 0 : eph - '0';
  if (auto p = check_blank(l, 64)) return p;

  long element_set = 0;
  if (auto p = parse_count_field(l, F[10], element_set)) return p;
  e.element_set_number = static_cast<int>(element_set);

  if (options.verify_checksums) return check_checksum(l);
  return std::nullopt;
}

std::optional<ParseProblem> parse_line2(const ElementLine& l, const ParseOptions& options, Elements& e) {
  const auto& F = kLine2Fields;
  if (auto p = check_length(l, F, options.verify_checksums)) return p;
  if (l.at(1) != '2') return l.problem(1, 1, F[0].name, "2");
  if (auto p = check_blank(l, 2)) return p;
  int catalog = 0;
  if (auto p = parse_catalog(l, catalog)) return p;
  if (catalog != e.catalog_number)
    return l.problem(3, 7, F[1].name, encode_catalog_number(e.catalog_number) + " as on line 1");
  if (auto p = check_blank(l, 8)) return p;
  if (auto p = parse_decimal_field(l, F[2], 0.0, 180.0, true, e.inclination_deg)) return p;
  if (auto p = check_blank(l, 17)) return p;
  if (auto p = parse_decimal_field(l, F[3], 0.0, 360.0, false, e.raan_deg)) return p;
  if (auto p = check_blank(l, 26)) return p;

  // Seven digits after an implied "0."; leading blanks read as zeros (right-aligned digits).
  std::string digits(l.raw(27, 33));
  const auto first_digit = digits.find_first_not_of(' ');
  if (first_digit != std::string::npos) std::fill_n(digits.begin(), first_digit, '0');
  if (!all_digits(digits)) return l.problem(27, 33, F[4].name, "7 digits (implied leading decimal point)");
  e.eccentricity = *text::parse_double("0." + digits);
  if (auto p = check_blank(l, 34)) return p;

  if (auto p = parse_decimal_field(l, F[5], 0.0, 360.0, false, e.arg_perigee_deg)) return p;
  if (auto p = check_blank(l, 43)) return p;
  if (auto p = parse_decimal_field(l, F[6], 0.0, 360.0, false, e.mean_anomaly_deg)) return p;
  if (auto p = check_blank(l, 52)) return p;
  const auto n = parse_fixed(l.raw(53, 63));
  if (!n) return l.problem(53, 63, F[7].name, "decimal number");
  // The field's smallest step: a smaller value (".0000000014", more digits than the field's 8
  // decimals) would be written back as 0, which no reader takes (found by fuzz_elements).
  if (!(*n >= 0.5e-8)) return l.problem(53, 63, F[7].name, "number >= 0.00000001");
  e.mean_motion_rev_per_day = *n;
  if (auto p = parse_count_field(l, F[8], e.revolution_number)) return p;

  if (options.verify_checksums) return check_checksum(l);
  return std::nullopt;
}

}  // namespace detail

using namespace detail;

namespace {

enum class LineKind { skip, name, line1, line2 };

LineKind classify(std::string_view line) {
  const std::string_view t = trim_left(line);
  if (t.empty() || t.front() == '#') return LineKind::skip;
  if (line.size() == 1 || line[1] == ' ') {
    if (line[0] == '1') return LineKind::line1;
    if (line[0] == '2') return LineKind::line2;
  }
  return LineKind::name;
}

std::string name_from_line(std::string_view line) {
  line = trim(line);
  if (line.starts_with("0 ")) line = trim(line.substr(2));  // Space-Track's three-line form
  return std::string(line);
}

// The line as quoted in a problem: trailing blanks removed, at most the 69 columns of the format.
std::string quote_line(std::string_view line) { return std::string(trim_right(line.substr(0, 69))); }

constexpr std::string_view kAlpha5Letters = "ABCDEFGHJKLMNPQRSTUVWXYZ";  // A=10 ... Z=33

}  // namespace

int nasa_checksum(std::string_view line) {
  int sum = 0;
  for (const char c : line.substr(0, 68)) {
    if (is_digit(c)) sum += c - '0';
    else if (c == '-') sum += 1;
  }
  return sum % 10;
}

int decode_catalog_number(std::string_view s) {
  if (s.size() != 5) return -1;
  if (is_upper(s[0])) {
    const auto letter = kAlpha5Letters.find(s[0]);
    if (letter == std::string_view::npos || !all_digits(s.substr(1))) return -1;
    return static_cast<int>(letter + 10) * 10000 + static_cast<int>(*parse_unsigned(s.substr(1)));
  }
  const std::string_view digits = trim_left(s);  // leading blanks: an unpadded number
  if (!all_digits(digits)) return -1;
  return static_cast<int>(*parse_unsigned(digits));
}

std::string encode_catalog_number(int number) {
  char buf[16];
  if (number >= 0 && number <= 99999) {
    std::snprintf(buf, sizeof buf, "%05d", number);
  } else if (number >= 100000 && number <= 339999) {
    std::snprintf(buf, sizeof buf, "%c%04d", kAlpha5Letters[static_cast<std::size_t>(number / 10000 - 10)],
                  number % 10000);
  } else {
    return {};
  }
  return buf;
}

ParseResult parse_nasa(std::string_view text, std::string_view file_name, const ParseOptions& options) {
  ParseResult result;
  const std::vector<TextLine> lines = split_lines(text);
  const std::size_t n = lines.size();
  auto next_significant = [&](std::size_t i) {
    while (i < n && classify(lines[i].text) == LineKind::skip) ++i;
    return i;
  };
  auto kind_at = [&](std::size_t i) { return i < n ? classify(lines[i].text) : LineKind::skip; };
  auto element_line = [&](std::size_t i) { return ElementLine{lines[i].text, lines[i].number, 0, file_name}; };

  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::size_t name_index = kNone;  // the text line just before, a candidate name
  for (std::size_t i = next_significant(0); i < n; i = next_significant(i)) {
    const TextLine& line = lines[i];
    switch (classify(line.text)) {
      case LineKind::skip:  // not reached: next_significant() passes over these
        ++i;
        break;
      case LineKind::name:
        name_index = i;  // a text line not followed by line 1 is simply replaced (bulletin text)
        ++i;
        break;
      case LineKind::line2: {
        // Line 2 without line 1. When line 1 of the same satellite follows and is not itself
        // followed by a line 2, the two were swapped: one problem for the pair.
        const std::size_t j = next_significant(i + 1);
        const bool swapped = kind_at(j) == LineKind::line1 && kind_at(next_significant(j + 1)) != LineKind::line2 &&
                             element_line(i).raw(3, 7) == element_line(j).raw(3, 7);
        result.problems.push_back(make_problem(file_name, line.number, 1, "line 1", quote_line(line.text),
                                               "line 1 before line 2"));
        i = swapped ? j + 1 : i + 1;
        name_index = kNone;
        break;
      }
      case LineKind::line1: {
        Elements e;
        e.source = ElementFormat::nasa;
        if (name_index != kNone) e.name = name_from_line(lines[name_index].text);
        name_index = kNone;
        const std::size_t j = next_significant(i + 1);
        const bool has_line2 = kind_at(j) == LineKind::line2;
        std::optional<ParseProblem> problem = parse_line1(element_line(i), options, e);
        if (!problem && !has_line2) {
          if (j < n) {
            problem = make_problem(file_name, lines[j].number, 1, "line 2", quote_line(lines[j].text),
                                   "line 2 after line 1");
          } else {
            problem = make_problem(file_name, line.number + 1, 1, "line 2", "", "line 2 after line 1");
          }
        }
        if (!problem) problem = parse_line2(element_line(j), options, e);
        if (problem) result.problems.push_back(std::move(*problem));
        else result.sets.push_back(std::move(e));
        i = has_line2 ? j + 1 : i + 1;
        break;
      }
    }
  }
  return result;
}

namespace {

// Right-aligned fixed-point text of exactly `width` columns, with as many of `decimals` decimals
// as fit; '*' when even no decimal fits (a value no element set can hold).
std::string fixed_columns(double v, int width, int decimals) {
  for (int d = decimals; d >= 0; --d) {
    std::string t = printf_string("%*.*f", width, d, v);
    if (static_cast<int>(t.size()) <= width) return t;
  }
  return std::string(static_cast<std::size_t>(width), '*');
}

// An angle in [0, 360) in columns "ddd.dddd": a value that rounds up to 360 is written as 0.
std::string angle_columns(double deg) {
  std::string t = fixed_columns(deg, 8, 4);
  return t == "360.0000" ? "  0.0000" : t;
}

// ndot/2 in 10 columns: sign or blank, then the number without its leading zero (".00002182").
std::string ndot_columns(double v) {
  const char sign = std::signbit(v) ? '-' : ' ';
  for (int d = 8; d >= 0; --d) {
    std::string t = printf_string("%.*f", d, std::fabs(v));
    if (t.starts_with("0.")) t.erase(0, 1);
    if (t.size() <= 9) return sign + std::string(9 - t.size(), ' ') + t;
    // The reader takes all 10 columns as the number, so a positive one may use the sign's column
    // (no real satellite has such a value, but what was read must write back).
    if (t.size() == 10 && sign == ' ') return t;
  }
  return std::string(10, '*');
}

// The implied-decimal exponent field, 8 columns: "-11606-4" for -0.11606e-4. Zero is " 00000-0".
std::string implied_exponent_columns(double v) {
  const std::string sign(1, std::signbit(v) ? '-' : ' ');
  const double a = std::fabs(v);
  if (a == 0.0) return sign + "00000-0";
  const std::string e = printf_string("%.4e", a);  // d.dddde+XX, correctly rounded
  const int exponent = std::atoi(e.c_str() + 7) + 1;
  if (exponent > 9) return sign + "99999+9";  // beyond the field: the largest it holds
  if (exponent < -9) {                         // below 0.1e-9: leading zeros in the mantissa
    const long long m = std::llround(a * 1e14);
    return m == 0 ? sign + "00000-0" : sign + printf_string("%05lld", m) + "-9";
  }
  return sign + e.substr(0, 1) + e.substr(2, 4) + (exponent < 0 ? '-' : '+') +
         static_cast<char>('0' + std::abs(exponent));
}

// A name the NASA parser would take for something else gets Space-Track's "0 " prefix.
std::string name_line(const std::string& name) {
  if (classify(name) != LineKind::name || name.starts_with("0 ")) return "0 " + name;
  return name;
}

}  // namespace

std::optional<std::string> nasa_unwritable(const Elements& e) {
  if (e.catalog_number < 0 || e.catalog_number > kMaxTleCatalogNumber)
    return "catalog number " + std::to_string(e.catalog_number) +
           " does not fit a TLE (at most 339999, Alpha-5 Z9999); write it as OMM";
  if (e.epoch_year < 1957 || e.epoch_year > 2056)
    return "epoch year " + std::to_string(e.epoch_year) + " does not fit a TLE's two digits (1957-2056)";
  return std::nullopt;
}

std::string format_nasa(const Elements& e, bool with_name) {
  if (nasa_unwritable(e)) return {};  // never a truncated number or a wrong century
  const std::string catalog = encode_catalog_number(e.catalog_number);

  std::string l1 = "1 " + catalog;
  l1 += is_upper(e.classification) ? e.classification : 'U';
  l1 += ' ';
  std::string designator = e.international_designator.substr(0, 8);
  designator.resize(8, ' ');
  l1 += designator + ' ';
  std::string epoch = epoch_text(e.epoch_year, e.epoch_day, false);
  if (epoch.size() != 14) epoch = std::string(14, '*');
  l1 += epoch + ' ';
  l1 += ndot_columns(e.ndot_over_2) + ' ';
  l1 += implied_exponent_columns(e.nddot_over_6) + ' ';
  l1 += implied_exponent_columns(e.bstar) + ' ';
  l1 += static_cast<char>(e.ephemeris_type >= 0 && e.ephemeris_type <= 9 ? '0' + e.ephemeris_type : '0');
  l1 += ' ';
  l1 += printf_string("%4d", e.element_set_number >= 0 ? e.element_set_number % 10000 : 0);
  l1 += static_cast<char>('0' + nasa_checksum(l1));

  std::string l2 = "2 " + catalog + ' ';
  l2 += fixed_columns(e.inclination_deg, 8, 4) + ' ';
  l2 += angle_columns(e.raan_deg) + ' ';
  const std::string ecc = printf_string("%.7f", std::clamp(e.eccentricity, 0.0, 0.9999999));
  l2 += ecc.substr(2, 7) + ' ';
  l2 += angle_columns(e.arg_perigee_deg) + ' ';
  l2 += angle_columns(e.mean_anomaly_deg) + ' ';
  l2 += fixed_columns(e.mean_motion_rev_per_day, 11, 8);
  l2 += printf_string("%5ld", e.revolution_number >= 0 ? e.revolution_number % 100000 : 0L);
  l2 += static_cast<char>('0' + nasa_checksum(l2));

  std::string out;
  if (with_name && !e.name.empty()) out += name_line(e.name) + "\n";
  return out + l1 + "\n" + l2 + "\n";
}

}  // namespace tb::orbit
