// The logger's reply readers (logbook::judge_qso_reply, judge_radio_reply): what a Cloudlog or
// Wavelog, or anything at its URL, answers to api/qso and api/radio (issue 56: a reply nested
// 100,000 deep ended the station with SIGSEGV). The first byte chooses the reader and the HTTP
// status: bit 0 the logger (Cloudlog, Wavelog), bit 1 api/radio rather than api/qso, bits 2-4 the
// status (200, 201, 400, 401, 403, 404, 500, 0: no answer); the rest is the body.
// Properties beyond no crash / hang / leak / UB: nothing thrown; the verdict's message is one line
// of at most 210 characters without control bytes, and never holds the key (any case; a piece of
// it at the cut is the unit test's); a
// refusal says why; a duplicate is accepted; an accepted reply came with a 2xx status, and an
// accepted api/qso reply with Cloudlog's 201 or Wavelog's 201 or 400.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "logbook/logger.h"

using namespace tb;

namespace {
[[noreturn]] void violated(const char* what, const std::string& detail) {
  std::fprintf(stderr, "*** fuzz property violated: %s\n%s\n", what, detail.c_str());
  std::abort();
}
constexpr std::string_view kKey = "cl64f0a1b2c3d4e5KEY";

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}
}  // namespace

#define REPLY_CHECK(cond, detail)           \
  do {                                      \
    if (!(cond)) violated(#cond, (detail)); \
  } while (0)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static constexpr long kStatus[] = {200, 201, 400, 401, 403, 404, 500, 0};
  const auto kind = (data[0] & 1) ? logbook::LoggerKind::wavelog : logbook::LoggerKind::cloudlog;
  const bool radio = data[0] & 2;
  const long status = kStatus[(data[0] >> 2) & 7];
  const std::string_view body(reinterpret_cast<const char*>(data + 1), size - 1);
  const logbook::ReplyVerdict v =
      radio ? logbook::judge_radio_reply(status, body, kKey) : logbook::judge_qso_reply(kind, status, body, kKey);
  const std::string& m = v.message;
  REPLY_CHECK(m.size() <= 200 + 10, m);  // the logger's words are cut at 200, "HTTP nnn: " before them
  for (const char c : m) REPLY_CHECK(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f, m);
  const std::string low = lower(m);
  REPLY_CHECK(low.find(lower(kKey)) == std::string::npos, m);
  if (!v.accepted) REPLY_CHECK(!m.empty(), "a refusal without a reason");
  if (v.duplicate) REPLY_CHECK(v.accepted, m);
  if (v.accepted) {
    REPLY_CHECK((status >= 200 && status < 300) || (!radio && status == 400 && v.duplicate), std::to_string(status));
    if (!radio) REPLY_CHECK(status == 201 || status == 400, std::to_string(status));
  }
  return 0;
}
