#include "rotator/satrak/client.h"

#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "rotator/satrak/commands.h"
#include "util/host_port.h"

namespace tb::satrak {

using Steady = std::chrono::steady_clock;

namespace {

int ms_left(Steady::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Steady::now()).count();
  return static_cast<int>(std::clamp<long long>(left, 0, 1 << 30));
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Client

Client::~Client() { close(); }

void Client::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  decoder_ = Decoder();
  pending_.clear();
}

bool Client::connect(const std::string& host, unsigned short port, std::chrono::milliseconds timeout) {
  close();
  const auto deadline = Steady::now() + timeout;
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* res = nullptr;
  const std::string service = std::to_string(port);
  if (const int rc = ::getaddrinfo(host.c_str(), service.c_str(), &hints, &res); rc != 0) {
    error_ = host + ": " + ::gai_strerror(rc);
    return false;
  }
  error_ = host + ":" + service + ": no address";
  for (addrinfo* a = res; a; a = a->ai_next) {
    const int fd = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC | SOCK_NONBLOCK, a->ai_protocol);
    if (fd < 0) continue;
    int rc = ::connect(fd, a->ai_addr, a->ai_addrlen);
    if (rc != 0 && errno == EINPROGRESS) {
      pollfd p{fd, POLLOUT, 0};
      rc = ::poll(&p, 1, ms_left(deadline));
      if (rc == 1) {
        int so = 0;
        socklen_t len = sizeof so;
        ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &so, &len);
        rc = so == 0 ? 0 : -1;
        errno = so;
      } else {
        if (rc == 0) errno = ETIMEDOUT;
        rc = -1;
      }
    }
    if (rc == 0) {
      int one = 1;
      ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
      fd_ = fd;
      error_.clear();
      break;
    }
    error_ = host + ":" + service + ": " + std::strerror(errno);
    ::close(fd);
    if (Steady::now() >= deadline) break;
  }
  ::freeaddrinfo(res);
  return fd_ >= 0;
}

bool Client::send_all(std::string_view bytes, Steady::time_point deadline) {
  while (!bytes.empty()) {
    const ssize_t n = ::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL);
    if (n > 0) {
      bytes.remove_prefix(static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      pollfd p{fd_, POLLOUT, 0};
      if (::poll(&p, 1, ms_left(deadline)) == 1) continue;
      error_ = "timed out sending";
      return false;
    }
    error_ = std::string("send: ") + std::strerror(errno);
    return false;
  }
  return true;
}

std::optional<std::string> Client::request(std::string_view payload, std::chrono::milliseconds timeout) {
  if (fd_ < 0) {
    error_ = "not connected";
    return std::nullopt;
  }
  const auto deadline = Steady::now() + timeout;
  const auto cmd = parse_payload(payload);
  const std::string want = cmd ? cmd->head() : std::string();
  if (!send_all(encode(payload), deadline)) {
    close();
    return std::nullopt;
  }
  char buf[2048];
  for (;;) {
    // Anything already decoded first (an earlier request's late reply is skipped).
    while (!pending_.empty()) {
      Decoded d = std::move(pending_.front());
      pending_.erase(pending_.begin());
      if (d.kind != Decoded::Kind::frame) continue;
      if (want.empty()) return d.payload;
      const auto r = parse_payload(d.payload);
      if (r && r->head() == want) return d.payload;
      // A reply to an unparseable word comes back without its kind ("FOO,ERR,4"): take it too.
      if (!r && cmd && d.payload.rfind(cmd->word + ",", 0) == 0) return d.payload;
    }
    pollfd p{fd_, POLLIN, 0};
    const int rc = ::poll(&p, 1, ms_left(deadline));
    if (rc == 0) {
      error_ = "no reply within " + std::to_string(timeout.count()) + " ms";
      close();  // a late reply would be taken for the next request's otherwise
      return std::nullopt;
    }
    if (rc < 0) {
      if (errno == EINTR) continue;
      error_ = std::string("poll: ") + std::strerror(errno);
      close();
      return std::nullopt;
    }
    const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
    if (n == 0) {
      error_ = "connection closed by the ACU";
      close();
      return std::nullopt;
    }
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN || errno == EWOULDBLOCK) continue;
      error_ = std::string("recv: ") + std::strerror(errno);
      close();
      return std::nullopt;
    }
    decoder_.feed(std::string_view(buf, static_cast<std::size_t>(n)), pending_);
  }
}

// ---------------------------------------------------------------------------------------------
// The command line

