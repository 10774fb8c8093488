#include "satrak/redact.h"

#include <vector>

#include "util/redact.h"
#include "util/text.h"

namespace tb::satrak {

std::string redact_url(std::string_view url) { return redact::url_credentials(url); }

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
