#include "netctl/protocol.h"

#include "util/text.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace tb::netctl {

std::string rprt(Error e) { return "RPRT " + std::to_string(-static_cast<int>(e)); }

namespace {
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// The Extended Response Protocol's markers: any punctuation but '\' (long names), '?' (help),
// '_' (get_info) and '#' (comments).
bool is_separator_marker(char c) {
  return std::ispunct(static_cast<unsigned char>(c)) && c != '\\' && c != '?' && c != '_' && c != '#';
}
}  // namespace

std::optional<Request> parse_request(std::string_view line) {
  std::size_t i = 0;
  while (i < line.size() && is_space(line[i])) ++i;
  if (i == line.size() || line[i] == '#') return std::nullopt;
  Request r;
  if (is_separator_marker(line[i])) {
    r.separator = line[i] == '+' ? '\n' : line[i];
    ++i;
  }
  if (i == line.size()) return std::nullopt;
  std::size_t end = i;
  if (line[i] == '\\') {
    r.long_name = true;
    ++i;
    end = i;
    while (end < line.size() && !is_space(line[end])) ++end;
    r.name = std::string(line.substr(i, end - i));
  } else {
    // A short command is one character; its arguments may follow without a space ("F14250000").
    r.name = std::string(1, line[i]);
    end = i + 1;
  }
  std::size_t p = end;
  while (p < line.size()) {
    while (p < line.size() && is_space(line[p])) ++p;
    if (p == line.size()) break;
    std::size_t q = p;
    while (q < line.size() && !is_space(line[q])) ++q;
    r.args.emplace_back(line.substr(p, q - p));
    p = q;
  }
  return r;
}

std::string format_reply(const Request& r, std::string_view long_name, bool get, const Outcome& o) {
  std::string out;
  if (r.extended()) {
    const char sep = r.separator;
    // The request is echoed: its control bytes (NUL, ESC, ... -- not line ends, the server split
    // the lines) go back as blanks, like every value.
    out += one_line(std::string(long_name));
    out += ':';
    for (const auto& a : r.args) {
      out += ' ';
      out += one_line(a);
    }
    out += sep;
    if (o.error == Error::none) {
      for (const auto& [k, v] : o.values) {
        if (!k.empty()) {
          out += k;
          out += ": ";
        }
        out += v;
        out += sep;
      }
    }
    out += rprt(o.error);
    out += '\n';
    return out;
  }
  if (o.error != Error::none) return rprt(o.error) + "\n";
  for (const auto& kv : o.values) {
    out += kv.second;
    out += '\n';
  }
  if (!get) out += rprt(Error::none) + "\n";
  return out;
}

Reply LineProtocol::handle(std::string_view line) {
  if (line.size() > kMaxLineLength) return overlong();
  const std::optional<Request> req = parse_request(line);
  if (!req) return {};
  // q / Q: Hamlib's NET rig client reads "RPRT 0" back before it closes; the rotator client
  // does not wait for it.
  if (!req->long_name && (req->name == "q" || req->name == "Q")) {
    return {format_reply(*req, "quit", false, Outcome{}), true};
  }
  if (req->long_name && req->name == "quit") {
    return {format_reply(*req, req->name, false, Outcome{}), true};
  }
  for (const Command& c : commands()) {
    const bool match = req->long_name ? (req->name == c.long_name)
                                      : (c.short_name != 0 && req->name[0] == c.short_name);
    if (match) return {format_reply(*req, c.long_name, c.get, execute(c.id, req->args)), false};
  }
  return {format_reply(*req, req->name, false, Outcome::fail(Error::not_available)), false};
}

std::string LineProtocol::refusal(Refusal) const { return rprt(Error::rejected) + "\n"; }

LineHandler::Gate LineProtocol::gate(std::string_view line) const {
  const std::optional<Request> req = parse_request(line);
  if (!req) return {Gate::Kind::allowed, {}};  // a blank line or a comment: nothing happens
  // Any case: "\PASSWORD x" is a secret too, and must never reach handle() and the debug log.
  if (req->long_name && text::iequals(req->name, "password")) return {Gate::Kind::password, req->args.empty() ? "" : req->args[0]};
  const bool quit = req->long_name ? req->name == "quit" : (req->name == "q" || req->name == "Q");
  const bool handshake = req->long_name && (req->name == "chk_vfo" || req->name == "dump_state");
  return {quit || handshake ? Gate::Kind::allowed : Gate::Kind::refused, {}};
}

std::string LineProtocol::auth_reply(bool ok) const { return rprt(ok ? Error::none : Error::invalid) + "\n"; }

std::string LineProtocol::auth_required() const { return rprt(Error::security) + "\n"; }

Reply LineProtocol::overlong() const { return {rprt(Error::protocol) + "\n", false}; }

std::string fixed2(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}

std::string one_line(std::string s) {
  for (char& c : s)
    if (std::iscntrl(static_cast<unsigned char>(c))) c = ' ';
  return s;
}

}  // namespace tb::netctl
