// The web endpoint's cost to the station (issue 37): the station's thread pushing the live state to
// 0 or 50 WebSocket viewers (CPU per push; at one push a second that is the share of one core), the
// live document built once per push and its merge patch (web/live_feed.h, issue 49),
// the memory each viewer costs the process, the first load's bytes, and the delay from a change
// (Server::push_soon) to the message at a viewer. The viewers are Beast clients on a thread of
// their own: only the station's thread's CPU clock is counted.
#include <benchmark/benchmark.h>

#include <atomic>
#include <chrono>
#include <malloc.h>
#include <thread>
#include <vector>

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>

#include "bench_support.h"
#include "support/sim_station.h"
#include "web/access.h"
#include "web/api.h"
#include "web/live_feed.h"
#include "web/page.h"
#include "web/server.h"

using namespace tb;
namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

namespace {

// Bytes the process has allocated (the viewers' client side included: an upper bound on what a
// viewer costs the station).
double heap_kb() { return static_cast<double>(mallinfo2().uordblks) / 1024.0; }

// A viewer: reads every message; `received` counts them, `last` is when the last one came.
struct Viewer : std::enable_shared_from_this<Viewer> {
  explicit Viewer(asio::io_context& io) : ws(io) {}
  websocket::stream<tcp::socket> ws;
  beast::flat_buffer buffer;
  std::atomic<int> received{0};
  std::atomic<long long> last_ns{0};
  void start() {
    ws.async_read(buffer, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) return;
      self->buffer.clear();
      self->last_ns = std::chrono::steady_clock::now().time_since_epoch().count();
      ++self->received;
      self->start();
    });
  }
};

struct Bench {
  testing::StationFixture station;
  web::Access access{web::AccessOptions{}};
  std::unique_ptr<web::Api> api;
  asio::io_context io;
  std::unique_ptr<web::Server> server;
  asio::io_context client_io;
  asio::executor_work_guard<asio::io_context::executor_type> work{client_io.get_executor()};
  std::thread client_thread;
  std::vector<std::shared_ptr<Viewer>> viewers;

  Bench() {
    station.build_station();
    station.tracker.track_single(*station.model.db.find("ISS"));
    station.station->tick();
    // The status document is built by the program (app/status.h); here a stand-in of the real one's
    // size (6.4 kB on the simulated station tracking ISS), so that the messages weigh what they do.
    api = std::make_unique<web::Api>(
        *station.station, access,
        web::ApiHooks{[] { return nlohmann::json{{"running", true}, {"stand_in", std::string(6300, 'x')}}; }, {}, {}, {}});
    web::ServerOptions o;
    o.port = 0;
    o.per_address = 100;
    o.max_connections = 100;
    o.push_every = std::chrono::hours(1);  // pushes only when the benchmark asks
    server = std::make_unique<web::Server>(io, *api, o);
    client_thread = std::thread([this] { client_io.run(); });
  }
  ~Bench() {
    for (auto& v : viewers) asio::post(client_io, [v] { beast::error_code ec; v->ws.next_layer().close(ec); });
    work.reset();
    client_io.stop();
    client_thread.join();
  }
  void connect(int n) {
    for (int i = 0; i < n; ++i) {
      auto v = std::make_shared<Viewer>(client_io);
      v->ws.next_layer().connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server->port()));
      std::atomic<bool> done{false};
      std::thread handshake([&] {
        v->ws.handshake("127.0.0.1", "/api/v1/live");
        done = true;
      });
      while (!done) io.run_for(std::chrono::milliseconds(1));
      handshake.join();
      asio::post(client_io, [v] { v->start(); });
      viewers.push_back(v);
    }
    settle(2 * n);
  }
  int received() const {
    int n = 0;
    for (const auto& v : viewers) n += v->received;
    return n;
  }
  // Runs the station's loop until the viewers have `total` messages (or 2 s pass).
  void settle(int total) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (received() < total && std::chrono::steady_clock::now() < until) io.run_for(std::chrono::microseconds(200));
  }
};

void BM_WebPush(benchmark::State& state) {
  Bench b;
  const int n = static_cast<int>(state.range(0));
  const double before = heap_kb();
  b.connect(n);
  b.server->push_soon();  // the buffers of a first push
  b.settle(b.received() + n);
  const double after = heap_kb();
  double cpu = 0;
  int pushes = 0;
  for (auto _ : state) {
    b.station.step(std::chrono::seconds(1));  // a second of the pass: the patch carries what it changed
    const int want = b.received() + n;
    const double t0 = bench::thread_cpu_ns();
    b.server->push_soon();
    if (n == 0) b.io.run_for(std::chrono::milliseconds(1));
    else b.settle(want);
    cpu += bench::thread_cpu_ns() - t0;
    ++pushes;
  }
  state.counters["station_cpu_us_per_push"] = cpu / pushes / 1e3;
  state.counters["core_percent_at_1Hz"] = cpu / pushes / 1e9 * 100.0;
  state.counters["kB_per_viewer"] = n ? (after - before) / n : 0.0;
  state.counters["message_bytes"] = static_cast<double>(b.api->live_state().size());
  state.counters["first_load_bytes"] = static_cast<double>(web::first_load_bytes());
}
BENCHMARK(BM_WebPush)->Arg(0)->Arg(50)->Unit(benchmark::kMicrosecond)->UseRealTime();

// From push_soon() to the message at a viewer.
void BM_WebStateToViewer(benchmark::State& state) {
  Bench b;
  b.connect(1);
  double total_us = 0;
  int n = 0;
  for (auto _ : state) {
    b.station.step(std::chrono::seconds(1));
    const int want = b.received() + 1;
    const long long t0 = std::chrono::steady_clock::now().time_since_epoch().count();
    b.server->push_soon();
    b.settle(want);
    total_us += static_cast<double>(b.viewers[0]->last_ns - t0) / 1e3;
    ++n;
  }
  state.counters["state_to_viewer_us"] = total_us / n;
}
BENCHMARK(BM_WebStateToViewer)->Unit(benchmark::kMicrosecond)->UseRealTime();

// The live document built and turned into this push's message (the whole document or the merge
// patch of what changed), once per push whatever the number of viewers; the bytes of each.
void BM_LiveDocument(benchmark::State& state) {
  Bench b;
  web::LiveFeed feed;
  feed.next(b.api->live_document());
  double cpu = 0, patch_bytes = 0;
  int pushes = 0;
  for (auto _ : state) {
    b.station.step(std::chrono::seconds(1));
    const double t0 = bench::thread_cpu_ns();
    const auto m = feed.next(b.api->live_document());
    cpu += bench::thread_cpu_ns() - t0;
    patch_bytes += m ? static_cast<double>(m->size()) : 0.0;
    ++pushes;
  }
  state.counters["cpu_us_per_push"] = cpu / pushes / 1e3;
  state.counters["patch_bytes"] = patch_bytes / pushes;
  state.counters["full_bytes"] = static_cast<double>(feed.full()->size());
}
BENCHMARK(BM_LiveDocument)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
