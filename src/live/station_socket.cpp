#include "live/station_socket.h"

#include <filesystem>

#include "store/state_file.h"

namespace tb::app {

std::string socket_for_state(const std::string& state_dir) { return state_dir + "/" + std::string(kSocketFile); }

std::string default_client_socket() {
  const std::string own = socket_for_state(store::default_state_directory().string());
  std::error_code ec;
  if (std::filesystem::exists(own, ec)) return own;
  return std::string(kServiceSocket);
}

}  // namespace tb::app
