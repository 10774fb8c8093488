#include "host/host_mode.h"
#include "host/host_log.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "rotator/adc_model.h"
#include "tracker/elements_refresh.h"
#include "tracker/operations.h"
#include "tracker/station_loop.h"
#include "util/exact_number.h"
#include "util/text.h"

namespace tb::host {

namespace {

using text::upper;

bool blank(char c) { return c == ' ' || c == '\t'; }

// A decimal number at the front of s ([+-]digits[.digits]); advances s past it.
std::optional<double> take_number(std::string_view& s, std::string& text) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  const std::size_t digits_from = i;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
  bool any = i > digits_from;
  if (i < s.size() && s[i] == '.') {
    ++i;
    const std::size_t frac = i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    any = any || i > frac;
  }
  text.assign(s.substr(0, i));
  if (!any) return std::nullopt;
  std::string_view num = s.substr(s[0] == '+' ? 1 : 0, i - (s[0] == '+' ? 1 : 0));
  double v = 0.0;
  const auto [p, ec] = std::from_chars(num.data(), num.data() + num.size(), v);
  if (ec != std::errc() || p != num.data() + num.size()) return std::nullopt;
  s.remove_prefix(i);
  return v;
}

void skip_blanks(std::string_view& s) {
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
}

std::string num(double v) { return text::exact_number(v); }

constexpr auto error = &Reply::error;  // "ERROR ..."

}  // namespace

AzElParse parse_az_el(std::string_view line) {
  const char* kForm = "expected AZxxx ELxxx in degrees, e.g. AZ220 EL45";
  std::string_view s = text::trim(line, text::kWhitespace);
  AzElParse r;
  if (s.size() < 2 || upper(s.substr(0, 2)) != "AZ") {
    r.error = kForm;
    return r;
  }
  s.remove_prefix(2);
  skip_blanks(s);
  std::string text;
  const auto az = take_number(s, text);
  if (!az) {
    r.error = std::string("no azimuth after AZ: ") + kForm;
    return r;
  }
  skip_blanks(s);
  if (!s.empty() && (s.front() == '_' || s.front() == ',')) s.remove_prefix(1);
  skip_blanks(s);
  if (s.size() < 2 || upper(s.substr(0, 2)) != "EL") {
    r.error = s.empty() ? std::string("no EL: ") + kForm : "'" + std::string(s) + "' where EL was expected: " + kForm;
    return r;
  }
  s.remove_prefix(2);
  skip_blanks(s);
  const auto el = take_number(s, text);
  if (!el) {
    r.error = std::string("no elevation after EL: ") + kForm;
    return r;
  }
  skip_blanks(s);
  if (!s.empty()) {
    r.error = "'" + std::string(s) + "' after the elevation: " + kForm;
    return r;
  }
  if (!(*az >= 0.0 && *az <= 360.0)) {
    r.error = "azimuth " + num(*az) + " out of range: expected 0 to 360";
    return r;
  }
  if (!(*el >= 0.0 && *el <= 90.0)) {
    r.error = "elevation " + num(*el) + " out of range: expected 0 to 90";
    return r;
  }
  r.args = AzElArgs{*az, *el};
  return r;
}

std::optional<radio::Hz> parse_ten_hz(std::string_view digits) {
  if (digits.empty() || digits.size() > 9) return std::nullopt;
  radio::Hz v = 0;
  for (char c : digits) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
    v = v * 10 + (c - '0');
  }
  if (v == 0) return std::nullopt;
  return v * radio::kTuningStepHz;
}

std::optional<std::string> unescape(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\\') {
      out.push_back(text[i]);
      continue;
    }
    if (i + 1 < text.size() && text[i + 1] == '\\') {
      out.push_back('\\');
      ++i;
      continue;
    }
    if (i + 3 < text.size() && (text[i + 1] == 'x' || text[i + 1] == 'X')) {
      int v = 0;
      const auto [p, ec] = std::from_chars(text.data() + i + 2, text.data() + i + 4, v, 16);
      if (ec != std::errc() || p != text.data() + i + 4) return std::nullopt;
      out.push_back(static_cast<char>(v));
      i += 3;
      continue;
    }
    return std::nullopt;
  }
  return out;
}

std::string format_antenna(double az_deg, double el_deg) {
  double az = std::round(az_deg * 10.0) / 10.0;
  if (az >= 360.0) az -= 360.0;
  if (az < 0.0) az += 360.0;
  if (az == 0.0) az = 0.0;  // no -0.0
  double el = std::round(el_deg * 10.0) / 10.0;
  if (el == 0.0) el = 0.0;
  char buf[48];
  std::snprintf(buf, sizeof buf, "AZ%.1f EL%.1f", az, el);
  return buf;
}

