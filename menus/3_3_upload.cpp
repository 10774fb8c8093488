// Menu 3-3: Update. Clears the database and reads a new one as an ASCII upload ending in Ctrl-Z
// (NASA two/three-line or AMSAT verbose, chosen first), then the freq/mode file:
//
//   Stored data in memory will be lost.
//   Are you sure ? [Y/N] ? Y
//   File format NASA/AMSAT (N/A) : N
//   Upload Kepeledata file. (EOF:ctrl+Z)
//   ...each line echoed as it arrives...
//   NASA>#1 AO-10
//   ...
//   Upload freq/mode data file. (EOF:ctrl+Z)
//   ...each line echoed...
//   Satellite (AO-10) updated and selected as # 1
//
// Each step is all or nothing for the stored state: the element upload replaces the database only
// when it ended with Ctrl-Z and gave at least one set; the freq/mode step applies its good records
// only when its upload ended with Ctrl-Z. Every record not taken is reported with its line and why.
// The business rules (names carried over, 32 satellites, list order) are store::Database's.
#include <cctype>

#include "menus/menus.h"
#include "store/model.h"
#include "tracker/station_loop.h"

namespace tb::menus {

namespace {

// Reads an upload, echoing each line as it arrives. Lines are joined with '\n' so that line
// numbers in problems are the upload's own. Throws InputClosed (after telling the operator)
// when the input ends before Ctrl-Z.
std::string read_echoed_upload(term::Terminal& t, const char* what_is_kept) {
  std::string text;
  const bool complete = t.read_upload([&](std::string_view line) {
    t.line(line);
    t.flush();
    text.append(line).append("\n");
  });
  if (!complete) {
    t.line("Upload ended before Ctrl-Z: " + std::string(what_is_kept));
    t.flush();
    throw InputClosed{};
  }
  return text;
}

bool blank(std::string_view text) {
  for (char c : text)
    if (!std::isspace(static_cast<unsigned char>(c))) return false;
  return true;
}

// "Line 5 skipped: checksum (column 69): found '3', expected checksum 5"
std::string describe(const orbit::ParseProblem& p) {
  std::string m = "Line " + std::to_string(p.line) + (p.warning ? " warning: " : " skipped: ") + p.field;
  if (p.column > 0) m += " (column " + std::to_string(p.column) + ")";
  m += ": found " + (p.found.empty() ? std::string("nothing") : "'" + p.found + "'") + ", expected " + p.expected;
  return m;
}

std::vector<std::string> upload_database_names(const store::Database& db) {
  std::vector<std::string> names;
  for (const auto& sat : db.satellites) names.push_back(sat.name());
  return names;
}

// O: the OMM encodings, told apart by their content; a NASA or AMSAT text is not taken for OMM.
orbit::ParseResult parse_omm_upload(const std::string& text) {
  orbit::ParseResult r = orbit::parse_elements(text, "<upload>");
  const auto not_omm = [](const orbit::Elements& e) {
    return e.source == orbit::ElementFormat::nasa || e.source == orbit::ElementFormat::amsat;
  };
  if (!r.sets.empty() && not_omm(r.sets.front())) {
    orbit::ParseProblem p;
    p.file = "<upload>";
    p.line = 1;
    p.field = "format";
    p.found = orbit::describe(r.sets.front().source);
    p.expected = "OMM (JSON, XML, CSV or KVN); answer N or A for NASA or AMSAT text";
    return orbit::ParseResult{{}, {p}};
  }
  return r;
}

}  // namespace

void menu_3_3_upload(term::Terminal& t, Services& s) {
  t.line("Stored data in memory will be lost.");
  if (!ask_yes_no(t, "Are you sure ? [Y/N] ? ")) return;
  // The manual's prompt, and trakbox's third format (said on the line before): OMM, in which
  // CelesTrak publishes the satellites numbered beyond what a TLE holds.
  t.line("(or O: OMM - JSON, XML, CSV or KVN, detected)");
  const char key = ask_key(t, "File format NASA/AMSAT (N/A) : ", "NAO");
  const bool nasa = key == 'N', omm = key == 'O';
  const char* format = nasa ? "NASA" : omm ? "OMM" : "AMSAT";

  // ---- step 1: the element sets ----
  t.line("Upload Kepeledata file. (EOF:ctrl+Z)");
  t.flush();
  const std::string kepele = read_echoed_upload(t, "the stored database is unchanged.");

  orbit::ParseOptions options;
  options.strict_amsat_checksum = true;  // a serial upload: a wrong checksum is a damaged set
  orbit::ParseResult parsed = nasa  ? orbit::parse_nasa(kepele, "<upload>", options)
                              : omm ? parse_omm_upload(kepele)
                                    : orbit::parse_amsat(kepele, "<upload>", options);
  parsed = orbit::clean_names(std::move(parsed), kepele, "<upload>");  // names from a terminal (issue 38)
  const std::vector<orbit::ParseProblem> problems = std::move(parsed.problems);
  parsed.problems.clear();  // reported here, with their lines, rather than by build_elements_upload
  store::ElementsUpload up = store::build_elements_upload(s.model.db, parsed);

  for (std::size_t k = 0; k < up.accepted.size(); ++k)
    t.line(std::string(format) + ">#" + std::to_string(k + 1) + " " + up.accepted[k]);
  std::size_t skipped = 0;
  for (const auto& p : problems) {
    t.line(describe(p));
    if (!p.warning) ++skipped;
  }
  for (const auto& m : up.skipped) t.line("Skipped: " + m);
  skipped += up.skipped.size();
  t.line(std::to_string(up.accepted.size()) + " satellite(s) accepted, " + std::to_string(skipped) +
         " record(s) skipped.");
  if (up.accepted.empty()) {
    t.line(blank(kepele) || !problems.empty() ? "No satellite data accepted: the stored database is unchanged."
                                              : std::string("No ") + format +
                                                    " element set found in the upload: the stored database is "
                                                    "unchanged.");
    return;
  }
  const bool was_tracking = s.tracker.mode() != tracker::Mode::off;
  // Database numbers now mean other satellites: nothing may be followed by its old number.
  s.tracker.stop();
  if (!commit(t, s, store::bit(store::Area::elements) | store::bit(store::Area::radio_entries) | store::bit(store::Area::tracking_list), "menu 3-3 elements",
              [&](store::Model& m) { m.db = std::move(up.database); }))
    return;
  if (was_tracking) t.line("Tracking stopped: the database changed (choose a satellite again with 1, S or M).");

  // ---- step 2: the freq/mode file (Ctrl-Z alone: none) ----
  t.line("Upload freq/mode data file. (EOF:ctrl+Z)");
  t.flush();
  const std::string freqmode =
      read_echoed_upload(t, "no freq/mode data applied (the new element data is stored).");
  if (blank(freqmode)) {
    t.line("No freq/mode data: known satellites kept their frequencies; the tracking list is the first " +
           std::to_string(s.model.db.selected.size()) + " satellite(s) of the database.");
  } else {
    const radio::FreqModeParse fm = radio::parse_freqmode(freqmode);
    store::Database db = s.model.db;  // committed whole, below
    const store::FreqModeUpload applied = store::apply_freqmode(db, fm.records);
    for (const auto& line : applied.updated) t.line(line);
    for (const auto& p : fm.problems) t.line("Skipped " + p.message());
    for (const auto& m : applied.skipped) t.line("Skipped " + m);
    t.line(std::to_string(applied.updated.size()) + " satellite(s) updated and selected, " +
           std::to_string(fm.problems.size() + applied.skipped.size()) + " record(s) skipped.");
    if (applied.updated.empty())
      t.line("No freq/mode record applied: the tracking list is the first " + std::to_string(db.selected.size()) +
             " satellite(s) of the database.");
    (void)commit(t, s, store::bit(store::Area::radio_entries) | store::bit(store::Area::tracking_list),
                 "menu 3-3 freq/mode", [&](store::Model& m) { m.db = std::move(db); });
  }

  // ---- the new database ----
  t.line("     *** Satellite database ***");
  for (const auto& r : format_satellite_list(upload_database_names(s.model.db), s.model.db.marked_index().value_or(-1)))
    t.line(r);
}

}  // namespace tb::menus
