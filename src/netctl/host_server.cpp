#include "netctl/host_server.h"

#include "host/host_mode.h"
#include "util/text.h"

namespace tb::netctl {

namespace {
constexpr std::string_view kEol = "\r\n";

std::string lines_then_prompt(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) {
    out += one_line(l);
    out += kEol;
  }
  out += host::kPrompt;
  return out;
}
}  // namespace

struct HostProtocol::Impl {
  explicit Impl(tracker::StationLoop& s) : interpreter(s) {}
  host::Interpreter interpreter;
};

HostProtocol::HostProtocol(tracker::StationLoop& station) : impl_(std::make_unique<Impl>(station)) {}
HostProtocol::~HostProtocol() = default;

std::string HostProtocol::greeting() const { return lines_then_prompt(host::Interpreter::greeting()); }

Reply HostProtocol::handle(std::string_view line) {
  // No echo: a TCP client shows what it typed itself (telnet, nc), with its own line end.
  const host::Reply r = impl_->interpreter.execute(line);
  if (r.quit) return {"", true};
  return {lines_then_prompt(r.lines), false};
}

std::string HostProtocol::refusal(Refusal why) const {
  switch (why) {
    case Refusal::not_allowed: return "ERROR not allowed: this address is not in the station's --allow list\r\n";
    case Refusal::locked_out: return "ERROR locked out: too many wrong secrets from this address; try again later\r\n";
    case Refusal::busy: break;
  }
  return "ERROR busy: every host-mode connection is taken and in use; try again later\r\n";
}

LineHandler::Gate HostProtocol::gate(std::string_view line) const {
  const std::string_view t = text::trim(line, text::kWhitespace);
  if (t.size() >= 4 && text::iequals(t.substr(0, 4), "PASS") && (t.size() == 4 || t[4] == ' ' || t[4] == '\t'))
    return {Gate::Kind::password, std::string(text::trim(t.substr(4), text::kWhitespace))};
  if (text::iequals(t, "Q")) return {Gate::Kind::allowed, {}};
  return {};
}

std::string HostProtocol::auth_reply(bool ok) const {
  return lines_then_prompt({ok ? "OK authenticated" : "ERROR wrong secret"});
}

std::string HostProtocol::auth_required() const {
  return lines_then_prompt({"ERROR this port wants its secret first: PASS <secret>"});
}

Reply HostProtocol::overlong() const {
  return {lines_then_prompt({"ERROR line too long: at most " + std::to_string(kMaxHostLine) + " characters"}), false};
}

ServerOptions HostServer::defaults() {
  ServerOptions o;
  o.name = "host";
  o.max_line = kMaxHostLine;
  o.cr_ends_line = true;
  return o;
}

HostServer::HostServer(boost::asio::io_context& io, std::uint16_t port, tracker::StationLoop& station,
                       ServerOptions options)
    : protocol_(station), server_(io, port, protocol_, std::move(options)) {}

}  // namespace tb::netctl
