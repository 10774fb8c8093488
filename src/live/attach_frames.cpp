// The attach socket's wire format (attach_server.h): a client's keyboard bytes with window sizes
// escaped by 0xFF, and the keys the menus take from a terminal's bytes. Pure: fuzzed by
// tests/fuzz/fuzz_attach_frames.cpp.
#include <algorithm>
#include <cstdint>

#include <nlohmann/json.hpp>

#include "live/attach_server.h"
#include "menus/term/terminal.h"
#include "util/json_limits.h"
#include "util/safe_text.h"

namespace tb::app {

ClientFrames FrameDecoder::feed(std::string_view data) {
  ClientFrames out;
  partial_.append(data);
  std::size_t i = 0;
  while (i < partial_.size()) {
    const unsigned char c = static_cast<unsigned char>(partial_[i]);
    if (c != 0xFF) {
      out.bytes.push_back(partial_[i++]);
      continue;
    }
    if (i + 1 >= partial_.size()) break;  // the rest of the escape comes later
    if (static_cast<unsigned char>(partial_[i + 1]) == 0xFF) {
      out.bytes.push_back('\xff');
      i += 2;
    } else if (partial_[i + 1] == 'W') {
      if (i + 6 > partial_.size()) break;
      auto byte = [&](std::size_t k) { return static_cast<int>(static_cast<unsigned char>(partial_[k])); };
      out.sizes.emplace_back(byte(i + 2) * 256 + byte(i + 3), byte(i + 4) * 256 + byte(i + 5));
      i += 6;
    } else {
      i += 2;  // an escape this side does not know: dropped
    }
  }
  partial_.erase(0, i);
  return out;
}

std::string encode_window_size(int rows, int cols) {
  rows = std::clamp(rows, 0, 65535);
  cols = std::clamp(cols, 0, 65535);
  return std::string{'\xff', 'W', static_cast<char>(rows >> 8), static_cast<char>(rows & 0xFF),
                     static_cast<char>(cols >> 8), static_cast<char>(cols & 0xFF)};
}

std::vector<int> decode_keys(std::string_view bytes) {
  std::vector<int> keys;
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(bytes[i]);
    if (c == 27 && i + 1 < bytes.size() && (bytes[i + 1] == '[' || bytes[i + 1] == 'O')) {
      // CSI: parameters then a final byte 0x40-0x7E; SS3: one more byte.
      std::size_t j = i + 2;
      if (bytes[i + 1] == '[')
        while (j < bytes.size() && !(bytes[j] >= 0x40 && bytes[j] <= 0x7E)) ++j;
      i = std::min(j, bytes.size() - 1);
      continue;
    }
    keys.push_back(c == 127 ? term::kBackspace : static_cast<int>(c));
  }
  return keys;
}

namespace {

const char* type_name(const nlohmann::json& v) {
  if (v.is_number_integer()) return "an integer";
  if (v.is_number()) return "a number with a fraction";
  return v.type_name();  // "string", "boolean", "array", "object", "null"
}

constexpr std::size_t kMaxHelloText = 64;  // a terminal type or a tty name

}  // namespace

std::optional<AttachHello> parse_attach_hello(std::string_view text, std::string& error) {
  AttachHello h;
  if (text.find_first_not_of(" \t") == std::string_view::npos) return h;  // a bare "attach"
  std::string why;
  const nlohmann::json j = json_limits::parse_bounded<nlohmann::json>(text, why, 4);
  if (why.starts_with("nested")) {
    error = "the greeting is nested too deep";
    return std::nullopt;
  }
  if (j.is_discarded() || !j.is_object()) {
    error = "the greeting is not a JSON object";
    return std::nullopt;
  }
  auto wrong = [&](const char* key, const char* want, const nlohmann::json& v) {
    error = std::string("'") + key + "' must be " + want + ", found " + type_name(v);
    return std::nullopt;
  };
  for (const char* key : {"term", "tty"}) {
    const auto it = j.find(key);
    if (it == j.end() || it->is_null()) continue;
    if (!it->is_string()) return wrong(key, "a string", *it);
    const std::string& v = it->get_ref<const std::string&>();
    if (v.size() > kMaxHelloText) {
      error = std::string("'") + key + "' is longer than " + std::to_string(kMaxHelloText) + " bytes";
      return std::nullopt;
    }
    (std::string_view(key) == "term" ? h.term : h.tty) = text::safe_text(v);
  }
  if (!std::all_of(h.term.begin(), h.term.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
               c == '+' || c == '-';
      })) {
    error = "'term' must be a terminal type (letters, digits, . _ + -), found '" + text::visible_bytes(h.term) + "'";
    return std::nullopt;
  }
  for (const char* key : {"rows", "cols"}) {
    const auto it = j.find(key);
    if (it == j.end() || it->is_null()) continue;
    if (!it->is_number_integer()) return wrong(key, "an integer", *it);
    const long long v = it->is_number_unsigned() ? static_cast<long long>(std::min<std::uint64_t>(it->get<std::uint64_t>(), 65535))
                                                 : std::clamp<long long>(it->get<std::int64_t>(), 0, 65535);
    (std::string_view(key) == "rows" ? h.rows : h.cols) = v;
  }
  for (const char* key : {"full_screen", "crlf"}) {
    const auto it = j.find(key);
    if (it == j.end() || it->is_null()) continue;
    if (!it->is_boolean()) return wrong(key, "true or false", *it);
    (std::string_view(key) == "full_screen" ? h.full_screen : h.crlf) = it->get<bool>();
  }
  return h;
}

}  // namespace tb::app
