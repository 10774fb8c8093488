// SIGHUP's re-reading of the endpoints' secret files (app/secret_reload.h) and --http-host (issue
// 46): a changed file changes the endpoint's secret and says so; an unreadable one keeps the old.
#include <doctest/doctest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "app/secret_reload.h"
#include "cli/tracker_config.h"

using namespace tb::app;

namespace {
std::string write_secret(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
  ::chmod(path.c_str(), 0600);
  return path;
}
}  // namespace

TEST_CASE("SIGHUP: a changed secret file reaches its endpoint, once, and the log names it") {
  char dir[] = "/tmp/trakbox-secret-XXXXXX";
  REQUIRE(::mkdtemp(dir) != nullptr);
  const std::string web = write_secret(std::string(dir) + "/web", "old-secret\n");
  std::ostringstream out;
  spdlog::logger log("t", std::make_shared<spdlog::sinks::ostream_sink_mt>(out));
  std::vector<std::string> given;
  std::vector<SecretEndpoint> e{{"web", web, "old-secret", [&](const std::string& s) { given.push_back(s); }},
                                {"rotctld", "", "", [&](const std::string& s) { given.push_back("rotctld " + s); }}};
  CHECK(reload_secrets(e, log) == 0);  // unchanged: nothing happens
  CHECK(given.empty());
  write_secret(web, "new-secret\n");
  CHECK(reload_secrets(e, log) == 1);
  CHECK(given == std::vector<std::string>{"new-secret"});
  CHECK(e[0].current == "new-secret");
  CHECK(out.str().find("SIGHUP: the web secret changed (" + web + " re-read)") != std::string::npos);
  ::unlink(web.c_str());
  CHECK(reload_secrets(e, log) == 0);  // gone: the secret stays
  CHECK(e[0].current == "new-secret");
  CHECK(out.str().find("the web secret stays as it was") != std::string::npos);
  ::rmdir(dir);
}

TEST_CASE("--http-host: names only, repeatable, with the web server on") {
  const auto ok = parse_tracker_config({"--http-port", "8073", "--http-host", "shack.lan", "--http-host", "trakbox"},
                                       FrontEnd::menus);
  REQUIRE(ok.config);
  CHECK(ok.config->http_hosts == std::vector<std::string>{"shack.lan", "trakbox"});
  CHECK(parse_tracker_config({"--http-port", "8073", "--http-host", "shack.lan:80"}, FrontEnd::menus).error.value_or("") ==
        "--http-host: expected a host name of letters, digits, '-' and '.' (no port); found 'shack.lan:80'");
  CHECK(parse_tracker_config({"--http-host", "shack.lan"}, FrontEnd::menus).error.value_or("") ==
        "--http-host: the web server is off (give --http-port)");
}
