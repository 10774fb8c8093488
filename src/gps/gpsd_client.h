// The link to gpsd: libgps on a thread of its own, so a slow or absent gpsd never holds up the event
// loop. It connects, asks for JSON reports (?WATCH), turns each TPV into a gps::Report and each
// DEVICES list into a count, and posts them to the loop; when gpsd cannot be reached or goes away it
// says so and tries again every 2 s until it is stopped (the destructor stops and joins it within
// about a quarter of a second, or a connect's time when gpsd's host does not answer).
#pragma once
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <thread>

#include "gps/monitor.h"

namespace tb::gps {

struct GpsdEndpoint {
  std::string host = "localhost";
  std::string port = "2947";
  std::string text() const { return "gpsd:" + host + ":" + port; }  // the stored form
};

// "gpsd", "gpsd:HOST", "gpsd:HOST:PORT" (PORT 1..65535). On failure, error says why.
std::optional<GpsdEndpoint> parse_gps_spec(const std::string& spec, std::string& error);

class GpsdClient {
 public:
  using Post = std::function<void(std::function<void()>)>;
  struct Sink {
    std::function<void(Link, std::string)> link;
    std::function<void(int)> devices;
    std::function<void(Report)> report;
  };
  // post runs a function on the event loop's thread; the sink's functions run there.
  GpsdClient(GpsdEndpoint endpoint, Post post, Sink sink);
  ~GpsdClient();
  GpsdClient(const GpsdClient&) = delete;
  GpsdClient& operator=(const GpsdClient&) = delete;

 private:
  void run();
  bool session();  // one connection; false when stopping
  void pause(int ms) const;  // until ms pass or the client stops (woken by wake_)
  // Blocks until gpsd's socket is readable or the client stops; false when stopping.
  bool wait_input(int gps_fd) const;
  GpsdEndpoint endpoint_;
  Post post_;
  Sink sink_;
  std::atomic<bool> stop_{false};
  int wake_ = -1;  // an eventfd the destructor writes: the thread's waits end at once
  std::thread thread_;
};

}  // namespace tb::gps
