#include "store/satnogs.h"

#include <set>

namespace tb::store {

SatnogsImport import_satnogs(Database& db, std::string_view json_text, bool replace) {
  SatnogsImport r;
  const ModeList list = read_mode_list(ListFormat::satnogs, json_text, "SatNOGS list");
  if (!list.ok()) {
    r.error = list.error;
    return r;
  }
  std::set<long long> listed;
  for (const ListedMode& l : list.modes) listed.insert(l.catalog);
  for (const Satellite& s : db.satellites)
    if (!listed.contains(s.elements.catalog_number)) ++r.without_transmitter;
  Database merged = db;
  r.report = merge_modes(merged, list, replace);
  r.lines = report_lines(r.report, list);
  db = std::move(merged);
  return r;
}

}  // namespace tb::store
