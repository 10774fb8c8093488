// The attach greeting as a client may send it (app::parse_attach_hello): `attach ` then any text.
// Issue 38: a field of the wrong type threw nlohmann's type_error out of the handler (SIGABRT).
//
// Properties: nothing is thrown; a refusal has a reason that is printable UTF-8 (it is sent to the
// client and logged); an accepted greeting has a terminal type of letters, digits and ". _ + -" of
// at most 64 bytes, a tty name that is printable UTF-8, rows and columns within 0..65535.
#include <algorithm>

#include "live/attach_server.h"
#include "fuzz_station.h"
#include "util/safe_text.h"

using namespace tb;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::as_text(data, size);
  std::string error;
  std::optional<app::AttachHello> h;
  try {
    h = app::parse_attach_hello(text, error);
  } catch (const std::exception& e) {
    fuzz::violated("parse_attach_hello threw", std::string(e.what()) + "\n" + std::string(text));
  }
  if (!h) {
    TB_FUZZ_CHECK(!error.empty() && text::is_safe_text(error), std::string(text));
    return 0;
  }
  TB_FUZZ_CHECK(h->term.size() <= 64 && std::all_of(h->term.begin(), h->term.end(), [](char c) {
                  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                         c == '_' || c == '+' || c == '-';
                }),
                std::string(text));
  TB_FUZZ_CHECK(text::is_safe_text(h->tty), std::string(text));
  TB_FUZZ_CHECK(h->rows >= 0 && h->rows <= 65535 && h->cols >= 0 && h->cols <= 65535, std::string(text));
  return 0;
}
