// The realtime display's L key (trakbox's own; the manual's keys are E, Y, Q, + - 0, and trakbox
// adds U and D): log a QSO of the pass being tracked. One prompt, "Log QSO: CALL [GRID] [RST]", the
// rest filled from the station (tracker::LogOps); the line after it says the QSO is on disk, or
// why it was not logged (naming the field). An empty answer logs nothing.
#include "menus/realtime_log.h"

#include "logbook/qso.h"
#include "menus/common.h"
#include "tracker/log_ops.h"
#include "util/text.h"

namespace tb::menus {

void realtime_log_qso(term::Terminal& t, Services& s) {
  t.write("Log QSO: CALL [GRID] [RST] > ");
  const std::string answer = read_line(t, 40);
  std::vector<std::string> words;
  for (std::string_view w : text::split(text::trim(answer, text::kWhitespace), ' '))
    if (!w.empty()) words.emplace_back(w);
  if (words.empty()) {
    t.line("Nothing logged");
    return;
  }
  if (words.size() > 3) {
    t.line("Not logged: expected CALL [GRID] [RST]");
    return;
  }
  tracker::LogRequest req;
  req.source = logbook::Source::menus;
  req.call = words[0];
  for (std::size_t i = 1; i < words.size(); ++i)
    (text::is_digit(words[i][0]) ? req.rst_sent : req.grid) = words[i];
  const tracker::LogResult r = tracker::LogOps(s.station).log(req);
  if (!r.ok()) {
    t.line("Not logged: " + *r.refusal);
    return;
  }
  t.line("Logged #" + std::to_string(r.qso.id) + " " + r.qso.call + " " + r.qso.sat_name + " " + r.qso.mode + " " +
         logbook::utc_text(r.qso.time_on).substr(11) + " UTC");
}

}  // namespace tb::menus
