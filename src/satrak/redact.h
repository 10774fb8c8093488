// What the log may keep of a Satrak exchange: everything but the secrets. The debug log records
// every command and reply (so an operator can see what a monitor-and-control program does); the
// FTP password of SATELLITE_FTP= and the credentials inside element-download URLs are replaced by
// "<redacted>" there and wherever a URL is logged.
#pragma once
#include <string>
#include <string_view>

#include "util/redact.h"

namespace tb::satrak {

inline constexpr std::string_view kRedacted = redact::kRedacted;

// "ftp://user:secret@host/x" -> "ftp://user:<redacted>@host/x"; a URL without a password as it is.
std::string redact_url(std::string_view url);

// A request or reply payload with its password fields and URL credentials redacted.
std::string redact_payload(std::string_view payload);

}  // namespace tb::satrak
