// The station information file of menu 6-9 (store::parse_station_file, apply_station_file).
// Properties: every problem has a message; a refused apply changes nothing; what
// write_station_file makes of an applied file parses clean and applies (it rounds: %.3f, %g); so does
// what write_station_file_later makes of an applied later-firmware (seven-line) file.
#include "fuzz_station.h"
#include "store/station_file.h"
#include "store/station_file_model.h"

using namespace tb;

namespace {
bool same_model(const store::Model& a, const store::Model& b) {
  return store::to_json(a) == store::to_json(b);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::as_text(data, size);
  const auto r = store::parse_station_file(text);
  for (const auto& p : r.problems) {
    const std::string m = p.message();
    TB_FUZZ_CHECK(!m.empty(), m);
    (void)store::station_file_item_name(p.line, p.field);
    (void)store::station_file_item_name(p.line, p.field, true);
  }
  TB_FUZZ_CHECK(r.ok() == r.file.has_value(), std::string(text));
  if (!r.file) return 0;

  store::Model m = store::factory_defaults();
  const store::Model before = m;
  const auto complaints = store::apply_station_file(*r.file, m);
  if (!complaints.empty()) {
    TB_FUZZ_CHECK(same_model(m, before), "a refused station file changed the model");
    return 0;
  }
  const std::string written = store::write_station_file(m);
  const auto again = store::parse_station_file(written);
  std::string why = written;
  for (const auto& p : again.problems) why += p.message() + "\n";
  TB_FUZZ_CHECK(again.ok(), why);
  store::Model m2 = store::factory_defaults();
  TB_FUZZ_CHECK(store::apply_station_file(*again.file, m2).empty(), why);
  if (r.file->later_firmware) {
    const std::string later = store::write_station_file_later(m);
    const auto back = store::parse_station_file(later);
    std::string why_later = later;
    for (const auto& p : back.problems) why_later += p.message() + "\n";
    TB_FUZZ_CHECK(back.ok() && back.file->later_firmware, why_later);
    store::Model m3 = store::factory_defaults();
    TB_FUZZ_CHECK(store::apply_station_file(*back.file, m3).empty(), why_later);
  }
  return 0;
}