Interpreter::Interpreter(tracker::StationLoop& station) : station_(station) {}

std::vector<std::string> Interpreter::greeting() {
  // The manual's two lines, then trakbox's own commands from the table (issue 60: the greeting
  // named none of LOG, PB, OR, OT, CT): a command is the manual's when the manual's line lists its
  // word (as is, or followed by its argument's x or _).
  std::vector<std::string> own;
  const std::string_view manual = kCommandLine.substr(kCommandLine.find(':') + 1);
  for (const Command& c : commands()) {
    const std::string_view word = c.word.substr(0, c.word.find(' '));   // "STANDBY ON": STANDBY
    bool listed = false;
    for (std::string_view item : text::split(manual, ','))
      listed = listed || item == word ||
               (item.rfind(word, 0) == 0 && (item[word.size()] == 'x' || item[word.size()] == '_'));
    if (!listed && std::find(own.begin(), own.end(), word) == own.end()) own.emplace_back(word);
  }
  std::string also = "Also:";
  for (std::size_t i = 0; i < own.size(); ++i) also += (i ? "," : "") + own[i];
  return {std::string(kBanner), std::string(kCommandLine), also + " (? explains each)"};
}

// Host mode's commands, one table (issue 55): the manual's and trakbox's own, in the order `?`
// lists them, each with its help line and what it runs. A line goes to the command whose word it
// matches (`exact`: the whole line; `prefix`: its start; `word`: the whole line or the word and a
// blank), the longest word winning ("STANDBY ON" before "S", "?A" before "?").
const std::vector<Interpreter::Command>& Interpreter::commands() {
  using M = Command::Match;
  auto tuned = [](Interpreter& in, std::string_view u, std::string_view s) { return *in.tuning(u, s); };
  static const std::vector<Command> kCommands = {
      {"AZ", M::prefix, "AZxxx ELxxx  point the antenna, degrees        AZ220 EL45",
       [](Interpreter& in, std::string_view, std::string_view s) { return in.az_el(s); }},
      {"MU", M::prefix, "MUxxx        uplink mode FM, LSB, USB or CW    MUFM",
       [](Interpreter& in, std::string_view, std::string_view s) { return in.mode("MU", s.substr(2)); }},
      {"MD", M::prefix, "MDxxx        downlink mode                     MDUSB",
       [](Interpreter& in, std::string_view, std::string_view s) { return in.mode("MD", s.substr(2)); }},
      {"FU", M::prefix, "FUxxxxxxxx   uplink frequency, 10 Hz units     FU14595000 = 145.950 MHz",
       [](Interpreter& in, std::string_view, std::string_view s) { return in.frequency("FU", s.substr(2)); }},
      {"FD", M::prefix, "FDxxxxxxxx   downlink frequency, 10 Hz units   FD43590000 = 435.900 MHz",
       [](Interpreter& in, std::string_view, std::string_view s) { return in.frequency("FD", s.substr(2)); }},
      // The string as typed after the S: only the blanks and CR/LF at the ends of the line are dropped
      // (\x20 sends a trailing blank).
      {"S", M::prefix, "Sxxx         send the string to the radio      STX;   (\\xHH sends byte HH)",
       [](Interpreter& in, std::string_view, std::string_view s) { return in.raw(s.substr(1)); }},
      {"?A", M::exact, "?A           present antenna position          reply AZ220.0 EL45.0",
       [](Interpreter& in, std::string_view, std::string_view) { return in.antenna(); }},
      {"RF", M::exact, "RF           refresh the elements now          (menu 3-5's sources)",
       [](Interpreter& in, std::string_view, std::string_view) { return in.refresh_now(); }},
      {"?R", M::exact, "?R           the last element refresh          reply REFRESH ...",
       [](Interpreter& in, std::string_view, std::string_view) { return in.refresh_status(); }},
      {"LOG", M::word, "LOG CALL [GRID] [RST]  log a QSO of this pass  reply LOGGED n CALL SAT TIME",
       [](Interpreter& in, std::string_view, std::string_view s) { return log_command(in.station_, s.substr(3)); }},
      {"?C", M::exact, "?C           who holds the antenna and radio   reply CONTROL ANTENNA ... RADIO ...",
       [](Interpreter& in, std::string_view, std::string_view) { return in.control(); }},
      {"STANDBY ON", M::exact, "STANDBY ON   standby (STANDBY OFF ends it)     nothing moves by itself",
       [](Interpreter& in, std::string_view, std::string_view) { return in.standby(true); }},
      {"STANDBY OFF", M::exact, "", [](Interpreter& in, std::string_view, std::string_view) { return in.standby(false); }},
      {"PB", M::prefix, "PBxxxxxxxxx  passband: the downlink spot, Hz   PB435640000 (a linear transponder)", tuned},
      {"OR", M::prefix, "ORxxx OTxxx  RX / TX offset in Hz, kept        OR+120  OT-300  (OR0 OT0 reset)", tuned},
      {"OT", M::prefix, "", tuned},
      {"CT", M::prefix, "CTxx.x       uplink CTCSS tone in Hz, 0 none   CT67.0", tuned},
      {"MODE", M::word, "MODE NAME    the tuned satellite's mode        MODE FT4  (MODE alone lists them)",
       [](Interpreter& in, std::string_view, std::string_view s) { return in.sat_mode(s.substr(4)); }},
      {"?T", M::exact, "?T           the tuning                        reply TUNE SPOT ... RX ... TX ... TONE ...", tuned},
      {"QTH", M::prefix, "QTHxxx       the station's position            QTH JN58td  or  QTH 48.15,11.58,520", tuned},
      {"?", M::exact, "?            this list",
       [](Interpreter&, std::string_view, std::string_view) { return Reply{help(), true, false}; }},
      {"Q", M::exact, "Q            quit to the main menu",
       [](Interpreter&, std::string_view, std::string_view) {
         Reply r;
         r.quit = true;
         return r;
       }},
  };
  return kCommands;
}

