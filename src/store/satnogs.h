// Frequencies from the SatNOGS DB transmitter list (https://db.satnogs.org/api/transmitters/?format=json,
// the list Gpredict uses): the active transmitters of the database's satellites become their
// freq/mode records (menu 3-1's F1/F2 and modes). Pure: JSON text in, a report and the changed
// database out; the menu (3-5) fetches the list.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "store/database.h"

namespace tb::store {

struct SatnogsImport {
  std::vector<std::string> updated;  // "ISS: downlink 437.800 FM, uplink 145.990 FM (FM voice)"
  std::vector<std::string> kept;     // the operator's own records, left alone (without `replace`)
  int without_transmitter = 0;       // database satellites with no active transmitter in the list
  std::string error;                 // not a SatNOGS transmitter list: nothing was changed
  bool ok() const { return error.empty(); }
};

// Reads the list (a JSON array of transmitter objects) and, for every satellite of the database
// (matched by catalog number) with an active transmitter, sets its radio entry: a transponder or
// transceiver with an uplink first, else the first active downlink. A passband's centre is used,
// and an inverting linear transponder gets LSB up / USB down. A satellite whose record the
// operator has filled in (a downlink or uplink frequency) is left alone unless `replace`.
// The database changes only when the whole text is a valid list.
SatnogsImport import_satnogs(Database& db, std::string_view json_text, bool replace);

}  // namespace tb::store
