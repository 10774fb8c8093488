// The SatNOGS DB transmitter list merged into the database's modes (store::import_satnogs, menu
// 3-5's S), on the shipped database. Properties: a refused list (an error) changes nothing; an
// accepted one keeps mode_merge_checks.h's properties (shape and elements stay, the operator's and
// the freq/mode file's values stay without `replace`, the result reads back as a state).
#include "fuzz_station.h"
#include "mode_merge_checks.h"
#include "store/satnogs.h"

using namespace tb;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::as_text(data, size);
  static const store::Model shipped = testing::shipped_model();
  for (const bool replace : {false, true}) {
    store::Database db = shipped.db;
    const store::SatnogsImport r = store::import_satnogs(db, text, replace);
    if (!r.ok()) {
      TB_FUZZ_CHECK(!r.report.changed,
                    "a refused list changed: " + r.error);
      for (std::size_t i = 0; i < db.satellites.size(); ++i)
        TB_FUZZ_CHECK(store::modes_of(db.satellites[i]) == store::modes_of(shipped.db.satellites[i]),
                      "a refused list changed " + db.satellites[i].name() + ": " + r.error);
    }
    fuzz::check_merge(shipped.db, db, replace, "satnogs");
  }
  return 0;
}
