// The attach socket's wire format (attach_server.h): a client's keyboard bytes with window sizes
// escaped by 0xFF, and the keys the menus take from a terminal's bytes. Pure: fuzzed by
// tests/fuzz/fuzz_attach_frames.cpp.
#include <algorithm>

#include "app/attach_server.h"
#include "menus/term/terminal.h"

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

}  // namespace tb::app
