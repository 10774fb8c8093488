#include "netctl/pst_server.h"

#include <spdlog/spdlog.h>

#include <boost/asio/ip/address.hpp>

#include "rotator/adc_model.h"
#include "rotator/pst/codec.h"
#include "tracker/operations.h"

namespace tb::netctl {

namespace asio = boost::asio;
using asio::ip::udp;
namespace pst = rotator::pst;

PstServer::PstServer(asio::io_context& io, std::uint16_t port, tracker::StationLoop& station, PstOptions options)
    : handler_(station, std::move(options)), socket_(io) {
  const udp::endpoint at(asio::ip::make_address(handler_.options().address), port);
  socket_.open(at.protocol());
  socket_.bind(at);
  port_ = socket_.local_endpoint().port();
  spdlog::info("pstrotator: listening on UDP {}:{}", handler_.options().address, port_);
  receive();
}

PstServer::~PstServer() {
  boost::system::error_code ignored;
  socket_.close(ignored);
}

void PstServer::receive() {
  socket_.async_receive_from(asio::buffer(buf_), sender_, [this](boost::system::error_code ec, std::size_t n) {
    if (ec == asio::error::operation_aborted) return;
    if (!ec) {
      const std::string from = sender_.address().to_string();
      // Replies go to the sender's address on this server's next port, as PstRotator's (12000 -> 12001).
      const udp::endpoint back(sender_.address(), static_cast<std::uint16_t>(port_ + 1));
      try {
        for (const std::string& reply : handler_.handle(std::string_view(buf_.data(), n), from)) {
          boost::system::error_code send_ec;
          socket_.send_to(asio::buffer(reply), back, 0, send_ec);
        }
      } catch (const std::exception& e) {   // nothing from outside gets past here
        handler_.refuse(from, e.what());
      }
    }
    receive();
  });
}

void PstHandler::refuse(const std::string& from, const std::string& why) {
  const auto now = std::chrono::steady_clock::now();
  if (now - said_at_ < std::chrono::seconds(1)) return;   // counted always, said at most once a second
  said_at_ = now;
  spdlog::warn("pstrotator: a datagram from {} refused: {}", from, why);
}

std::vector<std::string> PstHandler::handle(std::string_view datagram, const std::string& from) {
  if (!inet::allowed(options_.allow, from)) {
    ++stats_.refused_not_allowed;
    refuse(from, "not in --allow");
    return {};
  }
  const pst::Datagram d = pst::parse_command(datagram);
  if (!d.error.empty()) {
    ++stats_.refused_bad;
    refuse(from, d.error);
    return {};
  }
  std::vector<std::string> replies;
  const auto& status = station_.rotator().status();
  // An outside client of the antenna (tracker/control.h): it holds as "pstrotator ADDRESS:PORT", each
  // datagram counts as heard; UDP has no disconnect, so silence (--handback) hands the antenna back.
  const std::string label = "pstrotator " + from;
  station_.control().heard(label, station_.now());
  tracker::StationOps ops(station_, {tracker::HolderKind::pstrotator, label});
  bool aim = false;
  for (const pst::Command& c : d.commands) {
    switch (c.kind) {
      case pst::Command::Kind::azimuth: az_ = rotator::wrap360(c.value), aim = true; break;
      case pst::Command::Kind::elevation: el_ = c.value, aim = true; break;
      case pst::Command::Kind::stop: ops.stop(); break;
      case pst::Command::Kind::park:
        if (!ops.park().ok()) ++stats_.refused_by_station;
        break;
      case pst::Command::Kind::ask_azimuth:
        if (status.has_position) replies.push_back(pst::azimuth_reply(status.az.deg));
        break;
      case pst::Command::Kind::ask_elevation:
        if (status.has_position) replies.push_back(pst::elevation_reply(status.el.deg));
        break;
    }
  }
  ++stats_.taken;
  if (!aim) return replies;
  // As rotctld's set_pos: StationOps::go_to, the one place this server moves the antenna; it asks
  // the controller of record first and switches rotor control on only when the move is granted
  // (refused in standby, nothing is switched or stored).
  const double az = az_.value_or(status.has_position ? status.az.deg : 0.0);
  const double el = el_.value_or(status.has_position ? status.el.deg : 0.0);
  if (const tracker::OpResult r = ops.go_to(az, el); !r.ok()) {
    ++stats_.refused_by_station;
    refuse(from, *r.refusal);
  }
  return replies;
}

}  // namespace tb::netctl
