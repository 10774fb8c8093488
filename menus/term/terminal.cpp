#include "menus/term/terminal.h"

#include <cctype>

namespace tb::term {

// The one rule for Enter, for every menu, prompt and upload: CR, LF and CR LF are the same key, which
// read_key returns as kEnter ('\r'), so no menu ever sees '\n'. The LF of a CR LF pair is dropped
// whenever it comes (a terminal sends either CR, LF or CR LF for Enter; never a CR for one key and a
// lone LF for the next). And an Enter that follows a single-key answer (read_choice) is taken as
// that answer's terminator, never as the next answer: "Y" and "Y<Enter>" answer the same.
int Terminal::read_key(std::optional<Duration> timeout) {
  for (;;) {
    int k;
    if (!pending_.empty()) {
      k = pending_.front();
      pending_.erase(pending_.begin());
    } else {
      k = next_key(timeout);
    }
    if (k == kTimeout || k == kEndOfInput) return k;
    const bool lf_of_crlf = k == '\n' && last_was_cr_;
    last_was_cr_ = k == '\r';
    if (lf_of_crlf) continue;
    if (k == '\n') k = kEnter;
    if (k == kEnter && enter_ends_choice_) {
      enter_ends_choice_ = false;
      continue;
    }
    enter_ends_choice_ = false;
    return k;
  }
}

std::optional<std::string> Terminal::read_line(std::size_t max_length) {
  std::string text;
  non_ascii_ = false;
  for (;;) {
    const int k = read_key();
    if (k == kEndOfInput) return std::nullopt;
    if (k == kEnter) {
      if (echo_) write("\n");
      flush();
      return text;
    }
    if (k == kCtrlZ && text.empty()) {
      if (echo_) write("\n");
      return std::string(1, '\x1a');
    }
    if (k == kEscape && escape_leaves_) {  // what was typed on this line is dropped too
      if (echo_) write("\n");
      flush();
      return std::string(1, '\x1b');
    }
    if (k == kBackspace || k == 127) {
      if (!text.empty()) {
        text.pop_back();
        if (echo_) write("\b \b");
        flush();
      }
      continue;
    }
    if (k >= 128 && k <= 255) non_ascii_ = true;  // a byte of a UTF-8 character: not taken, and said
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
    if (k == kEnter) {
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
    enter_ends_choice_ = true;  // an Enter typed after the key ends this answer (see read_key)
    return c;
  }
}

bool Terminal::read_upload(const std::function<void(std::string_view line)>& on_line, std::size_t max_line) {
  std::string text;
  for (;;) {
    const int k = read_key();
    if (k == kEndOfInput) return false;
    if (k == kCtrlZ) {
      if (!text.empty()) on_line(text);
      return true;
    }
    if (k == kEnter) {
      on_line(text);
      text.clear();
      continue;
    }
    if (k < 0) continue;
    if (text.size() < max_line) text.push_back(static_cast<char>(k));
  }
}

}  // namespace tb::term
