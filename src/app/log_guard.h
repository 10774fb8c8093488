// What stands between every log line and the log (issue 33): credentials scrubbed from each line
// whatever its level, source or form (util/redact.h), and repeated lines rate-limited so that anyone
// who can reach a port cannot fill the disk. Lines "of the same kind" are those that differ only in
// their digits (addresses, ports, counts): after `burst` of a kind in `window`, the rest of that
// window is counted, not written, and one line says how many were left out and shows the last.
// The file under it rotates by size (spdlog's rotating sink); a log file that is a symbolic link is
// moved aside, never written through.
#pragma once
#include <spdlog/sinks/base_sink.h>

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace tb::app {

struct LogLimits {
  std::size_t burst = 10;                      // lines of one kind written in a window
  std::chrono::milliseconds window{60000};
  std::size_t max_kinds = 512;                 // kinds remembered at once
  std::size_t file_bytes = 10u * 1024 * 1024;  // trakbox.log rotates at this size
  std::size_t files = 5;                       // trakbox.log, trakbox.1.log ... trakbox.4.log
};

class GuardedSink : public spdlog::sinks::base_sink<std::mutex> {
 public:
  using Clock = std::chrono::steady_clock;
  GuardedSink(std::vector<spdlog::sink_ptr> sinks, LogLimits limits,
              std::function<Clock::time_point()> now = [] { return Clock::now(); });
  ~GuardedSink() override;

  // "connection from 127.0.0.9:4711 refused" -> "connection from #.#.#.#:# refused"
  static std::string kind_of(std::string_view text);

 protected:
  void sink_it_(const spdlog::details::log_msg& msg) override;
  void flush_() override;

 private:
  struct Kind {
    Clock::time_point window_start{};
    std::size_t written = 0;
    std::size_t suppressed = 0;
    std::string last;  // the last suppressed line, redacted
    spdlog::level::level_enum level = spdlog::level::info;
    std::string logger;
  };
  void forward(const spdlog::details::log_msg& msg, std::string_view payload);
  void report_suppressed(Kind& k, Clock::time_point now);
  void report_ended_windows(Clock::time_point now);

  std::vector<spdlog::sink_ptr> sinks_;
  LogLimits limits_;
  std::function<Clock::time_point()> now_;
  std::map<std::string, Kind> kinds_;
  Clock::time_point last_sweep_{};
};

// trakbox.log in `dir`, rotating; a symbolic link in its place (or in a rotated file's) is moved
// aside first. The note for the log when that happened; no sink when a link could not be moved.
struct LogFile {
  spdlog::sink_ptr sink;
  std::vector<std::string> notes;
};
LogFile open_log_file(const std::filesystem::path& dir, const LogLimits& limits);

}  // namespace tb::app
