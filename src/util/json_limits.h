#pragma once
// Bounds on JSON documents that come from outside (the state file, OMM JSON, SatNOGS lists, Satrak
// settings). nlohmann::json parses without recursion, but copying, comparing and dump() recurse once
// per level: a document nested 100,000 deep parses and then overflows the stack. Every reader of
// outside JSON checks the nesting with this scanner (iterative, linear, no allocation) first.
// The one door is parse_bounded: every parse of text from outside goes through it (a logger's
// reply, SatNOGS and element answers, web bodies and WebSocket messages, Satrak settings, the
// attach greeting, the station socket's replies); scripts/check-architecture.py fails on a
// json::parse anywhere else but the few files it lists (text trakbox wrote itself).
#include <cstddef>
#include <string>
#include <string_view>

namespace tb::json_limits {

// Deeper than any document trakbox reads or writes (the state document is about 6 levels deep).
inline constexpr std::size_t kMaxDepth = 64;

// The deepest nesting of arrays and objects in `text`, counting stops once it passes `stop_after`
// (the result is then stop_after + 1). Brackets inside strings do not count. Malformed text gets a
// number too; the parser reports the syntax.
inline std::size_t nesting_depth(std::string_view text, std::size_t stop_after = kMaxDepth) {
  std::size_t depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
      continue;
    }
    switch (c) {
      case '"': in_string = true; break;
      case '[':
      case '{':
        if (++depth > deepest) {
          deepest = depth;
          if (deepest > stop_after) return deepest;
        }
        break;
      case ']':
      case '}':
        if (depth) --depth;
        break;
      default: break;
    }
  }
  return deepest;
}

inline bool too_deep(std::string_view text, std::size_t max_depth = kMaxDepth) {
  return nesting_depth(text, max_depth) > max_depth;
}

// What a refused parse was, for a reader that locates its problems (the OMM reader names the line).
struct ParseFailure {
  bool too_deep = false;
  bool located = false;   // `byte` is where the syntax failed (1-based, as the library counts)
  std::size_t byte = 0;
  std::string what;       // the library's words without its prefix ("syntax error while parsing ...")
};

// `text` parsed as JSON (nlohmann::json or ordered_json: a template so that this header needs no
// JSON header) after the nesting check. On a refusal the result is discarded (is_discarded()) and
// `error` one sentence: "nested deeper than 64 levels" or "not JSON (at byte N)". Never throws for
// the text.
template <class Json>
Json parse_bounded(std::string_view text, std::string& error, std::size_t max_depth = kMaxDepth,
                   ParseFailure* failure = nullptr) {
  error.clear();
  ParseFailure f;
  if (too_deep(text, max_depth)) {
    f.too_deep = true;
    error = "nested deeper than " + std::to_string(max_depth) + " levels";
  } else {
    try {
      return Json::parse(text.begin(), text.end());
    } catch (const typename Json::parse_error& e) {
      f.located = true;
      f.byte = e.byte;
      f.what = e.what();
      if (const auto colon = f.what.rfind(": "); colon != std::string::npos) f.what = f.what.substr(colon + 2);
      error = "not JSON (at byte " + std::to_string(e.byte) + ")";
    } catch (const typename Json::exception& e) {  // a number beyond double: out_of_range
      f.what = e.what();
      if (const auto bracket = f.what.rfind("] "); bracket != std::string::npos) f.what = f.what.substr(bracket + 2);
      error = "not JSON (" + f.what + ")";
    }
  }
  if (failure) *failure = std::move(f);
  return Json(Json::value_t::discarded);
}

}  // namespace tb::json_limits
