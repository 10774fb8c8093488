#include "rotator/pst/link.h"

#include <arpa/inet.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <optional>

#include "rotator/pst/codec.h"

namespace tb::rotator {

namespace {

using Clock = std::chrono::steady_clock;

std::string where(const PstRotatorOptions& o) {
  return (o.host.find(':') != std::string::npos ? "[" + o.host + "]" : o.host) + ":" + std::to_string(o.port);
}

class PstLink final : public RotatorLink {
 public:
  explicit PstLink(PstRotatorOptions o) : o_(std::move(o)) {}
  ~PstLink() override { close(); }

  bool open(std::string& error) override {
    close();
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_DGRAM;
    addrinfo* found = nullptr;
    if (const int rc = ::getaddrinfo(o_.host.c_str(), std::to_string(o_.port).c_str(), &hints, &found); rc != 0) {
      error = std::string("cannot resolve ") + o_.host + ": " + gai_strerror(rc);
      return false;
    }
    std::memcpy(&box_, found->ai_addr, found->ai_addrlen);
    box_len_ = found->ai_addrlen;
    const int family = found->ai_family;
    ::freeaddrinfo(found);
    fd_ = ::socket(family, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
    if (fd_ < 0) {
      error = std::string("cannot make a UDP socket: ") + std::strerror(errno);
      return false;
    }
    // The box answers to this computer's port PORT+1.
    sockaddr_storage local{};
    socklen_t len = 0;
    if (family == AF_INET6) {
      auto* a = reinterpret_cast<sockaddr_in6*>(&local);
      a->sin6_family = AF_INET6;
      a->sin6_addr = in6addr_any;
      a->sin6_port = htons(static_cast<std::uint16_t>(o_.port + 1));
      len = sizeof *a;
    } else {
      auto* a = reinterpret_cast<sockaddr_in*>(&local);
      a->sin_family = AF_INET;
      a->sin_addr.s_addr = htonl(INADDR_ANY);
      a->sin_port = htons(static_cast<std::uint16_t>(o_.port + 1));
      len = sizeof *a;
    }
    if (::bind(fd_, reinterpret_cast<sockaddr*>(&local), len) != 0) {
      error = "cannot take UDP port " + std::to_string(o_.port + 1) + " for its replies: " + std::strerror(errno);
      close();
      return false;
    }
    last_.reset();
    return true;
  }

  void close() override {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

  bool stop(std::string& error) override { return send(pst::stop(), error); }

  bool go_to(AzEl p, std::optional<std::string>&, std::string& error) override {
    return send(pst::set_azimuth(p.az), error) && send(pst::set_elevation(p.el), error);
  }

  bool poll(LinkReport& report, std::string& error) override {
    char drop[512];
    while (::recv(fd_, drop, sizeof drop, 0) > 0) {}   // late answers to the poll before
    if (!send(pst::ask_azimuth(), error) || !send(pst::ask_elevation(), error)) return false;
    std::optional<double> az, el;
    const auto until = Clock::now() + o_.io_timeout;
    while (!(az && el)) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now()).count();
      pollfd p{fd_, POLLIN, 0};
      if (left <= 0 || ::poll(&p, 1, static_cast<int>(left)) <= 0) {
        error = std::string("no ") + (az ? "EL:" : el ? "AZ:" : "AZ: or EL:") + " reply within " +
                std::to_string(o_.io_timeout.count()) + " ms";
        return false;
      }
      char buf[600];
      const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
      if (n <= 0) continue;
      const pst::Reading r = pst::parse_reply(std::string_view(buf, static_cast<std::size_t>(n)));
      if (r.az) az = r.az;
      if (r.el) el = r.el;
    }
    const AzEl now{*az, *el};
    if (last_) {
      auto drive = [](double d) { return d > 0.05 ? Drive::increase : d < -0.05 ? Drive::decrease : Drive::stop; };
      report.motion = AxisMotion{drive(now.az - last_->az), drive(now.el - last_->el)};
    }
    report.position = now;
    last_ = now;
    return true;
  }

  std::string peer() const override { return "the PstRotator box at " + where(o_); }
  std::string silent_hint() const override {
    return "check that it runs, takes UDP on port " + std::to_string(o_.port) + " and answers to port " +
           std::to_string(o_.port + 1);
  }

 private:
  bool send(const std::string& datagram, std::string& error) {
    if (::sendto(fd_, datagram.data(), datagram.size(), 0, reinterpret_cast<const sockaddr*>(&box_), box_len_) < 0) {
      error = std::string("cannot send: ") + std::strerror(errno);
      return false;
    }
    return true;
  }

  const PstRotatorOptions o_;
  int fd_ = -1;
  sockaddr_storage box_{};
  socklen_t box_len_ = 0;
  std::optional<AzEl> last_;
};

}  // namespace

PstRotator::PstRotator(const PstRotatorOptions& o)
    : WorkerRotator("PstRotator " + where(o), std::make_unique<PstLink>(o), {o.poll, o.io_timeout, o.backoff_min, o.backoff_max}) {}

}  // namespace tb::rotator
