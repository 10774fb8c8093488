#include "menus/realtime_tuning.h"

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

// Runs the operation (asking for the radio), saves what it kept, and says what happened.
bool tune(term::Terminal& t, Services& s, const std::function<tracker::OpResult(tracker::StationOps&)>& op,
          bool say_note) {
  const tracker::OpResult r = with_confirmation(t, s.station, op);   // a refusal is shown there
  if (!r.ok()) return false;
  if (r.model_changed) save_or_report(t, s);   // the offsets, kept per satellite and mode
  if (say_note && !r.note.empty()) t.line(r.note);
  return true;
}

}  // namespace

std::optional<long long> parse_spot_hz(std::string_view text) {
  const auto dot = text.find('.');
  long long hz = 0;
  if (dot == std::string_view::npos) {
    if (!all_digits(text) || text.size() > 12) return std::nullopt;
    hz = *text::parse_integer<long long>(text);
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

void realtime_type_spot(term::Terminal& t, Services& s) {
  t.write("Spot (downlink, MHz 435.645 or Hz 435645000) > ");
  const std::string answer = text::trimmed(read_line(t, 20));
  if (answer.empty()) {
    t.line("Spot unchanged");
    return;
  }
  const auto hz = parse_spot_hz(answer);
  if (!hz) {
    t.line("Spot unchanged: " + quoted(answer) + " is not a frequency: expected MHz such as 435.645 or Hz such as "
           "435645000");
    return;
  }
  tune(t, s, [hz](tracker::StationOps& o) { return o.tune_spot(*hz); }, true);
}

void realtime_type_offset(term::Terminal& t, Services& s, bool tx) {
  const std::string what = tx ? "TX offset" : "RX offset";
  t.write(what + " (Hz, e.g. -300; 0 resets) > ");
  const std::string answer = text::trimmed(read_line(t, 20));
  if (answer.empty()) {
    t.line(what + " unchanged");
    return;
  }
  const auto hz = parse_offset_hz(answer);
  if (!hz) {
    t.line(what + " unchanged: " + quoted(answer) + " is not a whole number of Hz: expected -" +
           std::to_string(radio::kMaxOffsetHz) + " to " + std::to_string(radio::kMaxOffsetHz) + ", e.g. -300");
    return;
  }
  const std::optional<long long> v = *hz;
  tune(t, s, [v, tx](tracker::StationOps& o) { return tx ? o.tune_offsets(std::nullopt, v) : o.tune_offsets(v, std::nullopt); },
       true);
}

void realtime_step_offset(term::Terminal& t, Services& s, int direction) {
  const long long rit = s.station.tuner().rit_hz();
  const std::optional<long long> to = direction > 0 ? rit + radio::kRitStepHz : direction < 0 ? rit - radio::kRitStepHz : 0;
  if (!tune(t, s, [to](tracker::StationOps& o) { return o.tune_offsets(to, std::nullopt); }, false)) return;
  // A serial terminal has no radio line redrawn in place: the new offset in a line (issue 18, item 6).
  if (!t.full_screen()) t.line("Frequency offset " + std::string(s.station.tuner().rit_hz() > 0 ? "+" : "") +
                               std::to_string(s.station.tuner().rit_hz()) + " Hz");
}

}  // namespace tb::menus
