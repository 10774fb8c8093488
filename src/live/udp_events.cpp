#include "live/udp_events.h"

#include <stdexcept>

#include <boost/asio/ip/udp.hpp>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>


namespace tb::app {

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
