// SIGHUP re-reads the endpoints' secret files (--rotctld-secret-file, --rigctld-secret-file,
// --host-secret-file, --http-secret-file; issue 46): a changed secret takes effect at once, the
// clients and web sessions of the old one end, and the log says which endpoint's secret changed. A
// file that cannot be read now (gone, empty, too open) keeps the old secret, with a warning.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "util/loop_fwd.h"

namespace tb::app {

struct SecretEndpoint {
  std::string name;                          // "rotctld", "web", ...
  std::string file;                          // "" when the endpoint has no secret
  std::string current;                       // the secret in use
  std::function<void(const std::string&)> set;  // gives the endpoint its new secret
};

// Each endpoint's file read again; `set` called for each whose secret changed. The number changed.
int reload_secrets(std::vector<SecretEndpoint>& endpoints, spdlog::logger& log);

}  // namespace tb::app
