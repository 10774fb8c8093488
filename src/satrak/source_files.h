// The files and addresses behind the Satrak unit's element and image sources: reading a file of
// bounded size, its modification time, and the URL of an FTP source.
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>

#include "satrak/settings.h"

namespace tb::satrak {

inline constexpr std::uintmax_t kMaxSourceFileBytes = 4u << 20;

// The whole file; "" with too_big set when it is larger than kMaxSourceFileBytes.
std::string read_small_file(const std::filesystem::path& p, bool& too_big);
// Modification time (microseconds since 1970) and size of a regular file; nothing otherwise.
std::optional<std::pair<std::int64_t, std::uintmax_t>> stat_file(const std::filesystem::path& p);
// "ftp://host:port/file" (the file percent-encoded, an IPv6 host in brackets); a host given as a
// URL ("ftp://..." or "sftp://...") is used as the base.
std::string ftp_url(const FtpSource& f);

}  // namespace tb::satrak
