#include "app/secret_reload.h"

#include <spdlog/spdlog.h>

#include "util/secret.h"

namespace tb::app {

int reload_secrets(std::vector<SecretEndpoint>& endpoints, spdlog::logger& log) {
  int changed = 0;
  for (SecretEndpoint& e : endpoints) {
    if (e.file.empty()) continue;
    std::string error, warning;
    const auto s = secret::read_file(e.file, error, warning);
    if (!warning.empty()) log.warn("SIGHUP: {}", warning);
    if (!s) {
      log.warn("SIGHUP: {}: {}; the {} secret stays as it was", e.file, error, e.name);
      continue;
    }
    if (*s == e.current) continue;
    e.current = *s;
    e.set(*s);
    ++changed;
    log.info("SIGHUP: the {} secret changed ({} re-read): the clients and sessions of the old one end", e.name, e.file);
  }
  return changed;
}

}  // namespace tb::app
