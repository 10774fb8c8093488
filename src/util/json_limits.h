#pragma once
// Bounds on JSON documents that come from outside (the state file, OMM JSON, SatNOGS lists, Satrak
// settings). nlohmann::json parses without recursion, but copying, comparing and dump() recurse once
// per level: a document nested 100,000 deep parses and then overflows the stack. Every reader of
// outside JSON checks the nesting with this scanner (iterative, linear, no allocation) first.
#include <cstddef>
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

}  // namespace tb::json_limits