std::vector<std::string> Interpreter::help() {
  std::vector<std::string> lines;
  for (const Command& c : commands())
    if (!c.help.empty()) lines.emplace_back(c.help);
  return lines;
}

Reply Interpreter::standby(bool on) {
  const tracker::OpResult done = ops().standby(on);
  if (!done.ok()) return error("STANDBY: " + *done.refusal);
  return Reply{{done.note}, true, false};
}

Reply Interpreter::execute(std::string_view line) {
  const std::string_view s = text::trim(line, text::kWhitespace);
  if (s.empty()) return {};
  line_ = std::string(s);
  const std::string u = upper(s);
  const Command* best = nullptr;
  for (const Command& c : commands()) {
    const bool match = c.match == Command::Match::exact    ? u == c.word
                       : c.match == Command::Match::prefix ? u.rfind(c.word, 0) == 0
                                                           : u == c.word || u.rfind(std::string(c.word) + " ", 0) == 0;
    if (match && (!best || c.word.size() > best->word.size())) best = &c;
  }
  if (best) return best->run(*this, u, s);
  std::string shown(s.substr(0, 20));
  if (s.size() > 20) shown += "...";
  return error("unknown command '" + shown + "': expected AZxxx ELxxx, MUxxx, MDxxx, FUxxx, FDxxx, Sxxx, ?A, ? or Q");
}

// ?C: who holds the antenna and the radio (tracker/control.h), one line.
Reply Interpreter::control() {
  const tracker::Control& c = station_.control();
  return Reply{{"CONTROL ANTENNA " + c.holder(tracker::Resource::antenna).label + " RADIO " +
                c.holder(tracker::Resource::radio).label},
               true, false};
}

// RF / ?R: trakbox's own commands (the manual's set has no element refresh), answered with one line.
Reply Interpreter::refresh_now() {
  const tracker::OpResult done = ops().refresh_elements(tracker::ElementsRefresh::wall_now());
  if (!done.ok()) return error("RF: " + *done.refusal);
  return Reply{{"REFRESH STARTED"}, true, false};
}

Reply Interpreter::refresh_status() {
  tracker::ElementsRefresh* r = station_.refresh();
  if (!r) return error("?R: this trakbox has no element refresh (it runs only with the station)");
  if (r->running()) return Reply{{"REFRESH RUNNING"}, true, false};
  if (r->last_result().empty()) return Reply{{"REFRESH NONE YET"}, true, false};
  return Reply{{std::string(r->last_failed() ? "REFRESH FAILED " : "REFRESH OK ") + r->last_result()}, true, false};
}

