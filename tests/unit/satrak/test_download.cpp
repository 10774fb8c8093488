// Element downloads (SATELLITE_HTTP / SATELLITE_FTP) against real servers on loopback: Python's
// http.server and pyftpdlib (Debian python3-pyftpdlib), started here and ended by their pid.
#include <boost/asio/io_context.hpp>
#include <thread>

#include "fixture.h"
#include "net.h"
#include "download/download.h"

using namespace satrak_test;
using namespace std::chrono_literals;

namespace {

constexpr const char* kPython = "/usr/bin/python3";

const char* kHttpServer = R"(
import functools, http.server, sys
class Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args): pass
s = http.server.ThreadingHTTPServer(('127.0.0.1', 0), functools.partial(Quiet, directory=sys.argv[1]))
print(s.server_address[1], flush=True)
s.serve_forever()
)";

download::DownloadRequest get(std::string url) {
  download::DownloadRequest r;
  r.url = std::move(url);
  return r;
}

const char* kFtpServer = R"(
import logging, sys
logging.disable(logging.CRITICAL)
from pyftpdlib.authorizers import DummyAuthorizer
from pyftpdlib.handlers import FTPHandler
from pyftpdlib.servers import FTPServer
a = DummyAuthorizer()
a.add_user(sys.argv[2], sys.argv[3], sys.argv[1], perm='elr')
FTPHandler.authorizer = a
s = FTPServer(('127.0.0.1', 0), FTPHandler)
print(s.address[1], flush=True)
s.serve_forever()
)";

// The ISS set with a recognisable element set number.
std::string iss_file(int set_number, const std::string& name = "ISS") {
  orbit::Elements e = iss_elements();
  e.element_set_number = set_number;
  e.name = name;
  return orbit::format_nasa(e);
}

// Runs the unit's io_context (where download results arrive) until cond holds; bounded.
template <typename F>
bool pump_until(Acu& acu, F cond, std::chrono::milliseconds within = 15s) {
  const auto deadline = std::chrono::steady_clock::now() + within;
  while (std::chrono::steady_clock::now() < deadline) {
    acu.io.restart();
    acu.io.poll();
    if (cond()) return true;
    std::this_thread::sleep_for(10ms);
  }
  return false;
}

int set_number(const Acu& acu) { return acu.unit->elements() ? acu.unit->elements()->element_set_number : -1; }

}  // namespace

TEST_CASE("download(): HTTP body, HTTP 404, a refused connection, a size bound, an abort") {
  TempDir www;
  write_file(www.path / "iss.tle", iss_file(777));
  Child http({kPython, "-c", kHttpServer, www.path.string()});
  REQUIRE(http.port() != 0);
  const std::string base = "http://127.0.0.1:" + std::to_string(http.port());
  auto r = download::download(get(base + "/iss.tle"));
  CHECK(r.ok);
  CHECK(r.body == iss_file(777));
  r = download::download(get(base + "/missing.tle"));
  CHECK_FALSE(r.ok);
  CHECK(r.error.find("404") != std::string::npos);
  r = download::download(get("http://127.0.0.1:" + std::to_string(unused_port()) + "/x"));
  CHECK_FALSE(r.ok);
  download::DownloadRequest small = get(base + "/iss.tle");
  small.max_bytes = 50;
  r = download::download(small);
  CHECK_FALSE(r.ok);
  CHECK(r.error.find("larger than 50 bytes") != std::string::npos);
  r = download::download(get("file:///etc/passwd"));
  CHECK_FALSE(r.ok);  // only http(s), ftp(s) and sftp

  // A server that accepts and never answers: the destructor aborts the transfer at once.
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  REQUIRE(::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0);
  REQUIRE(::listen(fd, 4) == 0);
  socklen_t len = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  std::atomic<bool> called{false};
  const auto t0 = std::chrono::steady_clock::now();
  {
    download::Downloader d;
    d.submit(get("http://127.0.0.1:" + std::to_string(ntohs(a.sin_port)) + "/slow"), [&](download::DownloadResult) { called = true; });
    std::this_thread::sleep_for(300ms);
    CHECK(d.busy() == 1);
  }
  CHECK(std::chrono::steady_clock::now() - t0 < 3s);
  CHECK_FALSE(called);
  ::close(fd);
}

// A server that answers a POST with what it received: the status is the path's number (/201,
// /401), /moved redirects; the body names the method, Content-Type, Expect and the body.
const char* kPostServer = R"(
import http.server, json
class Echo(http.server.BaseHTTPRequestHandler):
    def log_message(self, *args): pass
    def do_POST(self):
        body = self.rfile.read(int(self.headers.get('Content-Length', '0'))).decode()
        if self.path == '/moved':
            self.send_response(302); self.send_header('Location', '/201'); self.send_header('Content-Length', '0')
            self.end_headers(); return
        out = json.dumps({'method': self.command, 'type': self.headers.get('Content-Type'),
                          'expect': self.headers.get('Expect'), 'body': body}).encode()
        self.send_response(int(self.path[1:])); self.send_header('Content-Length', str(len(out))); self.end_headers()
        self.wfile.write(out)
