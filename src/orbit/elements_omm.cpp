// CCSDS OMM: one object's keywords into an element set, whatever the encoding they came in
// (elements_omm_internal.h). Only SGP4 mean elements are taken; docs/element-formats.md lists the
// keywords used and what is refused.
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "orbit/elements_fields.h"
#include "orbit/elements_omm_internal.h"

namespace tb::orbit::detail {
namespace {

constexpr int kDaysInMonth[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
constexpr int kFirstYear = 1957, kLastYear = 2100;

struct Epoch {
  int year = 0;
  double day = 0.0;
};

// "YYYY-MM-DDTHH:MM:SS[.f...][Z]" or the day-of-year form "YYYY-DDDTHH:MM:SS[.f...][Z]".
std::optional<Epoch> parse_epoch(std::string_view s) {
  s = trim(s);
  if (s.ends_with('Z') || s.ends_with('z')) s.remove_suffix(1);
  const auto t = s.find('T');
  if (t == std::string_view::npos) return std::nullopt;
  const std::string_view date = s.substr(0, t), time = s.substr(t + 1);
  if (date.size() < 8 || date[4] != '-' || !all_digits(date.substr(0, 4))) return std::nullopt;
  const int year = static_cast<int>(*parse_unsigned(date.substr(0, 4)));
  if (year < kFirstYear || year > kLastYear) return std::nullopt;
  int doy = 0;
  if (date.size() == 8) {  // YYYY-DDD
    if (!all_digits(date.substr(5))) return std::nullopt;
    doy = static_cast<int>(*parse_unsigned(date.substr(5)));
    if (doy < 1 || doy > (is_leap_year(year) ? 366 : 365)) return std::nullopt;
  } else {
    if (date.size() != 10 || date[7] != '-' || !all_digits(date.substr(5, 2)) || !all_digits(date.substr(8)))
      return std::nullopt;
    const int month = static_cast<int>(*parse_unsigned(date.substr(5, 2)));
    const int day = static_cast<int>(*parse_unsigned(date.substr(8)));
    if (month < 1 || month > 12) return std::nullopt;
    const int length = kDaysInMonth[month - 1] + (month == 2 && is_leap_year(year) ? 1 : 0);
    if (day < 1 || day > length) return std::nullopt;
    for (int m = 1; m < month; ++m) doy += kDaysInMonth[m - 1] + (m == 2 && is_leap_year(year) ? 1 : 0);
    doy += day;
  }
  if (time.size() < 8 || time[2] != ':' || time[5] != ':' || !all_digits(time.substr(0, 2)) ||
      !all_digits(time.substr(3, 2)) || !all_digits(time.substr(6, 2)))
    return std::nullopt;
  const std::string_view second_text = time.substr(6);
  if (second_text.size() > 2 && (second_text[2] != '.' || !all_digits(second_text.substr(3)))) return std::nullopt;
  const int hour = static_cast<int>(*parse_unsigned(time.substr(0, 2)));
  const int minute = static_cast<int>(*parse_unsigned(time.substr(3, 2)));
  const auto second = parse_fixed(second_text);
  if (hour > 23 || minute > 59 || !second || *second >= 60.0) return std::nullopt;
  const Epoch epoch{year, doy + (hour * 3600.0 + minute * 60.0 + *second) / 86400.0};
  // The last moments of the last year would be written back (to the microsecond) in the next one.
  if (year == kLastYear && to_civil(from_year_day(year, epoch.day)).year != year) return std::nullopt;
  return epoch;
}

bool is_designator_piece(char c) { return is_upper(c); }

// One object's keywords and the problems about them: each names the object and the keyword.
class ObjectReader {
 public:
  ObjectReader(const OmmObject& o, int index, std::string_view file)
      : o_(o), file_(file), label_(omm_object_label(o, index)) {}

  const OmmField* find(std::string_view key) const {
    for (const OmmField& f : o_.fields)
      if (text::iequals(f.key, key)) return &f;
    return nullptr;
  }
  // The field when it is there with a value; an empty value counts as absent.
  const OmmField* value(std::string_view key) const {
    const OmmField* f = find(key);
    return f && !f->value.empty() ? f : nullptr;
  }

  ParseProblem problem(const OmmField* f, std::string_view key, std::string expected, bool warning = false) const {
    ParseProblem p = make_problem(file_, f ? f->line : o_.line, 0, std::string(key), f ? f->value : std::string(),
                                  std::move(expected), warning);
    p.object = label_;
    return p;
  }

  // The first keyword given twice, if any (an empty key, e.g. an empty CSV header cell, is no
  // keyword and is ignored).
  std::optional<ParseProblem> duplicate() const {
    for (std::size_t i = 0; i < o_.fields.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (!o_.fields[i].key.empty() && text::iequals(o_.fields[i].key, o_.fields[j].key))
          return problem(&o_.fields[i], o_.fields[i].key, "the keyword once per object (also on line " +
                                                              std::to_string(o_.fields[j].line) + ")");
    return std::nullopt;
  }

  // A keyword that, when present, must have this value (case ignored).
  std::optional<ParseProblem> must_be(std::string_view key, std::string_view wanted, const char* why) const {
    const OmmField* f = value(key);
    if (!f || text::iequals(f->value, wanted)) return std::nullopt;
    return problem(f, key, std::string(wanted) + " (" + why + ")");
  }

  std::optional<ParseProblem> number(std::string_view key, bool required, double low, double high,
                                     bool high_inclusive, double& out) const {
    const OmmField* f = value(key);
    if (!f) {
      if (!required) return std::nullopt;
      return problem(find(key), key, "the keyword with a number (it is required)");
    }
    const auto v = parse_general(f->value);
    if (!v) return problem(f, key, "a number such as 15.49291753 or 1.1282e-4");
    if (auto range = out_of_range(*v, low, high, high_inclusive)) return problem(f, key, std::move(*range));
    out = *v;
    return std::nullopt;
  }

  std::optional<ParseProblem> whole(std::string_view key, bool required, long& out) const {
    const OmmField* f = value(key);
    if (!f) {
      if (!required) return std::nullopt;
      return problem(find(key), key, "the keyword with a whole number (it is required)");
    }
    const auto v = parse_unsigned(f->value);
    if (!v) return problem(f, key, "a whole number 0..999999999");
    out = *v;
    return std::nullopt;
  }

  std::optional<ParseProblem> epoch(Elements& e) const {
    const OmmField* f = value("EPOCH");
    if (!f) return problem(find("EPOCH"), "EPOCH", "the keyword with a UTC time (it is required)");
    const auto epoch = parse_epoch(f->value);
    if (!epoch)
      return problem(f, "EPOCH", "ISO 8601 UTC YYYY-MM-DDTHH:MM:SS[.ffffff] (or YYYY-DDDT...), year " +
                                     std::to_string(kFirstYear) + "-" + std::to_string(kLastYear));
    e.epoch_year = epoch->year;
    e.epoch_day = epoch->day;
    return std::nullopt;
  }

  const std::string& label() const { return label_; }

 private:
  const OmmObject& o_;
  std::string_view file_;
  std::string label_;
};

// What makes an object something other than SGP4 mean elements.
std::optional<ParseProblem> check_theory(const ObjectReader& r) {
  if (auto p = r.must_be("MEAN_ELEMENT_THEORY", "SGP4", "only SGP4 mean elements are SGP4 input; SGP4-XP is not"))
    return p;
  if (auto p = r.must_be("REF_FRAME", "TEME", "SGP4 elements are in the TEME frame")) return p;
  if (auto p = r.must_be("CENTER_NAME", "EARTH", "SGP4 orbits the Earth")) return p;
  if (auto p = r.must_be("TIME_SYSTEM", "UTC", "SGP4 epochs are UTC")) return p;
  if (const OmmField* f = r.value("EPHEMERIS_TYPE"); f && parse_unsigned(f->value) != 0L)
    return r.problem(f, "EPHEMERIS_TYPE", "0 (SGP4 elements; other types are not SGP4 input)");
  return std::nullopt;
}

// The six mean elements and the drag terms.
std::optional<ParseProblem> read_orbit(const ObjectReader& r, Elements& e) {
  if (auto p = r.number("MEAN_MOTION", true, 0.0, 20.0, true, e.mean_motion_rev_per_day)) return p;
  if (!(e.mean_motion_rev_per_day > 0.0)) return r.problem(r.value("MEAN_MOTION"), "MEAN_MOTION", "number > 0");
  if (auto p = r.number("ECCENTRICITY", true, 0.0, 1.0, false, e.eccentricity)) return p;
  if (auto p = r.number("INCLINATION", true, 0.0, 180.0, true, e.inclination_deg)) return p;
  if (auto p = r.number("RA_OF_ASC_NODE", true, 0.0, 360.0, false, e.raan_deg)) return p;
  if (auto p = r.number("ARG_OF_PERICENTER", true, 0.0, 360.0, false, e.arg_perigee_deg)) return p;
  if (auto p = r.number("MEAN_ANOMALY", true, 0.0, 360.0, false, e.mean_anomaly_deg)) return p;
  if (auto p = r.number("BSTAR", true, -1.0, 1.0, true, e.bstar)) return p;
  if (auto p = r.number("MEAN_MOTION_DOT", false, -1.0, 1.0, true, e.ndot_over_2)) return p;
  return r.number("MEAN_MOTION_DDOT", false, -1.0, 1.0, true, e.nddot_over_6);
}

// Catalog number, classification, element set and revolution numbers.
std::optional<ParseProblem> read_numbers(const ObjectReader& r, Elements& e) {
  long catalog = 0;
  if (auto p = r.whole("NORAD_CAT_ID", true, catalog)) return p;
  e.catalog_number = static_cast<int>(catalog);
  if (const OmmField* f = r.value("CLASSIFICATION_TYPE")) {
    if (f->value.size() != 1 || !is_upper(f->value[0]))
      return r.problem(f, "CLASSIFICATION_TYPE", "one capital letter such as U, C or S");
    e.classification = f->value[0];
  }
  long element_set = 0;
  if (auto p = r.whole("ELEMENT_SET_NO", false, element_set)) return p;
  e.element_set_number = static_cast<int>(element_set);
  return r.whole("REV_AT_EPOCH", false, e.revolution_number);
}

}  // namespace

std::string omm_object_label(const OmmObject& object, int index) {
  std::string name, number;
  for (const OmmField& f : object.fields) {
    if (text::iequals(f.key, "OBJECT_NAME")) name = f.value;
    if (text::iequals(f.key, "NORAD_CAT_ID")) number = f.value;
  }
  std::string inside = name;
  if (!number.empty()) inside += (inside.empty() ? "" : " ") + number;
  std::string label = "object " + std::to_string(index);
  return inside.empty() ? label : label + " (" + inside + ")";
}

int line_of_offset(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

std::string omm_epoch_text(int year, double day) {
  std::string iso = format_iso8601(from_year_day(year, day), 6);  // ...T03:57:45.045216Z
  if (iso.ends_with('Z')) iso.pop_back();
  return iso;
}

std::string omm_object_id(std::string_view d) {
  if (d.size() < 6 || d.size() > 8 || !all_digits(d.substr(0, 5)) ||
      !std::all_of(d.begin() + 5, d.end(), is_designator_piece))
    return {};
  const int yy = static_cast<int>(*parse_unsigned(d.substr(0, 2)));
  return std::to_string(expand_two_digit_year(yy)) + "-" + std::string(d.substr(2));
}

void add_omm_object(const OmmObject& object, int index, std::string_view file, ElementFormat format,
                    ParseResult& out) {
  const ObjectReader r(object, index, file);
  if (!object.structural.field.empty()) {
    ParseProblem p = object.structural;
    p.object = r.label();
    out.problems.push_back(std::move(p));
    return;
  }
  Elements e;
  e.source = format;
  std::optional<ParseProblem> problem = r.duplicate();
  if (!problem) problem = check_theory(r);
  if (!problem) problem = read_numbers(r, e);
  if (!problem) problem = r.epoch(e);
  if (!problem) problem = read_orbit(r, e);
  if (problem) {
    out.problems.push_back(std::move(*problem));
    return;
  }
  if (const OmmField* f = r.value("OBJECT_NAME")) e.name = std::string(trim(f->value));
  if (const OmmField* f = r.value("OBJECT_ID")) {
    // "1998-067A" -> "98067A"; anything else is dropped with a warning (SGP4 does not use it).
    const std::string_view id = trim(f->value);
    const bool ok = id.size() >= 9 && id.size() <= 11 && all_digits(id.substr(0, 4)) && id[4] == '-' &&
                    all_digits(id.substr(5, 3)) && std::all_of(id.begin() + 8, id.end(), is_designator_piece);
    if (ok) e.international_designator = std::string(id.substr(2, 2)) + std::string(id.substr(5));
    else out.problems.push_back(r.problem(f, "OBJECT_ID", "YYYY-NNNP such as 1998-067A (left out)", true));
  }
  out.sets.push_back(std::move(e));
}

}  // namespace tb::orbit::detail
