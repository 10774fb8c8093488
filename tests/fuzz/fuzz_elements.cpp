// Element sets from outside (menu 3-3 uploads, TLE files, downloads, gpredict files): the NASA
// 2/3-line, AMSAT verbose and gpredict parsers, and what the station then does with an accepted set:
// SGP4 initialisation, a propagation and an observation, a short pass search.
//
// The first byte picks the parser and the options; the rest is the text.
// Properties beyond "no crash, no hang, no sanitizer report":
//  * every problem has a message naming its field, in printable UTF-8;
//  * a set the NASA parser accepts comes back from format_nasa unchanged within the precision of the
//    columns (the writer's promise), and one the AMSAT parser accepts from format_amsat exactly.
#include <algorithm>
#include <cmath>
#include <limits>

#include "fuzz_station.h"
#include "util/safe_text.h"
#include "orbit/observe.h"
#include "orbit/passes.h"
#include "orbit/sgp4.h"

using namespace tb;

namespace {

// Equal within half a unit of the last digit the NASA columns keep (a field may carry more digits
// than the writer's fixed layout, "08.02706" in an 8-column angle; the writer rounds them to 4):
// exact for sets written in the standard layout, which is what the writer promises. ndot/2 of 1 or
// more (no such satellite) loses a decimal to the integer digits in its 10 columns.
// The slack on top: the rounding of the subtraction itself, a few ulps of the values (an epoch day
// 76.156157475 written as 76.15615748 differs by 5e-9 plus 1.4e-14).
bool near(double a, double b, double tol) {
  return std::abs(a - b) <= tol * (1.0 + 1e-9) + 8.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b));
}
bool near_rel(double a, double b, double rel) { return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b)) + 1e-300; }
bool same(const orbit::Elements& a, const orbit::Elements& b, bool nasa) {
  const double k = nasa ? 1.0 : 0.0;  // AMSAT: the writer keeps every digit
  return a.catalog_number == b.catalog_number && a.epoch_year == b.epoch_year &&
         near(a.epoch_day, b.epoch_day, k * 5e-9) && near(a.ndot_over_2, b.ndot_over_2, k * 5e-9 * std::max(1.0, 10.0 * std::abs(a.ndot_over_2))) &&
         near_rel(a.nddot_over_6, b.nddot_over_6, k * 1e-5) && near_rel(a.bstar, b.bstar, k * 1e-5) &&
         near(a.inclination_deg, b.inclination_deg, k * 5e-5) && near(a.raan_deg, b.raan_deg, k * 5e-5) &&
         near(a.eccentricity, b.eccentricity, k * 5e-8) && near(a.arg_perigee_deg, b.arg_perigee_deg, k * 5e-5) &&
         near(a.mean_anomaly_deg, b.mean_anomaly_deg, k * 5e-5) &&
         near(a.mean_motion_rev_per_day, b.mean_motion_rev_per_day, k * 5e-9);
}

void check_round_trip(const orbit::Elements& e) {
  if (e.source == orbit::ElementFormat::nasa) {
    const std::string text = orbit::format_nasa(e);
    const auto again = orbit::parse_nasa(text, "<round trip>");
    std::string why = text;
    for (const auto& p : again.problems) why += p.message() + "\n";
    TB_FUZZ_CHECK(again.ok() && again.sets.size() == 1, why);
    TB_FUZZ_CHECK(same(e, again.sets[0], true), why);
  } else if (e.source == orbit::ElementFormat::amsat) {  // OMM sets (detected by parse_elements): fuzz_omm
    const std::string text = orbit::format_amsat(e);
    const auto again = orbit::parse_amsat(text, "<round trip>");
    std::string why = text;
    for (const auto& p : again.problems) why += p.message() + "\n";
    TB_FUZZ_CHECK(again.ok() && again.sets.size() == 1, why);
    TB_FUZZ_CHECK(same(e, again.sets[0], false), why);
  }
}

void use(const orbit::Elements& e, bool first) {
  (void)e.label();
  (void)e.epoch();
  const orbit::Sgp4 sgp4(e);
  (void)orbit::describe(sgp4.init_error());
  if (sgp4.init_error() != orbit::Sgp4Error::none) return;
  (void)sgp4.period_minutes();
  (void)sgp4.perigee_km();
  (void)sgp4.apogee_km();
  const orbit::Observer tucson{32.259, -110.778, 842.0};
  // At epoch, a day on, and a year on (what a stale upload tracked today means).
  for (double minutes : {0.0, 1440.0, 525600.0}) {
    const auto p = sgp4.propagate_minutes(minutes);
    if (!p.ok()) continue;
    const auto o = orbit::observe(sgp4, tucson, orbit::add_minutes(sgp4.epoch(), minutes));
    if (o.ok()) {
      (void)orbit::visible(o, tucson);
      (void)orbit::doppler_shift_hz(435e6, o.look.range_rate_km_s);
    }
  }
  // The first set only: the schedule of menu 2 and the tracker search passes on every set.
  if (first) {
    const auto from = sgp4.epoch();
    (void)orbit::find_passes(sgp4, tucson, from, orbit::add_minutes(from, 360.0));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t mode = data[0];
  const std::string_view text = fuzz::as_text(data + 1, size - 1);

  orbit::ParseOptions options;
  options.verify_checksums = (mode & 0x10) == 0;
  options.strict_amsat_checksum = (mode & 0x20) != 0;

  orbit::ParseResult r;
  switch (mode & 0x03) {
    case 0: r = orbit::parse_nasa(text, "<fuzz>", options); break;
    case 1: r = orbit::parse_amsat(text, "<fuzz>", options); break;
    case 2: r = orbit::parse_gpredict_satdata(text, "<fuzz>", options); break;
    default: r = orbit::parse_elements(text, "<fuzz>", options); break;
  }
  for (const auto& p : r.problems) {
    const std::string m = p.message();
    TB_FUZZ_CHECK(!p.field.empty(), m);
    // The message is for a terminal: printable UTF-8 (issue 38), the field named as it shows there.
    TB_FUZZ_CHECK(text::is_safe_text(m), m);
    TB_FUZZ_CHECK(m.find(text::safe_text(p.field)) != std::string::npos, m);
  }
  (void)r.ok();

  std::size_t n = 0;
  for (const auto& e : r.sets) {
    if (n == 4) break;  // a bound on the work per input
    if ((mode & 0x40) == 0) check_round_trip(e);
    use(e, n == 0);
    ++n;
  }
  // Alpha-5 both ways on the first five bytes.
  if (text.size() >= 5) {
    const int c = orbit::decode_catalog_number(text.substr(0, 5));
    if (c >= 0) TB_FUZZ_CHECK(orbit::decode_catalog_number(orbit::encode_catalog_number(c)) == c, text.substr(0, 5));
  }
  return 0;
}