s = http.server.ThreadingHTTPServer(('127.0.0.1', 0), Echo)
print(s.server_address[1], flush=True)
s.serve_forever()
)";

TEST_CASE("download(): a POST of JSON, its error answers read, no redirect followed, the body in no error") {
  Child http({kPython, "-c", kPostServer});
  REQUIRE(http.port() != 0);
  const std::string base = "http://127.0.0.1:" + std::to_string(http.port());
  download::DownloadRequest r = get(base + "/201");
  r.method = "POST";
  r.body = R"({"key":"s3cret-KEY"})";
  r.content_type = "application/json";
  r.http_errors_fail = false;
  auto got = download::download(r);
  REQUIRE_MESSAGE(got.ok, got.error);
  CHECK(got.status == 201);
  CHECK(got.body == R"({"method": "POST", "type": "application/json", "expect": null, "body": "{\"key\":\"s3cret-KEY\"}"})");
  r.url = base + "/401";
  got = download::download(r);
  CHECK(got.ok);  // an API's refusal is an answer to read
  CHECK(got.status == 401);
  CHECK(got.body.find("s3cret-KEY") != std::string::npos);
  r.url = base + "/moved";
  got = download::download(r);
  CHECK(got.ok);
  CHECK(got.status == 302);  // not followed: libcurl would have sent a GET without the body
  r.http_errors_fail = true;
  r.url = base + "/500";
  got = download::download(r);
  CHECK_FALSE(got.ok);
  CHECK(got.error.find("500") != std::string::npos);
  CHECK(got.error.find("s3cret") == std::string::npos);
  r.url = "http://127.0.0.1:" + std::to_string(unused_port()) + "/x";
  got = download::download(r);
  CHECK_FALSE(got.ok);
  CHECK(got.error.find("s3cret") == std::string::npos);
  r.url = "ftp://127.0.0.1:" + std::to_string(unused_port()) + "/x";
  got = download::download(r);
  CHECK_FALSE(got.ok);  // a POST is HTTP(S) only
  r.method = "PUT";
  CHECK(download::download(r).error == r.url + ": method 'PUT' is not GET or POST");
}

TEST_CASE("SATELLITE_HTTP: elements from the web, periodic updates, and both update error actions") {
  TempDir www;
  write_file(www.path / "iss.tle", iss_file(777));
  Child http({kPython, "-c", kHttpServer, www.path.string()});
  REQUIRE(http.port() != 0);
  const std::string base = "http://127.0.0.1:" + std::to_string(http.port());
  const orbit::Pass pass = iss_pass(tucson_model(), kT0, 30.0, 70.0);
  Acu acu(orbit::add_minutes(pass.aos, 1.0));

  // The HTTP settings name no file or satellite: those of SATELLITE= are used (a unit that has had
  // no SATELLITE= uses the station's database: test_conformance.cpp).
  REQUIRE(acu.cmd("SATELLITE=,amateur.txt,ISS,1,1") == "SATELLITE=,OK");
  const int shipped = set_number(acu);
  REQUIRE(acu.cmd("TRACK=,1") == "TRACK=,OK");

  CHECK(acu.cmd("SATELLITE_HTTP=, " + base + "/iss.tle,1,1,1") == "SATELLITE_HTTP=,OK");
  CHECK(acu.cmd("SATELLITE_HTTP?") == "SATELLITE_HTTP?," + base + "/iss.tle,1,1");
  CHECK(acu.fields("SETTINGS?")[10] == "1");  // X11: read from the web
  REQUIRE(pump_until(acu, [&] { return set_number(acu) == 777; }));
  CHECK(read_file(acu.dir.path / "tle" / "amateur.txt") == iss_file(777));  // saved as the SATELLITE= file
  CHECK(acu.errstatus(5) == "0");
  CHECK(acu.status(8) == "1");
  CHECK(acu.cmd("SATELLITE?").find("SATELLITE?,amateur.txt,ISS,1,25544,") == 0);

  SUBCASE("the next download after the update period") {
    CHECK(acu.cmd("SATELLITE_HTTP=," + base + "/iss.tle,0.001,1,1") == "SATELLITE_HTTP=,OK");  // 86.4 s
    REQUIRE(pump_until(acu, [&] { return !acu.unit->downloading(); }));
    CHECK(set_number(acu) == 777);
    write_file(www.path / "iss.tle", iss_file(778));
    acu.run(60s, 1000ms);
    CHECK_FALSE(acu.unit->downloading());  // not yet
    acu.run(30s, 1000ms);
    CHECK(acu.unit->downloading());
    CHECK(pump_until(acu, [&] { return set_number(acu) == 778; }));
  }
  SUBCASE("a failed download, continue from last data: flagged, tracking goes on with the last set") {
    CHECK(acu.cmd("SATELLITE_HTTP=," + base + "/missing.tle,1,1,1") == "SATELLITE_HTTP=,OK");
    REQUIRE(pump_until(acu, [&] { return acu.errstatus(5) == "1"; }));
    CHECK(acu.status(1) == "1");
    CHECK(acu.status(8) == "1");
    CHECK(set_number(acu) == 777);
    acu.run(2s);
    CHECK(acu.unit->tracking_target().has_value());
    // The next attempt (after retry_after = 60 s) succeeds: the flag clears.
    write_file(www.path / "missing.tle", iss_file(779));
    acu.run(61s, 1000ms);
    CHECK(pump_until(acu, [&] { return set_number(acu) == 779 && acu.errstatus(5) == "0"; }));
  }
  SUBCASE("a failed download, stop tracking: tracking stops and says why") {
    CHECK(acu.cmd("SATELLITE_HTTP=," + base + "/missing.tle,1,0,1") == "SATELLITE_HTTP=,OK");
    REQUIRE(pump_until(acu, [&] { return acu.errstatus(5) == "1"; }));
    CHECK(acu.status(8) == "0");
    CHECK(acu.errstatus(6) == "1");
  }
  SUBCASE("a file without the satellite is not used and not saved") {
    write_file(www.path / "other.tle", iss_file(5, "OTHER"));
    CHECK(acu.cmd("SATELLITE_HTTP=," + base + "/other.tle,1,1,1") == "SATELLITE_HTTP=,OK");
    REQUIRE(pump_until(acu, [&] { return acu.errstatus(4) == "1"; }));
    CHECK(read_file(acu.dir.path / "tle" / "amateur.txt") == iss_file(777));
    CHECK(set_number(acu) == 777);
    CHECK(acu.status(8) == "1");
  }
  SUBCASE("a server that is not there") {
    CHECK(acu.cmd("SATELLITE_HTTP=,http://127.0.0.1:" + std::to_string(unused_port()) + "/x,1,1,1") == "SATELLITE_HTTP=,OK");
    REQUIRE(pump_until(acu, [&] { return acu.errstatus(5) == "1"; }));
    CHECK(set_number(acu) == 777);
  }
  SUBCASE("back to the file") {
    CHECK(acu.cmd("SETTINGS=,?,?,?,?,?,?,?,?,?,?,0,?") == "SETTINGS=,OK");
    CHECK(acu.fields("SETTINGS?")[10] == "0");
    CHECK(set_number(acu) == 777);  // the downloaded file is the file now
  }
  (void)shipped;
}

