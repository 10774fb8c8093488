#pragma once
// printf into a std::string, of any length: the one copy (the element writers, the orbit
// subcommands' CSV and JSON, the state file's checksum, the Icom addresses).
#include <cstdarg>
#include <cstdio>
#include <string>

namespace tb::text {

inline std::string printf_string(const char* format, ...) __attribute__((format(printf, 1, 2)));
inline std::string printf_string(const char* format, ...) {
  char buf[512];
  va_list ap;
  va_start(ap, format);
  const int n = std::vsnprintf(buf, sizeof buf, format, ap);
  va_end(ap);
  if (n < 0) return {};
  if (static_cast<std::size_t>(n) < sizeof buf) return std::string(buf, static_cast<std::size_t>(n));
  std::string big(static_cast<std::size_t>(n) + 1, '\0');
  va_start(ap, format);
  std::vsnprintf(big.data(), big.size(), format, ap);
  va_end(ap);
  big.resize(static_cast<std::size_t>(n));
  return big;
}

}  // namespace tb::text
