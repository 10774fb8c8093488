// The web page's address (--http-port), once the server listens: the status line ends with it and
// menu 6-0 shows it, so that the URL the start message printed is not lost behind the full-screen
// menus. One station per process: a process-wide value, empty without a web server.
#pragma once
#include <string>

namespace tb::tracker {

inline std::string& web_page_url() {
  static std::string url;
  return url;
}

}  // namespace tb::tracker
