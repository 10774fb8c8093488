// The bounded request reader (web/http_reader.h), the Host check and the log of refusals (issue 46):
// requests as bytes, fed as a socket would hand them over; every bound refused at its number with the
// bytes held never above the read buffer's cap.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>

#include "web/access.h"
#include "web/http_reader.h"
#include "web/refusals.h"

using namespace tb;
using State = web::RequestReader::State;

namespace {

// Feeds `bytes` as far as the reader lets it, `step` at a time; the state at the end (or when done
// or refused), and the most ever held.
struct Fed {
  State state;
  std::size_t most_held = 0;
  std::size_t taken = 0;
};

Fed feed(web::RequestReader& r, const std::string& bytes, std::size_t step = 1000) {
  Fed f{State::more};
  std::size_t at = 0;
  while (f.state == State::more && at < bytes.size()) {
    const std::size_t n = std::min({step, r.room(), bytes.size() - at});
    REQUIRE(n > 0);
    f.state = r.feed(std::string_view(bytes).substr(at, n));
    at += n;
    f.most_held = std::max(f.most_held, r.held());
  }
  f.taken = at;
  return f;
}

const std::string kHead = "POST /api/v1/rotor HTTP/1.1\r\nHost: 127.0.0.1:8073\r\n";

}  // namespace

TEST_CASE("http reader: a plain GET, a chunked POST and two pipelined requests") {
  web::RequestReader r;
  CHECK(feed(r, "GET /api/v1/status HTTP/1.1\r\nHost: 127.0.0.1:8073\r\nOrigin: http://127.0.0.1:8073\r\n\r\n").state ==
        State::done);
  web::ReadRequest a = r.take();
  CHECK(a.request.method == "GET");
  CHECK(a.request.target == "/api/v1/status");
  CHECK(a.request.host == "127.0.0.1:8073");
  CHECK(a.request.origin == "http://127.0.0.1:8073");
  CHECK(a.keep_alive);
  CHECK(!a.head);
  CHECK(r.idle());

  CHECK(feed(r, kHead + "Transfer-Encoding: chunked\r\nContent-Type: application/json\r\n\r\n"
                        "5;name=value\r\n{\"act\r\n9\r\nion\":1}\r\n\r\n0\r\nX-Trailer: dropped\r\n\r\n",
             7).state == State::done);
  web::ReadRequest b = r.take();
  CHECK(b.request.body == "{\"action\":1}\r\n");
  CHECK(b.request.content_type == "application/json");
  for (const auto& [k, v] : b.fields) CHECK(k != "X-Trailer");  // trailers never reach the headers

  const std::string two = "HEAD / HTTP/1.1\r\nHost: localhost\r\n\r\nGET /app.js HTTP/1.1\r\nHost: localhost\r\n\r\n";
  CHECK(feed(r, two, two.size()).state == State::done);
  CHECK(r.take().head);
  CHECK(r.feed() == State::done);  // the second, from the bytes already held
  CHECK(r.take().request.target == "/app.js");
}