std::string cli_usage() {
  return "usage: trakbox satrak HOST[:PORT] [--timeout SECONDS] COMMAND...\n"
         "  sends each COMMAND to a Satrak ACU (port 4001 by default) and prints each reply, e.g.\n"
         "  trakbox satrak localhost STATUS? 'GOTO=,125.1,32.6' TPOS?\n";
}

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::vector<std::string> commands;
  std::optional<std::string> target;
  std::chrono::milliseconds timeout{5000};
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      out << cli_usage();
      return 0;
    }
    if (a == "--timeout") {
      const auto v = i + 1 < args.size() ? parse_number(args[i + 1]) : std::nullopt;
      if (!v || *v <= 0 || *v > 3600) {
        err << "trakbox satrak: --timeout: expected seconds, 0 < S <= 3600\n" << cli_usage();
        return 2;
      }
      timeout = std::chrono::milliseconds(static_cast<long long>(std::llround(*v * 1000.0)));
      ++i;
      continue;
    }
    if (!target) target = a;
    else commands.push_back(a);
  }
  if (!target || commands.empty()) {
    err << "trakbox satrak: " << (!target ? "missing HOST[:PORT]" : "missing COMMAND") << "\n" << cli_usage();
    return 2;
  }
  std::string e;
  const auto hp = inet::parse_host_port(*target, e, kDefaultPort);
  if (!hp) {
    err << "trakbox satrak: '" << *target << "': " << e << "\n";
    return 2;
  }
  // A whole frame given on the command line is taken as its payload.
  for (auto& c : commands) {
    if (c.empty() || c.front() != '$') continue;
    Decoded d;
    if (decode_line(c, d) && d.kind == Decoded::Kind::frame) c = d.payload;
    else {
      err << "trakbox satrak: '" << c << "' is not a valid frame (give the payload alone, e.g. STATUS?)\n";
      return 2;
    }
  }
  Client client;
  if (!client.connect(hp->host, hp->port, timeout)) {
    err << "trakbox satrak: cannot connect: " << client.error() << "\n";
    return 1;
  }
  int code = 0;
  for (const auto& c : commands) {
    const auto reply = client.request(c, timeout);
    if (!reply) {
      err << "trakbox satrak: " << c << ": " << client.error() << "\n";
      return 1;
    }
    out << *reply << "\n";
    const auto r = parse_payload(*reply);
    const bool refused = (r && !r->fields.empty() && r->fields.front() == "ERR") || reply->rfind("ERR,", 0) == 0 ||
                         reply->find(",ERR,") != std::string::npos;
    if (refused) code = 1;
  }
  out.flush();
  return code;
}

// ---------------------------------------------------------------------------------------------
// SatrakRotator

std::optional<SatrakRotatorOptions> parse_rotator_spec(std::string_view text, std::string& error) {
  constexpr std::string_view kPrefix = "satrak:";
  if (text.substr(0, kPrefix.size()) != kPrefix) {
    error = "expected satrak:HOST[:PORT]";
    return std::nullopt;
  }
  std::string e;
  const auto hp = inet::parse_host_port(text.substr(kPrefix.size()), e, kDefaultPort);
  if (!hp) {
    error = "bad --rotator '" + std::string(text) + "': " + e + "; expected satrak:HOST[:PORT], e.g. satrak:192.0.2.7:4001";
    return std::nullopt;
  }
  SatrakRotatorOptions o;
  o.host = hp->host;
  o.port = hp->port;
  return o;
}

namespace {

rotator::Drive drive_of(const std::string& s) {
  if (s == "1") return rotator::Drive::increase;
  if (s == "-1") return rotator::Drive::decrease;
  return rotator::Drive::stop;
}

bool refused(const std::string& reply) { return reply.find(",ERR,") != std::string::npos; }

// One connection to the other ACU, on the worker thread of WorkerRotator.
class SatrakLink final : public rotator::RotatorLink {
 public:
  explicit SatrakLink(SatrakRotatorOptions opt) : opt_(std::move(opt)) {}

  bool open(std::string& error) override {
    if (client_.connect(opt_.host, opt_.port, opt_.io_timeout)) return true;
    error = client_.error();
    return false;
  }
  void close() override { client_.close(); }

  bool stop(std::string& error) override { return request("STOP=", error).has_value(); }

  bool go_to(rotator::AzEl p, std::optional<std::string>& refusal, std::string& error) override {
    const std::string payload = "GOTO=," + format_fixed(rotator::wrap360(p.az), 2) + "," + format_fixed(p.el, 2);
    const auto r = request(payload, error);
    if (!r) return false;
    if (refused(*r)) refusal = "refused " + payload + ": " + *r;
    return true;
  }

  bool poll(rotator::LinkReport& report, std::string& error) override {
    const auto r = request("STATUS?", error);
    if (!r) return false;
    const auto c = parse_payload(*r);
    if (c && c->fields.size() >= 15) {
      const auto& f = c->fields;
      const auto az = parse_number(f[1]), el = parse_number(f[2]);
      if (az && el) report.position = rotator::AzEl{*az, *el};
      report.limits = rotator::LimitFlags{{f[4] == "1", f[3] == "1"}, {f[6] == "1", f[5] == "1"}};
      report.motion = rotator::AxisMotion{drive_of(f[11]), drive_of(f[12])};
    }
    return true;
  }

 private:
  std::optional<std::string> request(std::string_view payload, std::string& error) {
    auto r = client_.request(payload, opt_.io_timeout);
    if (!r) error = client_.error();
    return r;
  }

  const SatrakRotatorOptions opt_;
  Client client_;
};

std::string rotator_label(const SatrakRotatorOptions& o) {
  const bool v6 = o.host.find(':') != std::string::npos;
  return "satrak " + (v6 ? "[" + o.host + "]" : o.host) + ":" + std::to_string(o.port);
}

}  // namespace

SatrakRotator::SatrakRotator(SatrakRotatorOptions options)
    : WorkerRotator(rotator_label(options), std::make_unique<SatrakLink>(options),
                    {options.poll, options.io_timeout, options.backoff_min, options.backoff_max}) {}

}  // namespace tb::satrak
