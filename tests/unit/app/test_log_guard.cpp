// Issue 33, defects 2, 4 and 5: every log line passes the guard. Credentials are scrubbed whatever
// the level; a flood of one kind of line is written `burst` times a window and then counted, with one
// line saying how many were left out; a symbolic link in place of trakbox.log is moved aside.
#include "app/log_guard.h"

#include <doctest/doctest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

using namespace tb::app;
namespace fs = std::filesystem;
using namespace std::chrono_literals;

namespace {

struct Guarded {
  std::ostringstream out;
  GuardedSink::Clock::time_point now = GuardedSink::Clock::time_point{} + 1h;
  std::shared_ptr<spdlog::logger> log;
  explicit Guarded(LogLimits limits = {}) {
    auto text = std::make_shared<spdlog::sinks::ostream_sink_mt>(out);
    text->set_pattern("%l %v");
    auto g = std::make_shared<GuardedSink>(std::vector<spdlog::sink_ptr>{text}, limits, [this] { return now; });
    log = std::make_shared<spdlog::logger>("t", g);
    log->set_level(spdlog::level::trace);
  }
  std::vector<std::string> lines() {
    log->flush();
    std::vector<std::string> v;
    std::istringstream in(out.str());
    for (std::string l; std::getline(in, l);) v.push_back(l);
    return v;
  }
};

}  // namespace

TEST_CASE("log guard: credentials never reach the sink, at any level") {
  Guarded g;
  g.log->debug("rotctld: client 127.0.0.1:40000: '{}' -> '{}'", "\\password RealSecret42", "RPRT -11");
  g.log->warn("satrak: download failed: {}", "http://op:HttpPass77@127.0.0.1:1/x.txt: Couldn't connect to server");
  g.log->error("x {}", "HTTP://op:HttpPass77@h/");
  const auto l = g.lines();
  REQUIRE(l.size() == 3);
  CHECK(l[0] == "debug rotctld: client 127.0.0.1:40000: '\\password <redacted>' -> 'RPRT -11'");
  CHECK(l[1] == "warning satrak: download failed: http://op:<redacted>@127.0.0.1:1/x.txt: Couldn't connect to server");
  CHECK(l[2] == "error x HTTP://op:<redacted>@h/");
}

TEST_CASE("log guard: lines of one kind beyond the burst are counted, and the count is written") {
  LogLimits limits;
  limits.burst = 3;
  limits.window = 60s;
  Guarded g(limits);
  for (int i = 0; i < 1000; ++i) {
    g.log->warn("host: connection from 127.0.{}.{} refused: not in --allow", i / 250, i % 250 + 1);
    g.now += 10ms;  // 10 s in all
  }
  g.log->info("something else");
  auto l = g.lines();
  REQUIRE(l.size() == 4);
  CHECK(l[0] == "warning host: connection from 127.0.0.1 refused: not in --allow");
  CHECK(l[2] == "warning host: connection from 127.0.0.3 refused: not in --allow");
  CHECK(l[3] == "info something else");
  // The window ends: the next line of any kind brings the count of what was left out.
  g.now += 51s;
  g.log->info("a minute later");
  l = g.lines();
  REQUIRE(l.size() == 6);
  CHECK(l[4] ==
        "warning 997 more lines like this left out of the log in 61 s; the last: host: connection from 127.0.3.250 "
        "refused: not in --allow");
  CHECK(l[5] == "info a minute later");
  // A new window writes the burst again.
  g.log->warn("host: connection from 127.0.0.9 refused: not in --allow");
  CHECK(g.lines().size() == 7);
}

TEST_CASE("log guard: what is still counted when the log closes is written") {
  LogLimits limits;
  limits.burst = 1;
  std::ostringstream out;
  {
    auto text = std::make_shared<spdlog::sinks::ostream_sink_mt>(out);
    text->set_pattern("%v");
    const auto t = GuardedSink::Clock::time_point{} + 1h;
    auto g = std::make_shared<GuardedSink>(std::vector<spdlog::sink_ptr>{text}, limits, [t] { return t; });
    spdlog::logger log("t", g);
    for (int i = 0; i < 5; ++i) log.info("tick {}", i);
  }
  CHECK(out.str() == "tick 0\n4 more lines like this left out of the log in 0 s; the last: tick 4\n");
}

TEST_CASE("log guard: a symbolic link in place of trakbox.log is moved aside; the file rotates by size") {
  std::string tmpl = (fs::temp_directory_path() / "trakbox-log-XXXXXX").string();
  const fs::path dir = ::mkdtemp(tmpl.data());
  const fs::path victim = dir / "victim.txt";
  { std::ofstream(victim) << "precious\n"; }
  fs::create_symlink(victim, dir / "trakbox.log");
  LogLimits limits;
  limits.file_bytes = 4096;
  limits.files = 3;
  {
    LogFile f = open_log_file(dir, limits);
    REQUIRE(f.sink);
    REQUIRE(f.notes.size() == 1);
    CHECK(f.notes[0].find("was a symbolic link, not written through: moved aside to") != std::string::npos);
    spdlog::logger log("t", f.sink);
    for (int i = 0; i < 1000; ++i) log.info("line {} of a long run of lines that fills the file", i);
    log.flush();
  }
  std::ifstream in(victim);
  std::string v((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(v == "precious\n");
  CHECK(!fs::is_symlink(fs::symlink_status(dir / "trakbox.log")));
  CHECK(fs::file_size(dir / "trakbox.log") <= 4096);
  CHECK(fs::exists(dir / "trakbox.1.log"));
  CHECK(fs::exists(dir / "trakbox.2.log"));
  CHECK(!fs::exists(dir / "trakbox.3.log"));  // three files at most
  fs::remove_all(dir);
}
