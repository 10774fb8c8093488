// The ADIF reader of the logbook (logbook::read_adif, `trakbox log import`). Properties: a refusal
// names the record or the header and has a reason, and returns no record; an accepted file's
// records pass the logbook's own check, and written out (write_adif) they read back the same,
// field for field (export then import is the identity).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "logbook/adif.h"

using namespace tb;

namespace {
[[noreturn]] void violated(const char* what, const std::string& detail) {
  std::fprintf(stderr, "property violated: %s\n%s\n", what, detail.c_str());
  std::abort();
}
}  // namespace

#define ADIF_CHECK(cond, detail) \
  do {                           \
    if (!(cond)) violated(#cond, (detail)); \
  } while (0)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const logbook::AdifRead r = logbook::read_adif(text);
  if (!r.ok()) {
    ADIF_CHECK(r.qsos.empty(), r.error);
    ADIF_CHECK(r.error.rfind("record ", 0) == 0 || r.error.rfind("header: ", 0) == 0, r.error);
    ADIF_CHECK(r.error.find(": ") != std::string::npos && r.error.back() != ' ', r.error);
    return 0;
  }
  for (const auto& q : r.qsos) ADIF_CHECK(!logbook::check_qso(q), *logbook::check_qso(q));
  const logbook::AdifExport out = logbook::write_adif(r.qsos, "0", 0);
  const logbook::AdifRead again = logbook::read_adif(out.text);
  ADIF_CHECK(again.ok(), again.error + "\n" + out.text);
  ADIF_CHECK(again.qsos.size() == r.qsos.size(), out.text);
  for (std::size_t i = 0; i < r.qsos.size(); ++i) ADIF_CHECK(again.qsos[i] == r.qsos[i], out.text);
  return 0;
}
