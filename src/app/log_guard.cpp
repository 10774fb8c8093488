#include "app/log_guard.h"

#include <spdlog/sinks/rotating_file_sink.h>
#include <sys/stat.h>

#include <cctype>

#include "store/state_file.h"
#include "util/redact.h"

namespace tb::app {

GuardedSink::GuardedSink(std::vector<spdlog::sink_ptr> sinks, LogLimits limits, std::function<Clock::time_point()> now)
    : sinks_(std::move(sinks)), limits_(limits), now_(std::move(now)) {}

GuardedSink::~GuardedSink() {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto now = now_();
  for (auto& [key, k] : kinds_) report_suppressed(k, now);
  for (auto& s : sinks_) s->flush();
}

std::string GuardedSink::kind_of(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (std::isdigit(c) || (std::isxdigit(c) && i && text[i - 1] == ':')) {
      // digits (and the hex groups of IPv6 addresses) become one '#'
      while (i + 1 < text.size() && std::isxdigit(static_cast<unsigned char>(text[i + 1]))) ++i;
      out += '#';
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

void GuardedSink::forward(const spdlog::details::log_msg& msg, std::string_view payload) {
  spdlog::details::log_msg copy(msg);
  copy.payload = payload;
  for (auto& s : sinks_)
    if (s->should_log(copy.level)) s->log(copy);
}

void GuardedSink::report_suppressed(Kind& k, Clock::time_point now) {
  if (k.suppressed == 0) return;
  const auto secs = std::chrono::duration_cast<std::chrono::seconds>(now - k.window_start).count();
  const std::string line = std::to_string(k.suppressed) + " more line" + (k.suppressed == 1 ? "" : "s") +
                           " like this left out of the log in " + std::to_string(secs) + " s; the last: " + k.last;
  spdlog::details::log_msg m(spdlog::source_loc{}, k.logger, k.level, line);
  forward(m, line);
  k.suppressed = 0;
  k.last.clear();
}

void GuardedSink::report_ended_windows(Clock::time_point now) {
  // At most once a second, look for kinds whose window has ended with lines left out.
  if (now - last_sweep_ < std::chrono::seconds(1)) return;
  last_sweep_ = now;
  for (auto it = kinds_.begin(); it != kinds_.end();) {
    Kind& k = it->second;
    if (now - k.window_start >= limits_.window) {
      report_suppressed(k, now);
      it = kinds_.erase(it);  // a quiet kind starts a new window when it comes again
    } else {
      ++it;
    }
  }
}

void GuardedSink::sink_it_(const spdlog::details::log_msg& msg) {
  const std::string text = redact::text(std::string_view(msg.payload.data(), msg.payload.size()));
  const auto now = now_();
  report_ended_windows(now);
  const std::string key = std::to_string(static_cast<int>(msg.level)) + kind_of(text);
  auto it = kinds_.find(key);
  if (it == kinds_.end()) {
    if (kinds_.size() >= limits_.max_kinds) {
      // Too many kinds at once (text that never repeats): the oldest window goes first.
      auto oldest = kinds_.begin();
      for (auto i = kinds_.begin(); i != kinds_.end(); ++i)
        if (i->second.window_start < oldest->second.window_start) oldest = i;
      report_suppressed(oldest->second, now);
      kinds_.erase(oldest);
    }
    it = kinds_.emplace(key, Kind{}).first;
    it->second.window_start = now;
  }
  Kind& k = it->second;
  if (now - k.window_start >= limits_.window) {
    report_suppressed(k, now);
    k.window_start = now;
    k.written = 0;
  }
  if (k.written < limits_.burst) {
    ++k.written;
    forward(msg, text);
    return;
  }
  ++k.suppressed;
  k.last = text;
  k.level = msg.level;
  k.logger.assign(msg.logger_name.data(), msg.logger_name.size());
}

void GuardedSink::flush_() {
  for (auto& s : sinks_) s->flush();
}

namespace {

// The path spdlog's rotating sink gives rotated file n: trakbox.log -> trakbox.n.log.
std::filesystem::path rotated(const std::filesystem::path& file, std::size_t n) {
  if (n == 0) return file;
  return file.parent_path() / (file.stem().string() + "." + std::to_string(n) + file.extension().string());
}

}  // namespace

LogFile open_log_file(const std::filesystem::path& dir, const LogLimits& limits) {
  LogFile out;
  const std::filesystem::path file = dir / "trakbox.log";
  // spdlog opens with fopen, which follows links: trakbox.log (or a rotated file it would be renamed
  // over) that is a symbolic link is moved aside, and the link's target is never touched.
  for (std::size_t n = 0; n < limits.files; ++n) {
    const std::filesystem::path p = rotated(file, n);
    struct stat st {};
    if (::lstat(p.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
      const std::filesystem::path kept = store::keep_aside(p);
      if (kept.empty()) {
        out.notes.push_back(p.string() + " is a symbolic link that could not be moved aside: no log file is written");
        return out;
      }
      out.notes.push_back(p.string() + " was a symbolic link, not written through: moved aside to " + kept.string());
    }
  }
  out.sink = std::make_shared<spdlog::sinks::rotating_file_sink_mt>(file.string(), limits.file_bytes,
                                                                     limits.files > 0 ? limits.files - 1 : 0);
  return out;
}

}  // namespace tb::app
