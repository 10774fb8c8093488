#pragma once
// Reading a whole file: the one copy (the station's data files, Satrak's bounded source files,
// 3-5's local sources, the test data). The state file opens its own, refusing a symbolic link.
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

namespace tb::files {

// The file's bytes; nullopt when it cannot be opened.
inline std::optional<std::string> read_whole_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream ss;
  ss << in.rdbuf();
  return std::move(ss).str();
}

}  // namespace tb::files
