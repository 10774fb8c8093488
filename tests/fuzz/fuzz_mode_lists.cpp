// The readers of the public mode lists and the merge (store/mode_import.h): the input's first byte
// picks the format (satnogs, trsp, sqf, subtone, oscarwatch), the rest is the file. Properties: the
// reader never throws and a refused file offers nothing; the merge into the shipped database keeps
// mode_merge_checks.h's properties, with and without `replace`.
#include "fuzz_station.h"
#include "mode_merge_checks.h"

using namespace tb;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  static const store::Model shipped = testing::shipped_model();
  const auto format = static_cast<store::ListFormat>(data[0] % 5);
  const std::string_view text = fuzz::as_text(data + 1, size - 1);
  const store::ModeList list = store::read_mode_list(format, text, "44909.trsp");
  TB_FUZZ_CHECK(list.ok() || list.modes.empty(), "a refused list offers modes: " + list.error);
  for (const bool replace : {false, true}) {
    store::Database db = shipped.db;
    const store::MergeReport r = store::merge_modes(db, list, replace);
    if (!list.ok()) TB_FUZZ_CHECK(!r.changed, "a refused list changed the database: " + list.error);
    fuzz::check_merge(shipped.db, db, replace, std::string(store::to_string(format)));
  }
  return 0;
}
