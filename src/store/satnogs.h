// Modes from the SatNOGS DB transmitter list (https://db.satnogs.org/api/transmitters/?format=json,
// the list Gpredict uses): menu 3-5's S. The one SatNOGS importer: the list is read by
// store/mode_import.h's reader (every alive, active transmitter a mode) and merged into the
// database's modes (the operator's values kept, conflicts reported), as `trakbox radio import` does.
// Pure: JSON text in, a report and the changed database out; the menu fetches the list.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "store/database.h"
#include "store/mode_import.h"

namespace tb::store {

struct SatnogsImport {
  MergeReport report;
  std::vector<std::string> lines;    // report_lines: added, updated, conflicts, then the count
  int without_transmitter = 0;       // database satellites with no active transmitter in the list
  std::string error;                 // not a SatNOGS transmitter list: nothing was changed
  bool ok() const { return error.empty(); }
};

// Reads the list and merges its modes into db (matched by catalog number). `replace` takes the
// list's values over the operator's too. The database changes only when the whole text is a valid list.
SatnogsImport import_satnogs(Database& db, std::string_view json_text, bool replace);

}  // namespace tb::store
