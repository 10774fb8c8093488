// The realtime display's L key (trakbox's own; the manual's keys are E, Y, Q, + - 0, and trakbox
// adds U and D): log a QSO of the pass being tracked. One prompt, "Log QSO: CALL [GRID] [RST]", the
// rest filled from the station (tracker::LogOps); what it says (the QSO is on disk, or why it was
// not logged, naming the field) is a line on a serial terminal and stays in the full screen's live
// block under the radio line, as the tuning keys' answers do. An empty answer logs nothing.
#include "menus/realtime_log.h"

#include "logbook/qso.h"
#include "menus/common.h"
#include "menus/realtime_tuning.h"
#include "tracker/log_ops.h"
#include "util/text.h"

namespace tb::menus {

std::string realtime_log_qso(term::Terminal& t, Services& s) {
  live_prompt(t, "Log QSO: CALL [GRID] [RST] > ");
  const std::string answer = read_line(t, 40);
  std::vector<std::string> words;
  for (std::string_view w : text::split(text::trim(answer, text::kWhitespace), ' '))
    if (!w.empty()) words.emplace_back(w);
  if (words.empty()) return live_said(t, "Nothing logged");
  if (words.size() > 3) return live_said(t, "Not logged: expected CALL [GRID] [RST]");
  tracker::LogRequest req;
  req.source = logbook::Source::menus;
  req.call = words[0];
  for (std::size_t i = 1; i < words.size(); ++i)
    (text::is_digit(words[i][0]) ? req.rst_sent : req.grid) = words[i];
  const tracker::LogResult r = tracker::LogOps(s.station).log(req);
  if (!r.ok()) return live_said(t, "Not logged: " + *r.refusal);
  return live_said(t, "Logged #" + std::to_string(r.qso.id) + " " + r.qso.call + " " + r.qso.sat_name + " " +
                          r.qso.mode + " " + logbook::utc_text(r.qso.time_on).substr(11) + " UTC" +
                          (r.warning ? "; NOTE " + *r.warning : std::string()));
}

}  // namespace tb::menus
