// The Satrak client side: a blocking client (for `trakbox satrak HOST[:PORT] COMMAND...` and for
// the rotator driver's worker thread), and SatrakRotator, a rotator driver that makes another
// Satrak ACU (or another trakbox) trakbox's rotator: `--rotator satrak:HOST[:PORT]`.
#pragma once
#include <chrono>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "rotator/worker.h"
#include "rotator/satrak/frame.h"

namespace tb::satrak {

inline constexpr unsigned short kDefaultPort = 4001;

// HOST[:PORT] of `trakbox satrak` and satrak:HOST[:PORT] are read by inet::parse_host_port
// (util/host_port.h) with this default port.

// A blocking client. Every call returns within its timeout.
class Client {
 public:
  Client() = default;
  ~Client();
  Client(const Client&) = delete;
  Client& operator=(const Client&) = delete;

  bool connect(const std::string& host, unsigned short port, std::chrono::milliseconds timeout);
  bool connected() const { return fd_ >= 0; }
  void close();
  // Sends one payload as a frame and returns the payload of its reply: the next frame whose head
  // (`STATUS?`, `MOVE=`) matches the request's (any reply when the request does not parse).
  // Nothing on timeout or a lost connection (error() says which; the connection is closed).
  std::optional<std::string> request(std::string_view payload, std::chrono::milliseconds timeout);
  const std::string& error() const { return error_; }

 private:
  bool send_all(std::string_view bytes, std::chrono::steady_clock::time_point deadline);
  int fd_ = -1;
  Decoder decoder_;
  std::vector<Decoded> pending_;
  std::string error_;
};

// `trakbox satrak HOST[:PORT] [--timeout SECONDS] COMMAND...`: sends each COMMAND (a payload such
// as STATUS? or GOTO=,10,20; a whole `$...*HH` frame is taken too) and prints each reply payload on
// a line of `out`. Returns 0 when every command was answered without ERR, 1 when one was refused
// (ERR), not answered or the connection failed, 2 for bad arguments (`err` says why).
int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
// The usage line for --help.
std::string cli_usage();

// --- The rotator driver -------------------------------------------------------------------------

struct SatrakRotatorOptions {
  std::string host;
  unsigned short port = kDefaultPort;
  std::chrono::milliseconds poll{250};         // STATUS? interval while connected
  std::chrono::milliseconds io_timeout{1000};  // one request's reply
  std::chrono::milliseconds backoff_min{250};  // first reconnect delay
  std::chrono::milliseconds backoff_max{8000};
};

// `satrak:HOST[:PORT]` (PORT defaults to 4001). Nothing (with `error` saying what is expected)
// otherwise.
std::optional<SatrakRotatorOptions> parse_rotator_spec(std::string_view text, std::string& error);

// Another Satrak ACU as trakbox's rotator. All network I/O runs on the worker thread of a
// WorkerRotator (rotator/worker.h):
//   set_position -> GOTO=,AZ,EL (the latest position wins; STOP= first when stop() came in)
//   read / motion / limits -> from STATUS? polled every `poll` (X2/X3 az/el, X4..X7 limit flags,
//                             X12/X13 motion)
//   health -> connecting / ok / fault; a lost connection is reported and retried with backoff
//             (backoff_min doubling to backoff_max); commands given while it is down are dropped.
// A GOTO the ACU refuses (ERR) is reported as a fault with its code until a GOTO is accepted.
class SatrakRotator final : public rotator::WorkerRotator {
 public:
  explicit SatrakRotator(SatrakRotatorOptions options);
};

}  // namespace tb::satrak
