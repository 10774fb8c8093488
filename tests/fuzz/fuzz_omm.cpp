// OMM element data from outside (CelesTrak and Space-Track downloads, files an operator converts or
// uploads): the JSON, XML, CSV and KVN readers and the detection of parse_elements.
//
// The first byte picks the reader: 0 JSON, 1 XML, 2 CSV, 3 KVN, anything else parse_elements
// (detection, the empty and binary checks). The rest is the text.
// Properties beyond "no crash, no hang, no sanitizer report":
//  * every problem names its keyword (or the part of the file at fault), and the message says it;
//    a problem about one object names the object;
//  * every set accepted comes back from the JSON writer as the same numbers (the epoch within the
//    microsecond the writer keeps), and SGP4 initialises on it without crashing.
#include <cmath>
#include <cstdlib>

#include "fuzz_station.h"
#include "orbit/sgp4.h"
#include "util/safe_text.h"

using namespace tb;

namespace {

bool valid_utf8(const std::string& s) {
  try {
    (void)nlohmann::json(s).dump();
    return true;
  } catch (const nlohmann::json::exception&) {
    return false;
  }
}

bool same_after_json(const orbit::Elements& a, const orbit::Elements& b) {
  const auto epoch_gap = std::llabs((a.epoch() - b.epoch()).count());
  return (a.name == b.name || !valid_utf8(a.name)) && a.catalog_number == b.catalog_number &&
         a.classification == b.classification && a.international_designator == b.international_designator &&
         epoch_gap <= 1 && a.ndot_over_2 == b.ndot_over_2 && a.nddot_over_6 == b.nddot_over_6 && a.bstar == b.bstar &&
         a.element_set_number == b.element_set_number && a.inclination_deg == b.inclination_deg &&
         a.raan_deg == b.raan_deg && a.eccentricity == b.eccentricity && a.arg_perigee_deg == b.arg_perigee_deg &&
         a.mean_anomaly_deg == b.mean_anomaly_deg && a.mean_motion_rev_per_day == b.mean_motion_rev_per_day &&
         a.revolution_number == b.revolution_number;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string_view text = fuzz::as_text(data + 1, size - 1);
  orbit::ParseResult r;
  switch (data[0]) {
    case 0: r = orbit::parse_omm_json(text, "<fuzz>"); break;
    case 1: r = orbit::parse_omm_xml(text, "<fuzz>"); break;
    case 2: r = orbit::parse_omm_csv(text, "<fuzz>"); break;
    case 3: r = orbit::parse_omm_kvn(text, "<fuzz>"); break;
    default: r = orbit::parse_elements(text, "<fuzz>"); break;
  }
  for (const auto& p : r.problems) {
    const std::string m = p.message();
    TB_FUZZ_CHECK(!p.field.empty(), m);
    // The message is for a terminal: printable UTF-8 (issue 38), field and object as they show there.
    TB_FUZZ_CHECK(text::is_safe_text(m), m);
    TB_FUZZ_CHECK(m.find(text::safe_text(p.field)) != std::string::npos, m);
    TB_FUZZ_CHECK(p.object.empty() || m.find(text::safe_text(p.object)) != std::string::npos, m);
  }
  if (r.sets.empty()) return 0;

  const std::string json = orbit::format_omm(r.sets, orbit::OmmEncoding::json);
  const orbit::ParseResult again = orbit::parse_omm_json(json, "<round trip>");
  std::string why = json;
  for (const auto& p : again.problems) why += p.message() + "\n";
  TB_FUZZ_CHECK(again.ok() && again.sets.size() == r.sets.size(), why);
  for (std::size_t i = 0; i < r.sets.size(); ++i) TB_FUZZ_CHECK(same_after_json(r.sets[i], again.sets[i]), why);

  const orbit::Sgp4 sgp4(r.sets.front());
  if (sgp4.init_error() == orbit::Sgp4Error::none) (void)sgp4.propagate_minutes(1440.0);
  return 0;
}