TEST_CASE("SATELLITE_FTP: elements over FTP with a user and password") {
  TempDir ftpdir;
  write_file(ftpdir.path / "sats.txt", iss_file(1, "AO-07") + iss_file(888));
  Child ftp({kPython, "-c", kFtpServer, ftpdir.path.string(), "tracker", "s3cret"});
  REQUIRE(ftp.port() != 0);
  const std::string port = std::to_string(ftp.port());
  Acu acu(kT0);
  CHECK(acu.cmd("SATELLITE_FTP?") == "SATELLITE_FTP?,,,,21,,,1,1");
  // (The seed's six-field example form on a unit with no satellite: test_conformance.cpp.)
  CHECK(acu.cmd("SATELLITE_FTP=,127.0.0.1,tracker,s3cret," + port + ",sats.txt,ISS,1,1") == "SATELLITE_FTP=,OK");
  REQUIRE(pump_until(acu, [&] { return set_number(acu) == 888; }));
  CHECK(acu.cmd("SATELLITE_FTP?") == "SATELLITE_FTP?,127.0.0.1,tracker,?," + port + ",sats.txt,ISS,1,1");
  CHECK(acu.fields("SETTINGS?")[10] == "2");
  CHECK(acu.cmd("SATELLITE?").find("SATELLITE?,sats.txt,ISS,1,25544,") == 0);
  CHECK(fs::exists(acu.dir.path / "tle" / "sats.txt"));
  CHECK(acu.unit->settings().ftp.password == "s3cret");
  CHECK(acu.errstatus(5) == "0");

  SUBCASE("the masked password sent back keeps the stored one (six-field form)") {
    write_file(ftpdir.path / "sats.txt", iss_file(889));
    CHECK(acu.cmd("SATELLITE_FTP=,127.0.0.1,tracker,***," + port + ",1,1") == "SATELLITE_FTP=,OK");
    CHECK(pump_until(acu, [&] { return set_number(acu) == 889; }));
  }
  SUBCASE("a wrong password: the download fails, the last data stays") {
    CHECK(acu.cmd("SATELLITE_FTP=,127.0.0.1,tracker,wrong," + port + ",sats.txt,ISS,1,1") == "SATELLITE_FTP=,OK");
    REQUIRE(pump_until(acu, [&] { return acu.errstatus(5) == "1"; }));
    CHECK(set_number(acu) == 888);
  }
}
