// The SatNOGS DB transmitter list into the database's freq/mode records (store::import_satnogs),
// on the shipped database. Properties: a refused list (an error) changes nothing; an accepted one
// changes only radio entries (elements, names, the tracking list stay), keeps the operator's
// records without `replace`, and every record it writes is one the freq/mode file can carry
// (it reads back through write_freqmode / parse_freqmode).
#include "fuzz_station.h"
#include "store/satnogs.h"

using namespace tb;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::as_text(data, size);
  static const store::Model shipped = testing::shipped_model();
  for (const bool replace : {false, true}) {
    store::Database db = shipped.db;
    const store::SatnogsImport r = store::import_satnogs(db, text, replace);
    TB_FUZZ_CHECK(db.satellites.size() == shipped.db.satellites.size() && db.selected == shipped.db.selected,
                  "the database's shape changed");
    for (std::size_t i = 0; i < db.satellites.size(); ++i) {
      const auto& now = db.satellites[i];
      const auto& was = shipped.db.satellites[i];
      TB_FUZZ_CHECK(now.elements.name == was.elements.name && now.elements.epoch_day == was.elements.epoch_day,
                    "elements changed");
      if (!r.ok()) TB_FUZZ_CHECK(now.radio == was.radio, "a refused list changed " + now.name() + ": " + r.error);
      if (!replace && (was.radio.has_downlink() || was.radio.has_uplink()))
        TB_FUZZ_CHECK(now.radio == was.radio, "the operator's record of " + now.name() + " changed");
      if (now.radio == was.radio) continue;
      const radio::FreqModeRecord rec{0, now.name(), now.radio, {}, 0};
      const auto back = radio::parse_freqmode(radio::write_freqmode({rec}));
      std::string why = radio::write_freqmode({rec});
      for (const auto& p : back.problems) why += p.message() + "\n";
      TB_FUZZ_CHECK(back.ok() && back.records.size() == 1 && back.records[0].radio == now.radio, why);
    }
  }
  return 0;
}