TEST_CASE("http reader: every part bounded at its number, never more than the buffer held") {
  struct Case {
    const char* what;
    std::string bytes;
    int status;
  };
  const Case cases[] = {
      {"request line", "GET /" + std::string(3000, 'a') + " HTTP/1.1\r\n", 414},
      {"one header line", "GET / HTTP/1.1\r\nX-A: " + std::string(5000, 'a') + "\r\n", 431},
      {"all headers", "GET / HTTP/1.1\r\n" + [] {
         std::string s;
         for (int i = 0; i < 40; ++i) s += "X-" + std::to_string(i) + ": " + std::string(300, 'a') + "\r\n";
         return s;
       }(), 431},
      {"header lines", "GET / HTTP/1.1\r\n" + [] {
         std::string s;
         for (int i = 0; i < 70; ++i) s += "X-" + std::to_string(i) + ": a\r\n";
         return s + "\r\n";
       }(), 431},
      {"chunk-size line", kHead + "Transfer-Encoding: chunked\r\n\r\n" + std::string(2000, '0'), 413},
      {"chunk extension", kHead + "Transfer-Encoding: chunked\r\n\r\n1;" + std::string(48 * 1024, 'a'), 413},
      {"trailers", kHead + "Transfer-Encoding: chunked\r\n\r\n0\r\n" + [] {
         std::string s;
         for (int i = 0; i < 100; ++i) s += "X-T" + std::to_string(i) + ": aaaaaaaaaaaaaaaaaaaa\r\n";
         return s;
       }(), 413},
      {"chunked body", kHead + "Transfer-Encoding: chunked\r\n\r\n" + [] {
         std::string s;
         for (int i = 0; i < 20; ++i) s += "400\r\n" + std::string(1024, 'a') + "\r\n";
         return s;
       }(), 413},
      {"Content-Length body", kHead + "Content-Length: 20000\r\n\r\n", 413},
  };
  for (const Case& c : cases) {
    CAPTURE(c.what);
    web::RequestReader r;
    const Fed f = feed(r, c.bytes);
    CHECK(f.state == State::refused);
    CHECK(r.status() == c.status);
    CHECK(!r.why().empty());
    CHECK(f.most_held <= web::ReadLimits{}.buffer);
    CHECK(r.room() == 0);
  }
}

TEST_CASE("http reader: Transfer-Encoding only a final chunked, alone") {
  const std::pair<const char*, int> cases[] = {{"xchunked", 400},         {"chunked, identity", 400},
                                               {"gzip, chunked", 501},    {"identity", 400},
                                               {"chunked, chunked", 501}, {"", 400}};
  for (const auto& [te, status] : cases) {
    CAPTURE(te);
    web::RequestReader r;
    // A GET whose "body" is a POST: never read as the next request.
    const std::string hidden = "POST /api/v1/rotor HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 2\r\n\r\n{}";
    const Fed f = feed(r, "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nTransfer-Encoding: " + std::string(te) +
                              "\r\nContent-Length: 0\r\n\r\n" + hidden);
    // (with Content-Length too, Beast refuses the pair first: 400 either way)
    CHECK(f.state == State::refused);
    web::RequestReader r2;
    const Fed g = feed(r2, "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nTransfer-Encoding: " + std::string(te) + "\r\n\r\n" + hidden);
    CHECK(g.state == State::refused);
    CHECK(r2.status() == status);
  }
  web::RequestReader r;
  CHECK(feed(r, "POST / HTTP/1.0\r\nTransfer-Encoding: chunked\r\n\r\n0\r\n\r\n").state == State::refused);
  web::RequestReader two_hosts;
  CHECK(feed(two_hosts, "GET / HTTP/1.1\r\nHost: a\r\nHost: b\r\n\r\n").state == State::refused);
  CHECK(two_hosts.status() == 400);
}

TEST_CASE("Host: an exact parse; IP literals, localhost and --http-host names, each with a port") {
  const std::vector<std::string> names{"shack.lan"};
  for (const char* ok : {"127.0.0.1", "127.0.0.1:8073", "192.168.1.5:80", "[::1]", "[::1]:8073",
                         "[2001:db8::1]:8073", "localhost", "LOCALHOST:8073", "shack.lan", "Shack.LAN:8080"})
    CHECK_MESSAGE(web::Access::host_allowed(ok, names), ok);
  for (const char* bad : {"127.evil.example", "127.0.0.1.nip.io", "localhost.evil", "evil.localhost", "", ":8073",
                          "127.0.0.1:", "127.0.0.1:99999", "127.0.0.1:80a", "[::1", "[::1]x", "[127.0.0.1]",
                          "::1", "127.1", "shack.lan.evil", "a.shack.lan", "127.0.0.1:80:80", "0x7f.0.0.1"})
    CHECK_MESSAGE(!web::Access::host_allowed(bad, names), bad);
}

