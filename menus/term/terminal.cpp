#include "menus/term/terminal.h"

#include <cctype>

namespace tb::term {

int Terminal::read_key(std::optional<Duration> timeout) {
  for (;;) {
    int k;
    if (!pending_.empty()) {
      k = pending_.front();
      pending_.erase(pending_.begin());
    } else {
      k = next_key(timeout);
    }
    return k;
  }
}

std::optional<std::string> Terminal::read_line(std::size_t max_length) {
  std::string text;
  for (;;) {
    const int k = read_key();
    if (k == kEndOfInput) return std::nullopt;
    if (k == '\r' || k == '\n') {
      // A CRLF pair ends one line: swallow the LF that may follow a CR.
      if (k == '\r') {
        const int next = read_key(std::chrono::milliseconds(30));
        if (next != '\n' && next != kTimeout && next != kEndOfInput) pending_.push_back(next);
      }
      if (echo_) write("\n");
      flush();
      return text;
    }
    if (k == kCtrlZ && text.empty()) {
      if (echo_) write("\n");
      return std::string(1, '\x1a');
    }
    if (k == kBackspace || k == 127) {
      if (!text.empty()) {
        text.pop_back();
        if (echo_) write("\b \b");
        flush();
      }
      continue;
    }
    if (k < 32 || k > 126 || text.size() >= max_length) continue;  // ignore controls, overlong input
    text.push_back(static_cast<char>(k));
    if (echo_) write(std::string_view(&text.back(), 1));
    flush();
  }
}

std::optional<char> Terminal::read_choice(std::string_view accept, bool allow_enter) {
  for (;;) {
    const int k = read_key();
    if (k == kEndOfInput) return std::nullopt;
    if (k == '\n') continue;  // the tail of a CRLF from the previous answer
    if (k == '\r') {
      if (!allow_enter) continue;
      write("\n");
      flush();
      return '\r';
    }
    if (k < 32 || k > 126) continue;
    const char c = static_cast<char>(std::toupper(k));
    if (!accept.empty() && accept.find(c) == std::string_view::npos) continue;
    write(std::string_view(&c, 1));
    write("\n");
    flush();
    return c;
  }
}

bool Terminal::read_upload(const std::function<void(std::string_view line)>& on_line, std::size_t max_line) {
  std::string text;
  bool last_cr = false;
  for (;;) {
    const int k = read_key();
    if (k == kEndOfInput) return false;
    if (k == kCtrlZ) {
      if (!text.empty()) on_line(text);
      return true;
    }
    if (k == '\n' && last_cr) {
      last_cr = false;
      continue;
    }
    last_cr = (k == '\r');
    if (k == '\r' || k == '\n') {
      on_line(text);
      text.clear();
      continue;
    }
    if (k < 0) continue;
    if (text.size() < max_line) text.push_back(static_cast<char>(k));
  }
}

}  // namespace tb::term
