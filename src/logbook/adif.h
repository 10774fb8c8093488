#pragma once
// ADIF 3.1.4 (adif.org) out and in, pure. A satellite QSO as LoTW matches it: PROP_MODE SAT,
// SAT_NAME in TQSL's spelling, BAND/FREQ the uplink (what the station transmits), BAND_RX/FREQ_RX
// the downlink, FREQ in MHz, MODE the emission (never SAT), GRIDSQUARE and MY_GRIDSQUARE. What ADIF
// has no field for (the database's satellite name, the NORAD number, the frequencies as tuned, the
// front end) goes in APP_TRAKBOX_* fields, so that an export read back is the same log.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "logbook/qso.h"

namespace tb::logbook {

struct AdifExport {
  std::string text;
  std::vector<std::string> warnings;  // "QSO 3 (W1AW, CSS): no LoTW name for NORAD 48274; SAT_NAME left out"
};

// `created` is the export's UTC time (CREATED_TIMESTAMP); deleted records are left out.
AdifExport write_adif(const std::vector<Qso>& qsos, std::string_view program_version, std::int64_t created);
// One record as write_adif writes it, without a header ("<CALL:4>W1AW ... <EOR>\n"): what the
// logger's api/qso takes for one QSO.
std::string adif_record(const Qso& q);

// A record that is not a satellite QSO (an HF contact in a general logger's export): left out of
// the import and reported, not a refusal of the file.
struct AdifSkipped {
  std::size_t record = 0;   // counted from 1
  std::string call;         // as the record gives it ("" when it has none)
  std::string why;          // "PROP_MODE F2, not SAT"
};

struct AdifRead {
  std::vector<Qso> qsos;   // source import unless the file says it (APP_TRAKBOX_SOURCE)
  std::vector<AdifSkipped> skipped;
  std::string error;       // "record 3: TIME_ON: ..." or "header: ..."; no records when set
  bool ok() const { return error.empty(); }
};

// The satellite QSOs of a whole file or nothing: every refusal names the record (counted from 1)
// and the field. Records that are not satellite QSOs (a PROP_MODE other than SAT, or neither
// PROP_MODE nor SAT_NAME) are skipped and listed, whatever else they hold. Field lengths count bytes.
AdifRead read_adif(std::string_view text);

// "145.965000" of 145965000 Hz; the MHz text back into Hz (nullopt when not a number of MHz with
// at most 6 decimals).
std::string mhz_text(std::int64_t hz);
std::optional<std::int64_t> parse_mhz_hz(std::string_view s);

}  // namespace tb::logbook
