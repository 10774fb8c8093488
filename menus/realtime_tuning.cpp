#include "menus/realtime_tuning.h"

#include <algorithm>

#include "menus/common.h"
#include "menus/take_back.h"
#include "radio/doppler.h"
#include "tracker/operations.h"
#include "tracker/station_loop.h"

namespace tb::menus {

namespace {

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!text::is_digit(c)) return false;
  return true;
}

// The answer as typed, short enough to quote.
std::string quoted(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size() && i < 20; ++i) out.push_back(s[i] >= 0x20 && s[i] < 0x7f ? s[i] : '?');
  return "'" + out + (s.size() > 20 ? "...'" : "'");
}

// Runs the operation (asking for the radio) and saves what it kept: the note, or the refusal.
// Nothing when the operator answered N to taking the radio back.
std::optional<std::string> tune(term::Terminal& t, Services& s,
                                const std::function<tracker::OpResult(tracker::StationOps&)>& op, bool& ok) {
  const tracker::OpResult r = with_confirmation(t, s.station, op, false);
  ok = r.ok();
  if (!ok) {
    if (r.confirm) return std::nullopt;   // N: left to the outside client, as asked
    return *r.refusal;
  }
  if (r.model_changed) save_or_report(t, s);   // the offsets, kept per satellite and mode
  return r.note;
}

}  // namespace

std::optional<long long> parse_spot_hz(std::string_view text) {
  const auto dot = text.find('.');
  long long hz = 0;
  if (dot == std::string_view::npos) {
    if (!all_digits(text) || text.size() > 12) return std::nullopt;
    hz = *text::parse_integer<long long>(text);
    if (hz < 1'000'000) hz *= 1'000'000;   // "437": MHz (no satellite's spot is under 1 MHz)
  } else {
    const std::string_view whole = text.substr(0, dot), frac = text.substr(dot + 1);
    if (!all_digits(whole) || whole.size() > 6 || frac.size() > 6 || (!frac.empty() && !all_digits(frac)))
      return std::nullopt;
    std::string micro(frac);
    micro.resize(6, '0');
    hz = *text::parse_integer<long long>(whole) * 1'000'000 + *text::parse_integer<long long>(micro);
  }
  if (hz <= 0) return std::nullopt;
  return hz;
}

std::optional<long long> parse_offset_hz(std::string_view text) {
  std::string_view digits = text;
  if (!digits.empty() && (digits.front() == '+' || digits.front() == '-')) digits.remove_prefix(1);
  if (!all_digits(digits) || digits.size() > 9) return std::nullopt;
  return text::parse_integer<long long>(text);
}

std::string realtime_type_spot(term::Terminal& t, Services& s) {
  live_prompt(t, "Spot (downlink, MHz 435.645 or Hz 435645000) > ");
  const std::string answer = text::trimmed(read_line(t, 20));
  if (answer.empty()) return live_said(t, "Spot unchanged");
  const auto hz = parse_spot_hz(answer);
  if (!hz)
    return live_said(t, "Spot unchanged: " + quoted(answer) +
                       " is not a frequency: expected MHz such as 435.645 or Hz such as 435645000");
  bool ok = false;
  const auto r = tune(t, s, [hz](tracker::StationOps& o) { return o.tune_spot(*hz); }, ok);
  return r ? live_said(t, *r) : std::string();
}

std::string realtime_type_offset(term::Terminal& t, Services& s, bool tx) {
  const std::string what = tx ? "TX offset" : "RX offset";
  live_prompt(t, what + " (Hz, e.g. -300; 0 resets) > ");
  const std::string answer = text::trimmed(read_line(t, 20));
  if (answer.empty()) return live_said(t, what + " unchanged");
  const auto hz = parse_offset_hz(answer);
  if (!hz)
    return live_said(t, what + " unchanged: " + quoted(answer) + " is not a whole number of Hz: expected -" +
                       std::to_string(radio::kMaxOffsetHz) + " to " + std::to_string(radio::kMaxOffsetHz) + ", e.g. -300");
  const std::optional<long long> v = *hz;
  bool ok = false;
  const auto r = tune(t, s, [v, tx](tracker::StationOps& o) {
    return tx ? o.tune_offsets(std::nullopt, v) : o.tune_offsets(v, std::nullopt);
  }, ok);
  return r ? live_said(t, *r) : std::string();
}

std::string realtime_type_mode(term::Terminal& t, Services& s) {
  const auto tuned = s.station.tuned();
  if (!tuned) return live_said(t, "Mode unchanged: no satellite is tuned");
  const store::Satellite& sat = s.model.db.satellites[static_cast<std::size_t>(*tuned)];
  const std::string name = sat.name();  // (a copy: the edit replaces the record)
  std::string names;
  for (const auto& m : store::modes_of(sat)) names += (names.empty() ? "" : " ") + m.name;
  if (names.empty()) return live_said(t, "Mode unchanged: " + name + " has no modes");
  live_prompt(t, "Mode (" + names + ") > ");
  const std::string answer = text::trimmed(read_line(t, 20));
  if (answer.empty()) return live_said(t, "Mode unchanged");
  bool ok = false;
  const auto r = tune(t, s, [&name, &answer](tracker::StationOps& o) { return o.choose_mode(name, answer); }, ok);
  return r ? live_said(t, *r) : std::string();
}

std::string realtime_step_offset(term::Terminal& t, Services& s, int direction) {
  const long long rit = s.station.tuner().rit_hz();
  const std::optional<long long> to = direction > 0 ? rit + radio::kRitStepHz : direction < 0 ? rit - radio::kRitStepHz : 0;
  bool ok = false;
  const auto r = tune(t, s, [to](tracker::StationOps& o) { return o.tune_offsets(to, std::nullopt); }, ok);
  if (!r) return "";
  if (!ok) return live_said(t, *r);
  // The manual's RIT: the new offset (the full screen's radio line shows it too; issue 18, item 6).
  const radio::Hz now = s.station.tuner().rit_hz();
  return live_said(t, "Frequency offset " + std::string(now > 0 ? "+" : "") + std::to_string(now) + " Hz");
}

void live_prompt(term::Terminal& t, const std::string& text) {
  if (t.full_screen()) t.write("\r" + std::string(static_cast<std::size_t>(std::max(0, t.columns() - 1)), ' ') + "\r");
  t.write(text);
}

std::string live_said(term::Terminal& t, std::string text) {
  if (!t.full_screen()) t.line(text);
  return text;
}

}  // namespace tb::menus
