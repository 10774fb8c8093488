#include "cli/options.h"
#include "util/text.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cmath>
#include <cstdlib>

namespace tb::app {
namespace {

const OptionSpec* find_spec(const std::vector<OptionSpec>& specs, std::string_view name) {
  for (const OptionSpec& s : specs)
    if (s.name == name) return &s;
  return nullptr;
}

bool looks_like_number(std::string_view word) {
  return word.size() >= 2 && word[0] == '-' &&
         ((word[1] >= '0' && word[1] <= '9') || word[1] == '.');
}

std::string quote_value(std::string_view s) { return "'" + std::string(s) + "'"; }

}  // namespace

bool ParsedOptions::has(std::string_view name) const { return values_.find(name) != values_.end(); }

std::optional<std::string> ParsedOptions::value(std::string_view name) const {
  const auto it = values_.find(name);
  if (it == values_.end() || it->second.empty()) return std::nullopt;
  return it->second.back();
}

std::vector<std::string> ParsedOptions::values(std::string_view name) const {
  const auto it = values_.find(name);
  return it == values_.end() ? std::vector<std::string>{} : it->second;
}

namespace {

// Edits between two words, a swap of neighbours counting one (the optimal string alignment
// distance): "strat" is one from "start". For "did you mean" (short words: option names).
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// "unknown option; did you mean --rotator?" when one option is within two edits (a typo), or
// when the word is the start of exactly one.
std::string unknown_option(std::string_view name, const std::vector<OptionSpec>& specs) {
  if (name.size() > 40) return "unknown option";  // no option is that long: no guess (and no cost)
  const OptionSpec* best = nullptr;
  std::size_t best_d = 3;
  int prefixed = 0;
  const OptionSpec* prefix = nullptr;
  for (const OptionSpec& s : specs) {
    const std::size_t d = edit_distance(name, s.name);
    if (d < best_d) best_d = d, best = &s;
    if (name.size() >= 3 && s.name.rfind(name, 0) == 0) ++prefixed, prefix = &s;
  }
  if (!best && prefixed == 1) best = prefix;
  if (!best || name.size() < 3) return "unknown option";
  return "unknown option; did you mean --" + best->name + "?";
}

}  // namespace

ParseOutcome parse_options(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs) {
  ParseOutcome out;
  auto fail = [&](std::string argument, std::string message) {
    out.error = ArgError{std::move(argument), std::move(message)};
    return out;
  };
  bool options_ended = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& word = args[i];
    if (options_ended || word == "-" || word.empty() || word[0] != '-' || looks_like_number(word)) {
      out.options.positional_.push_back(word);
      continue;
    }
    if (word == "--") {
      options_ended = true;
      continue;
    }
    std::string name;
    std::optional<std::string> inline_value;
    if (word.rfind("--", 0) == 0) {
      const std::size_t eq = word.find('=');
      name = word.substr(2, eq == std::string::npos ? std::string::npos : eq - 2);
      if (eq != std::string::npos) inline_value = word.substr(eq + 1);
    } else if (word == "-h" && find_spec(specs, "help")) {
      name = "help";
    } else {
      return fail(word, "unknown option (options are written --name)");
    }
    const std::string label = "--" + name;
    const OptionSpec* spec = find_spec(specs, name);
    if (!spec) return fail(label, unknown_option(name, specs));
    std::vector<std::string>& slot = out.options.values_[spec->name];
    if (!slot.empty() && !spec->repeatable) return fail(label, "given more than once");
    if (!spec->takes_value()) {
      if (inline_value) return fail(label, "takes no value, found " + quote_value(*inline_value));
      slot.emplace_back();
      continue;
    }
    if (inline_value) {
      slot.push_back(*inline_value);
      continue;
    }
    if (i + 1 >= args.size() || args[i + 1].rfind("--", 0) == 0)
      return fail(label, "expected " + spec->value_name + " after it");
    slot.push_back(args[++i]);
  }
  return out;
}

