#include "menus/common.h"
#include "util/text.h"

#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstdlib>

namespace tb::menus {

std::string read_line(term::Terminal& t, std::size_t max_length) {
  auto l = t.read_line(max_length);
  if (!l) throw InputClosed{};
  if (t.escape_leaves() && *l == "\x1b") throw Escaped{};
  return *l;
}

bool ask_yes_no(term::Terminal& t, std::string_view prompt) {
  t.write(prompt);
  t.flush();
  const auto c = t.read_choice();
  if (!c) throw InputClosed{};
  return *c == 'Y';
}

char ask_key(term::Terminal& t, std::string_view prompt, std::string_view keys, bool allow_enter) {
  t.write(prompt);
  t.flush();
  const auto c = t.read_choice(keys, allow_enter);  // other keys (and Enter, unless allowed) are ignored
  if (!c) throw InputClosed{};
  return *c;
}


void run_menu(term::Terminal& t, const std::function<void()>& show, std::string_view prompt,
              const std::function<MenuStep(char key)>& choose) {
  bool skip_menu = false;
  for (;;) {
    if (!skip_menu) show();
    t.write(prompt);
    t.flush();
    // A menu choice is one key, as on the TrakBox: "7" opens 6-7 with or without an Enter after it
    // (the Enter that follows ends the answer; Terminal's rule for Enter). Blanks are passed over.
    std::optional<char> key;
    do {
      key = t.read_choice();
      if (!key) throw InputClosed{};
    } while (*key == ' ');
    const MenuStep step = *key == '\r' ? MenuStep::unknown : choose(*key);
    if (step == MenuStep::back) return;
    skip_menu = step == MenuStep::unknown;
  }
}

std::optional<double> parse_number(std::string_view s) { return text::parse_double(text::trim(s, text::kWhitespace)); }

std::optional<long> parse_integer(std::string_view s) {
  return text::parse_integer<long>(text::trim(s, text::kWhitespace));
}

std::string edit_text(term::Terminal& t, std::string_view label, std::string_view current,
                      const std::function<std::optional<std::string>(const std::string&)>& validate) {
  for (;;) {
    t.write(label);
    t.write(" : ");
    t.write(current);
    t.write("  ");
    t.flush();
    std::string answer = text::trimmed(read_line(t));
    if (t.last_line_had_non_ascii()) {
      // Refused, not kept without the letters the terminal could not give ("PRIS" for "Pàris").
      t.line("  only ASCII characters are taken here (A-Z, a-z, 0-9 and punctuation): '" + answer +
             "' is what is left; not changed");
      continue;
    }
    if (answer.empty()) return std::string(current);
    if (validate) {
      if (auto err = validate(answer)) {
        t.line("  " + *err);
        continue;
      }
    }
    return answer;
  }
}

double edit_number(term::Terminal& t, std::string_view label, double current, std::string_view shown, double lo,
                   double hi) {
  double result = current;
  edit_text(t, label, shown, [&](const std::string& s) -> std::optional<std::string> {
    const auto v = parse_number(s);
    if (!v) return "'" + s + "' is not a number";
    if (*v < lo || *v > hi) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "%s is out of range: expected %g to %g", s.c_str(), lo, hi);
      return std::string(buf);
    }
    result = *v;
    return std::nullopt;
  });
  return result;
}

int edit_int(term::Terminal& t, std::string_view label, int current, int lo, int hi) {
  int result = current;
  edit_text(t, label, std::to_string(current), [&](const std::string& s) -> std::optional<std::string> {
    const auto v = parse_integer(s);
    if (!v) return "'" + s + "' is not a whole number";
    if (*v < lo || *v > hi) return s + " is out of range: expected " + std::to_string(lo) + " to " + std::to_string(hi);
    result = static_cast<int>(*v);
    return std::nullopt;
  });
  return result;
}

std::vector<std::string> format_satellite_list(const std::vector<std::string>& names, int marked_index,
                                               char marker) {
  std::vector<std::string> rows;
  std::string row;
  for (std::size_t i = 0; i < names.size(); ++i) {
    char cell[40];
    std::snprintf(cell, sizeof cell, "%2zu.%c%-9s", i + 1, static_cast<int>(i) == marked_index ? marker : ' ',
                  names[i].substr(0, 9).c_str());
    row += cell;
    row += "  ";
    if (i % 4 == 3) {
      while (!row.empty() && row.back() == ' ') row.pop_back();
      rows.push_back(row);
      row.clear();
    }
  }
  while (!row.empty() && row.back() == ' ') row.pop_back();
  if (!row.empty()) rows.push_back(row);
  return rows;
}

std::optional<int> choose_satellite(term::Terminal& t, std::string_view title, const std::vector<std::string>& names,
                                    int marked_index, char marker, std::optional<orbit::Body>* body) {
  if (names.empty()) {
    t.line("No satellite selected: load elements with menu 3-3 and select with 3-2.");
    return std::nullopt;
  }
  t.line(title);
  for (const auto& r : format_satellite_list(names, marked_index, marker)) t.line(r);
  for (;;) {
    t.write("     Select :");
    t.flush();
    // Esc leaves the list with nothing chosen, as Q does (issue 39), rather than being typed.
    std::string a;
    try {
      EscapeLeaves esc(t);
      a = text::trimmed(read_line(t));
    } catch (const Escaped&) {
      return std::nullopt;
    }
    if (a.empty()) {
      if (marked_index >= 0 && marked_index < static_cast<int>(names.size())) return marked_index;
      continue;
    }
    if (a == "Q" || a == "q") return std::nullopt;
    const auto n = parse_integer(a);
    if (n && *n >= 1 && *n <= static_cast<long>(names.size())) return static_cast<int>(*n - 1);
    if (const auto b = body ? orbit::parse_body(a) : std::nullopt) {
      *body = b;
      return -1;
    }
    t.line("  Enter 1 to " + std::to_string(names.size()) + (body ? ", SUN or MOON" : "") +
           ", Enter for the marked one, or Q");
  }
}

std::string format_date(orbit::UtcTime t) {
  const auto c = orbit::to_civil(t);
  char buf[16];
  std::snprintf(buf, sizeof buf, "%04d/%02d/%02d", c.year, c.month, c.day);
  return buf;
}

std::string format_time(orbit::UtcTime t) {
  const auto c = orbit::to_civil(t);
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d:%02d:%02d", c.hour, c.minute, static_cast<int>(c.second));
  return buf;
}

std::optional<orbit::UtcTime> parse_yymmdd_hhmmss(std::string_view text) {
  int yy, mo, dd, hh, mi, ss;
  char tail;
  const std::string s(text);
  if (std::sscanf(s.c_str(), "%d/%d/%d %d:%d:%d %c", &yy, &mo, &dd, &hh, &mi, &ss, &tail) != 6) return std::nullopt;
  if (yy < 0 || yy > 99 || mo < 1 || mo > 12 || dd < 1 || dd > 31 || hh < 0 || hh > 23 || mi < 0 || mi > 59 ||
      ss < 0 || ss > 59)
    return std::nullopt;
  char iso[32];
  std::snprintf(iso, sizeof iso, "%04d-%02d-%02dT%02d:%02d:%02dZ", orbit::expand_two_digit_year(yy), mo, dd, hh, mi,
                ss);
  return orbit::parse_iso8601(iso);  // rejects 31 April and the like
}

}  // namespace tb::menus
