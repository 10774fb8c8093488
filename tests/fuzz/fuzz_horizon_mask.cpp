// The horizon mask reader (orbit::read_horizon_mask, issue 57): N.I.N.A's pairs, CSV, the VLBI Field
// System's step list, and the one-line form the state keeps. Properties: a refusal names where
// ("NAME line N" or "pair N") and says what; a mask read comes back the same through text() (the
// setting's form); its elevation anywhere lies between its lowest and highest; describe() says it.
#include "fuzz_station.h"
#include "orbit/horizon_mask.h"

using namespace tb;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::as_text(data, size);
  const auto r = orbit::read_horizon_mask(text, "mask");
  if (!r.mask) {
    TB_FUZZ_CHECK(r.error.rfind("mask", 0) == 0 && r.error.size() > 6, r.error);
    return 0;
  }
  const orbit::HorizonMask& m = *r.mask;
  const std::string line = m.text();
  const auto back = orbit::read_horizon_mask(line, "mask");
  TB_FUZZ_CHECK(back.mask && *back.mask == m, line + " <- " + std::string(text.substr(0, 200)) + " " + back.error);
  TB_FUZZ_CHECK(!m.describe().empty(), line);
  for (const double az : {-720.5, -1.0, 0.0, 0.25, 89.9, 180.0, 359.999, 360.0, 1000.0}) {
    const double el = m.at(az);
    TB_FUZZ_CHECK(el >= m.min_el() - 1e-9 && el <= m.max_el() + 1e-9, line + " at " + std::to_string(az));
  }
  return 0;
}