TEST_CASE("refusals: one line per address a minute, an IPv6 /64 as one, with the count unsaid") {
  web::RefusalLog log;
  const auto t0 = web::RefusalLog::Clock::time_point(std::chrono::hours(1));
  CHECK(log.note("192.0.2.7", 401, t0) == std::optional<std::uint64_t>(0));
  CHECK(!log.note("192.0.2.7", 401, t0 + std::chrono::seconds(1)));
  CHECK(!log.note("192.0.2.7", 401, t0 + std::chrono::seconds(59)));
  CHECK(log.note("192.0.2.8", 401, t0 + std::chrono::seconds(2)) == std::optional<std::uint64_t>(0));
  CHECK(log.note("192.0.2.7", 401, t0 + std::chrono::seconds(60)) == std::optional<std::uint64_t>(2));
  CHECK(log.note("2001:db8:1::1", 401, t0) == std::optional<std::uint64_t>(0));
  CHECK(!log.note("2001:db8:1::ffff", 401, t0 + std::chrono::seconds(5)));  // the same /64
  CHECK(log.note("2001:db8:1::ffff", 403, t0 + std::chrono::seconds(5)));   // another kind: its own line
  web::RefusalLog small(std::chrono::seconds(60), 2);
  CHECK(small.note("192.0.2.1", 401, t0));
  CHECK(small.note("192.0.2.2", 401, t0));
  CHECK(small.note("192.0.2.3", 401, t0));   // the first of "(others)"
  CHECK(!small.note("192.0.2.4", 401, t0));  // also "(others)": the table does not grow
  CHECK(small.size() == 3);
}

TEST_CASE("http reader: an absolute-form target is its path, its authority the Host (issue 56, item 15)") {
  web::RequestReader r;
  CHECK(feed(r, "GET http://127.0.0.1:8073/api/v1/status?x=1 HTTP/1.1\r\nHost: other.example\r\n\r\n").state == State::done);
  web::ReadRequest a = r.take();
  CHECK(a.request.target == "/api/v1/status?x=1");
  CHECK(a.request.host == "127.0.0.1:8073");  // RFC 9112 3.2.2: the authority, so the Host check sees it
  CHECK(feed(r, "GET HTTP://evil.example HTTP/1.1\r\nHost: 127.0.0.1:8073\r\n\r\n").state == State::done);
  a = r.take();
  CHECK(a.request.target == "/");
  CHECK(a.request.host == "evil.example");
  web::RequestReader user;
  CHECK(feed(user, "GET http://bob@127.0.0.1:8073/ HTTP/1.1\r\nHost: 127.0.0.1:8073\r\n\r\n").state == State::refused);
  CHECK(user.status() == 400);
  web::RequestReader ftp;
  CHECK(feed(ftp, "GET ftp://127.0.0.1:8073/ HTTP/1.1\r\nHost: 127.0.0.1:8073\r\n\r\n").state == State::refused);
  CHECK(ftp.status() == 400);
}

TEST_CASE("http reader: Expect: 100-continue asks for the interim answer once; another expectation is 417") {
  web::RequestReader r;
  const std::string head = kHead + "Content-Type: application/json\r\nContent-Length: 8\r\nExpect: 100-continue\r\n\r\n";
  CHECK(feed(r, head).state == State::more);
  CHECK(r.take_continue());
  CHECK(!r.take_continue());  // once
  CHECK(feed(r, "{\"a\":12}").state == State::done);
  CHECK(r.take().request.body == "{\"a\":12}");
  // The body sent with the header (the client did not wait): nothing to answer before it.
  CHECK(feed(r, head + "{\"a\":12}").state == State::done);
  CHECK(!r.take_continue());
  r.take();
  web::RequestReader odd;
  CHECK(feed(odd, kHead + "Expect: 200-ok\r\nContent-Length: 0\r\n\r\n").state == State::refused);
  CHECK(odd.status() == 417);
  web::RequestReader old;  // HTTP/1.0's expectation is ignored (RFC 9110 10.1.1)
  CHECK(feed(old, "POST /api/v1/rotor HTTP/1.0\r\nExpect: 100-continue\r\nContent-Length: 2\r\n\r\n").state == State::more);
  CHECK(!old.take_continue());
}