std::string describe_options(const std::vector<OptionSpec>& specs) {
  std::string text;
  for (const OptionSpec& s : specs) {
    std::string left = "  --" + s.name + (s.takes_value() ? " " + s.value_name : "");
    if (left.size() < 26) left.resize(26, ' ');
    else left += "  ";
    text += left + s.help + (s.repeatable ? " (repeatable)" : "") + "\n";
  }
  return text;
}

std::optional<int> read_subcommand(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs,
                                   std::string_view name, std::string_view usage, Subcommand& out) {
  std::vector<std::string> opts;
  for (const std::string& a : args) (a.rfind("--", 0) == 0 || !opts.empty() ? opts : out.words).push_back(a);
  ParseOutcome parsed = parse_options(opts, specs);
  if (parsed.error) {
    std::fprintf(stderr, "trakbox %.*s: %s (see trakbox %.*s --help)\n", static_cast<int>(name.size()), name.data(),
                 parsed.error->text().c_str(), static_cast<int>(name.size()), name.data());
    return kExitUsage;
  }
  out.options = std::move(parsed.options);
  if (out.options.has("help")) {
    std::fputs((std::string(usage) + describe_options(specs)).c_str(), stdout);
    return kExitOk;
  }
  return std::nullopt;
}

std::optional<double> to_double(std::string_view text) {
  if (text.empty() || text.size() > 64) return std::nullopt;
  const char c0 = text[0];
  if (!(c0 == '-' || c0 == '+' || c0 == '.' || (c0 >= '0' && c0 <= '9'))) return std::nullopt;
  return tb::text::parse_double(text);  // plain decimal: no hexadecimal, no "inf"/"nan"
}

std::optional<std::int64_t> to_int64(std::string_view text) {
  if (text.empty() || text.size() > 20) return std::nullopt;
  std::size_t i = (text[0] == '-' || text[0] == '+') ? 1 : 0;
  if (i == text.size()) return std::nullopt;
  for (std::size_t k = i; k < text.size(); ++k)
    if (text[k] < '0' || text[k] > '9') return std::nullopt;
  const std::string s(text);
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(s.c_str(), &end, 10);
  if (errno == ERANGE || end != s.c_str() + s.size()) return std::nullopt;
  return static_cast<std::int64_t>(v);
}

std::optional<std::vector<double>> to_double_list(std::string_view text, char separator) {
  std::vector<double> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find(separator, start);
    const auto item = to_double(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (!item) return std::nullopt;
    out.push_back(*item);
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return out;
}

bool Range::contains(double v) const {
  if (min && (min_exclusive ? !(v > *min) : !(v >= *min))) return false;
  if (max && (max_exclusive ? !(v < *max) : !(v <= *max))) return false;
  return true;
}

void OptionReader::fail(std::string argument, std::string message) {
  if (!error_) error_ = ArgError{std::move(argument), std::move(message)};
}

std::optional<std::string> OptionReader::text(std::string_view name, bool required, std::string_view expected) {
  auto v = options_.value(name);
  if (!v && required) fail(option_label(name), "missing; expected " + std::string(expected));
  return v;
}

std::optional<double> OptionReader::number(std::string_view name, bool required, std::string_view expected,
                                           const Range& range) {
  const auto t = text(name, required, expected);
  if (!t) return std::nullopt;
  const auto v = to_double(*t);
  if (!v || !range.contains(*v)) {
    fail(option_label(name), "expected " + std::string(expected) + ", found " + quote_value(*t));
    return std::nullopt;
  }
  return v;
}

std::optional<std::int64_t> OptionReader::integer(std::string_view name, bool required, std::string_view expected,
                                                  const Range& range) {
  const auto t = text(name, required, expected);
  if (!t) return std::nullopt;
  const auto v = to_int64(*t);
  if (!v || !range.contains(static_cast<double>(*v))) {
    fail(option_label(name), "expected " + std::string(expected) + ", found " + quote_value(*t));
    return std::nullopt;
  }
  return v;
}

}  // namespace tb::app
