#pragma once
// Shared secrets of the TCP endpoints (--rotctld-secret-file, ...; docs/security.md): read from a
// file, never from the command line where `ps` shows them, and compared in constant time.
#include <sys/stat.h>

#include <cstddef>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

namespace tb::secret {

inline constexpr std::size_t kMaxLength = 256;

// a == b, taking the same time whatever the contents and wherever they first differ (the time
// depends only on the length of `expected`).
inline bool equal(std::string_view given, std::string_view expected) {
  unsigned diff = given.size() != expected.size() ? 1u : 0u;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const unsigned char g = i < given.size() ? static_cast<unsigned char>(given[i]) : 0u;
    diff |= g ^ static_cast<unsigned char>(expected[i]);
  }
  return diff == 0;
}

// The secret: the file's first line without its line end. Nothing, with the reason in `error`,
// when the file cannot be read, the secret is empty, longer than kMaxLength or holds blanks or
// control characters (they could not be typed after "\password "). `warning` is set when the file
// can be read by group or others.
inline std::optional<std::string> read_file(const std::string& path, std::string& error, std::string& warning) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = path + ": cannot be read";
    return std::nullopt;
  }
  std::string line;
  std::getline(in, line);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (line.empty()) {
    error = path + ": the first line (the secret) is empty";
    return std::nullopt;
  }
  if (line.size() > kMaxLength) {
    error = path + ": the secret is longer than " + std::to_string(kMaxLength) + " characters";
    return std::nullopt;
  }
  for (const char c : line)
    if (static_cast<unsigned char>(c) <= 0x20 || c == 0x7F) {
      error = path + ": the secret holds a blank or a control character";
      return std::nullopt;
    }
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && (st.st_mode & (S_IRWXG | S_IRWXO)) != 0)
    warning = path + " can be read by other users (chmod 600 it)";
  return line;
}

}  // namespace tb::secret
