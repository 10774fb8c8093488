#include "satrak/redact.h"

#include <vector>

#include "util/text.h"

namespace tb::satrak {

std::string redact_url(std::string_view url) {
  const auto scheme = url.find("://");
  if (scheme == std::string_view::npos) return std::string(url);
  const auto authority = scheme + 3;
  const auto end = url.find_first_of("/?#", authority);
  const std::string_view auth = url.substr(authority, end == std::string_view::npos ? url.npos : end - authority);
  const auto at = auth.rfind('@');
  if (at == std::string_view::npos) return std::string(url);
  const auto colon = auth.substr(0, at).find(':');
  if (colon == std::string_view::npos) return std::string(url);  // a user name alone is no secret
  std::string out(url.substr(0, authority + colon + 1));
  out += kRedacted;
  out += url.substr(authority + at);
  return out;
}

std::string redact_payload(std::string_view payload) {
  std::vector<std::string_view> fields = text::split(payload, ',');
  const std::string head = text::upper(text::trim(fields.front()));
  std::string out;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) out += ',';
    // SATELLITE_FTP=,host,user,PASSWORD,... and its query's reply SATELLITE_FTP?,host,user,PASSWORD,...
    const bool password = i == 3 && (head == "SATELLITE_FTP=" || head == "SATELLITE_FTP?") && !fields[i].empty() &&
                          text::trim(fields[i]) != "?";
    if (password)
      out += kRedacted;
    else if (fields[i].find("://") != std::string_view::npos)
      out += redact_url(fields[i]);
    else
      out += fields[i];
  }
  return out;
}

}  // namespace tb::satrak
