#include "app/udp_events.h"

#include <stdexcept>

#include <boost/asio/ip/udp.hpp>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "util/text.h"

namespace tb::app {

std::optional<UdpTarget> parse_udp_target(const std::string& text, std::string& error) {
  std::string host, port;
  if (!text.empty() && text.front() == '[') {
    const auto end = text.find("]:");
    if (end == std::string::npos) {
      error = "'" + text + "': expected [IPV6]:PORT";
      return std::nullopt;
    }
    host = text.substr(1, end - 1);
    port = text.substr(end + 2);
  } else {
    const auto colon = text.rfind(':');
    if (colon == std::string::npos || text.find(':') != colon) {
      error = "'" + text + "': expected HOST:PORT, e.g. 192.168.1.20:9000 or [2001:db8::2]:9000";
      return std::nullopt;
    }
    host = text.substr(0, colon);
    port = text.substr(colon + 1);
  }
  const auto p = text::parse_double(port);
  if (host.empty() || !p || *p < 1 || *p > 65535 || *p != static_cast<int>(*p)) {
    error = "'" + text + "': expected HOST:PORT with a port 1 to 65535";
    return std::nullopt;
  }
  return UdpTarget{host, static_cast<std::uint16_t>(*p)};
}

struct UdpEvents::Impl {
  Impl(boost::asio::io_context& io, spdlog::logger& log) : v4(io), v6(io), log(log) {}
  boost::asio::ip::udp::socket v4, v6;
  spdlog::logger& log;
  struct Destination {
    boost::asio::ip::udp::endpoint endpoint;
    std::string name;
    bool failed = false;  // said once
  };
  std::vector<Destination> destinations;
};

UdpEvents::UdpEvents(boost::asio::io_context& io, const std::vector<UdpTarget>& targets, spdlog::logger& log)
    : impl_(std::make_unique<Impl>(io, log)) {
  using boost::asio::ip::udp;
  udp::resolver resolver(io);
  for (const UdpTarget& t : targets) {
    boost::system::error_code ec;
    const auto found = resolver.resolve(t.host, std::to_string(t.port), ec);
    if (ec || found.empty())
      throw std::runtime_error("--udp-events " + t.host + ":" + std::to_string(t.port) + ": cannot resolve: " +
                               ec.message());
    const udp::endpoint e = found.begin()->endpoint();
    udp::socket& s = e.address().is_v6() ? impl_->v6 : impl_->v4;
    if (!s.is_open()) {
      s.open(e.protocol());
      s.non_blocking(true);  // a full send buffer drops the datagram; the station never waits
    }
    impl_->destinations.push_back({e, t.host + ":" + std::to_string(t.port)});
  }
}

UdpEvents::~UdpEvents() = default;

void UdpEvents::send(const nlohmann::json& event) {
  const std::string text = event.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  for (auto& d : impl_->destinations) {
    boost::system::error_code ec;
    (d.endpoint.address().is_v6() ? impl_->v6 : impl_->v4).send_to(boost::asio::buffer(text), d.endpoint, 0, ec);
    if (ec && !d.failed) impl_->log.warn("--udp-events {}: {} (said once)", d.name, ec.message());
    d.failed = d.failed || ec;
  }
}

}  // namespace tb::app
