#include "host/host_log.h"

#include "logbook/qso.h"
#include "tracker/log_ops.h"
#include "util/text.h"

namespace tb::host {

Reply log_command(tracker::StationLoop& station, std::string_view args) {
  const auto refuse = [](const std::string& why) { return Reply{{"ERROR LOG: " + why}, false, false}; };
  std::vector<std::string_view> words;
  for (std::string_view w : text::split(text::trim(args, text::kWhitespace), ' '))
    if (!w.empty()) words.push_back(w);
  if (words.empty() || words.size() > 3) return refuse("expected LOG CALL [GRID] [RST]");
  tracker::LogRequest req;
  req.source = logbook::Source::host;
  req.call = std::string(words[0]);
  for (std::size_t i = 1; i < words.size(); ++i) {
    const bool digits = !words[i].empty() && text::is_digit(words[i][0]);
    std::string& slot = digits ? req.rst_sent : req.grid;
    if (!slot.empty()) return refuse("expected LOG CALL [GRID] [RST]");
    slot = std::string(words[i]);
  }
  const tracker::LogResult r = tracker::LogOps(station).log(req);
  if (!r.ok()) return refuse(*r.refusal);
  Reply done{{"LOGGED " + std::to_string(r.qso.id) + " " + r.qso.call + " " + r.qso.sat_name + " " +
               logbook::utc_text(r.qso.time_on)},
              true, false};
  if (r.warning) done.lines.push_back("NOTE " + *r.warning);
  return done;
}

}  // namespace tb::host
