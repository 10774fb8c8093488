// 6-9: Set default parameter. Every parameter goes back to its factory value and the kepele database
// is emptied (the manual: "the kepele database will be lost"); the real-time clock is not a
// parameter and keeps its time. Then a station file may be uploaded (src/store/station_file.h): it
// is read whole first and applied only when every line is valid.
#include "menus/6_configuration.h"
#include "store/model.h"
#include "rotator/parking_mask.h"
#include "rotator/split_travel.h"
#include "store/station_file.h"
#include "store/station_file_model.h"
#include "tracker/station_loop.h"

namespace tb::menus {

void menu_6_9_default_parameter(term::Terminal& t, Services& s) {
  t.line("Stored data in memory will be lost.");
  if (!ask_yes_no(t, "Are you sure ? [Y/N] ? ")) return;
  s.station.stop_antenna();  // tracking stops: the satellites it follows are about to go
  if (!commit(t, s, store::kAllAreas, "menu 6-9 defaults", [](store::Model& m) {
        const auto clock_offset = m.clock_offset;
        m = store::factory_defaults();
        m.clock_offset = clock_offset;
      }))
    return;
  t.bell();
  if (!ask_yes_no(t, "Configure your station elements by uploading data file ? [Y/N] ")) return;
  t.line("Upload Station info data file (EOF:ctrl-Z)");
  std::string text;
  const bool ended = t.read_upload([&](std::string_view line) {
    t.line(line);  // echoed as received
    text.append(line).append("\n");
  });
  if (!ended) throw InputClosed{};
  const store::StationFileParse parsed = store::parse_station_file(text);
  std::vector<std::string> problems;
  for (const auto& p : parsed.problems) problems.push_back(p.message());
  store::Model next = s.model;
  if (parsed.ok()) problems = store::apply_station_file(*parsed.file, next);
  if (!problems.empty()) {
    t.bell();
    for (const auto& p : problems) t.line("  " + p);
    t.line("Station file not applied: every parameter is at its default.");
    return;
  }
  if (!commit(t, s, store::kAllAreas, "menu 6-9 station file", [&](store::Model& m) { m = next; })) return;
  t.line("Station file loaded. Verify it with 6-0 (Display all configured value).");
  if (const auto w = rotator::split_travel_warning(s.model.rotator, s.model.station.rotor_start))
    for (const auto& line : cfg::wrap_words(*w)) t.line(line);
  // The file's parking position under the station's horizon mask (issue 57): kept, said.
  if (const auto w = rotator::parking_mask_warning(s.model.rotator, s.model.station.mask().get())) {
    t.bell();
    for (const auto& line : cfg::wrap_words("WARNING: " + *w + " (menu 4 sets the mask)")) t.line(line);
  }
}

}  // namespace tb::menus