Reply Interpreter::az_el(std::string_view line) {
  const AzElParse p = parse_az_el(line);
  if (!p.args) return error("AZ/EL: " + p.error);
  // A host program pointing the antenna takes control, as the operator pressing E would: it has no
  // other way to switch rotor control on. The limits still hold (go_to clamps).
  const std::string command(text::trim(line, text::kWhitespace));
  const tracker::OpResult done = ops(!unconfirmed_.empty() && unconfirmed_ == command).go_to(p.args->az, p.args->el);
  unconfirmed_ = done.confirm ? command : std::string();
  if (!done.ok()) return error("AZ/EL: " + *done.refusal + (done.confirm ? " (send it again to confirm)" : ""));
  Reply r;
  const rotator::AzEl asked{p.args->az, p.args->el};
  const rotator::AzEl got = *done.commanded;
  if (rotator::azimuth_distance(asked.az, got.az) > 0.05 || std::abs(asked.el - got.el) > 0.05)
    r.lines.push_back("LIMIT " + format_antenna(got.az, got.el));
  return r;
}

Reply Interpreter::mode(std::string_view cmd, std::string_view arg) {
  const std::string_view a = text::trim(arg, text::kWhitespace);
  const auto m = radio::parse_mode(a);
  if (!m || *m == radio::Mode::none)
    return error(std::string(cmd) + ": '" + std::string(a) + "' is not a radio mode: expected FM, LSB, USB or CW, e.g. " +
                 std::string(cmd) + "FM");
  if (auto no = ask_radio(cmd)) return *no;
  station_.tracker().stop();
  station_.radio().set_mode(cmd == "MU" ? radio::Link::uplink : radio::Link::downlink, *m);
  return radio_outcome(cmd);
}

Reply Interpreter::frequency(std::string_view cmd, std::string_view arg) {
  const std::string_view a = text::trim(arg, text::kWhitespace);
  const auto hz = parse_ten_hz(a);
  if (!hz)
    return error(std::string(cmd) + ": '" + std::string(a) +
                 "' is not a frequency: expected 1 to 9 digits in 10 Hz units, not 0, e.g. " + std::string(cmd) +
                 "14595000 for 145.950 MHz");
  // What a station radio tunes: HF to the 5.8 GHz band (a 10 GHz downlink reaches the radio at
  // its LNB's IF). Outside, the number was mistyped (FD999999999) or written short (FU14595 is
  // 145.950 kHz, not MHz): an error, not a radio set to nonsense.
  constexpr radio::Hz kLowest = 1'000'000, kHighest = 6'000'000'000;
  if (*hz < kLowest || *hz > kHighest) {
    char mhz[32];
    std::snprintf(mhz, sizeof mhz, "%.5f", static_cast<double>(*hz) / 1e6);
    return error(std::string(cmd) + ": " + std::string(a) + " is " + mhz +
                 " MHz, which no radio here tunes: expected 1 MHz to 6 GHz in 10 Hz units, e.g. " + std::string(cmd) +
                 "14595000 for 145.950 MHz");
  }
  if (auto no = ask_radio(cmd)) return *no;
  station_.tracker().stop();
  station_.radio().set_frequency(cmd == "FU" ? radio::Link::uplink : radio::Link::downlink, *hz);
  return radio_outcome(cmd);
}

Reply Interpreter::raw(std::string_view arg) {
  if (arg.empty()) return error("S: nothing to send: expected the string after S, e.g. STX;");
  const auto bytes = unescape(arg);
  if (!bytes) return error("S: a bad escape in '" + std::string(arg) + "': expected \\xHH (two hex digits) or \\\\");
  if (auto no = ask_radio("S")) return *no;
  station_.tracker().stop();
  station_.radio().send_raw(*bytes);
  return radio_outcome("S");
}

std::optional<Reply> Interpreter::ask_radio(std::string_view cmd) {
  const tracker::OpResult done = ops(!unconfirmed_.empty() && unconfirmed_ == line_).take_radio();
  unconfirmed_ = done.confirm ? line_ : std::string();
  if (done.ok()) return std::nullopt;
  return error(std::string(cmd) + ": " + *done.refusal + (done.confirm ? " (send it again to confirm)" : ""));
}

Reply Interpreter::radio_outcome(std::string_view cmd) {
  const radio::RadioStatus st = station_.radio().status();
  if (st.fault) return error(std::string(cmd) + ": radio fault: " + st.message);
  return {};
}

Reply Interpreter::antenna() {
  const auto a = station_.antenna();
  if (!a) {
    const auto& st = station_.rotator().status();
    return error("?A: no antenna position" + (st.link.ok() ? std::string() : ": " + st.link.message));
  }
  Reply r;
  r.lines.push_back(format_antenna(a->az, a->el));
  // With a GPS receiver (--gps), a second line: its fix (docs/gps.md).
  if (const gps::Monitor* g = station_.gps()) r.lines.push_back("GPS " + g->describe());
  return r;
}

}  // namespace tb::host
