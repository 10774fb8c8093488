// The station's socket (attach, status, events): its file name in a state directory and the system
// service's path, in one place for the server, the clients and the options' help.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace tb::app {

inline constexpr std::string_view kSocketFile = "trakbox.sock";                 // in STATE_DIR
inline constexpr std::string_view kServiceSocket = "/run/trakbox/trakbox.sock";  // the system service's
// The longest first line the socket reads: a `trakbox log import` carries its whole file in it
// (16 MiB: some 30000 QSOs as trakbox writes them). The client refuses a longer one itself.
inline constexpr std::size_t kMaxRequestBytes = std::size_t{16} << 20;

// STATE_DIR/trakbox.sock.
std::string socket_for_state(const std::string& state_dir);
// The one `trakbox attach`, `status` and `events` use when neither --socket nor --state says: the
// default state directory's when it exists, else the system service's.
std::string default_client_socket();

}  // namespace tb::app
