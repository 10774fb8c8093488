// --udp-events HOST:PORT (repeatable): each station event as one JSON datagram (the fields of
// `trakbox events`, tracker::to_json), for a recorder or a logger on another computer. Sent without
// waiting: a datagram that cannot go is logged once per destination, and the station goes on.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "util/host_port.h"
#include "util/loop_fwd.h"

namespace tb::app {

// "HOST:PORT" or "[IPV6]:PORT", read by inet::parse_host_port (util/host_port.h), a port required.
using UdpTarget = inet::HostPort;

class UdpEvents {
 public:
  // Resolves the destinations now; throws std::runtime_error naming one that cannot be resolved.
  UdpEvents(boost::asio::io_context& io, const std::vector<UdpTarget>& targets, spdlog::logger& log);
  ~UdpEvents();
  UdpEvents(const UdpEvents&) = delete;
  UdpEvents& operator=(const UdpEvents&) = delete;
  void send(const nlohmann::json& event);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tb::app
