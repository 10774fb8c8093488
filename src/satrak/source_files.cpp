#include "satrak/source_files.h"

#include <sys/stat.h>

#include <fstream>
#include <sstream>
#include <string_view>

#include "util/files.h"

namespace tb::satrak {
namespace fs = std::filesystem;

std::string read_small_file(const fs::path& p, bool& too_big) {
  too_big = false;
  std::error_code ec;
  const auto size = fs::file_size(p, ec);
  if (!ec && size > kMaxSourceFileBytes) {
    too_big = true;
    return {};
  }
  return files::read_whole_file(p).value_or("");
}

std::optional<std::pair<std::int64_t, std::uintmax_t>> stat_file(const fs::path& p) {
  struct stat st {};
  if (::stat(p.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  const std::int64_t us = static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1000000 + st.st_mtim.tv_nsec / 1000;
  return std::make_pair(us, static_cast<std::uintmax_t>(st.st_size));
}

namespace {
std::string percent_encode(std::string_view s) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : s) {
    if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
        c == '.' || c == '~') {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}
}  // namespace

std::string ftp_url(const FtpSource& f) {
  const std::string file = percent_encode(f.file);
  if (f.host.find("://") != std::string::npos) {
    std::string base = f.host;
    while (!base.empty() && base.back() == '/') base.pop_back();
    return base + "/" + file;
  }
  std::string host = f.host;
  if (host.find(':') != std::string::npos && host.front() != '[') host = "[" + host + "]";
  return "ftp://" + host + ":" + std::to_string(f.port) + "/" + file;
}

}  // namespace tb::satrak
