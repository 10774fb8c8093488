// A terminal that reads keys from a string and collects what is written: for tests of menus, and
// for running a menu against canned input. An optional hook runs whenever input is awaited (tests
// use it to advance a manual clock or tick the tracker, as the event loop would).
#pragma once
#include <functional>
#include <string>

#include "menus/term/terminal.h"

namespace tb::term {

class ScriptTerminal final : public Terminal {
 public:
  explicit ScriptTerminal(std::string input = {}) : input_(std::move(input)) {}

  void feed(std::string_view more) { input_.append(more); }
  const std::string& output() const { return out_; }
  void clear_output() { out_.clear(); }
  // Called with the timeout each time a key is awaited and none is left (or a timeout applies).
  std::function<void(std::optional<Duration>)> on_wait;
  // Timed reads (live displays) return kTimeout this many times before the next key is given.
  int timeouts_before_key = 0;

  void write(std::string_view text) override { out_.append(text); }
  void bell() override { out_.push_back('\a'); }
  void clear() override {
    out_.append("\n");
    graphics_shown_ = false;
  }
  void flush() override {}
  void live(const std::vector<std::string>& lines) override {
    for (const auto& l : lines) out_.append(l).append("\n");
  }
  void end_live() override {}
  void status(std::string_view text) override { status_.assign(text); }
  void graphics(const Graphics& g) override {
    graphics_ = g;
    ++graphics_count_;
    graphics_shown_ = true;
  }
  bool full_screen() const override { return full_screen_; }
  // Plays a full-screen terminal (whose graphics stay on the screen until it is cleared).
  void set_full_screen(bool on) { full_screen_ = on; }
  // Graphics drawn since the last clear(): on a full screen, still there.
  bool graphics_shown() const { return graphics_shown_; }
  int columns() const override { return 80; }
  int rows() const override { return 24; }
  bool closed() const override { return pos_ >= input_.size(); }
  const std::string& last_status() const { return status_; }
  const Graphics& last_graphics() const { return graphics_; }
  int graphics_count() const { return graphics_count_; }

 protected:
  int next_key(std::optional<Duration> timeout) override {
    if (timeout && waited_ < timeouts_before_key) {
      ++waited_;
      if (on_wait) on_wait(timeout);
      return kTimeout;
    }
    waited_ = 0;
    if (on_wait && timeout) on_wait(timeout);
    if (pos_ >= input_.size()) return kEndOfInput;
    return static_cast<unsigned char>(input_[pos_++]);
  }

 private:
  std::string input_;
  std::size_t pos_ = 0;
  std::string out_;
  std::string status_;
  Graphics graphics_;
  bool full_screen_ = false;
  bool graphics_shown_ = false;
  int graphics_count_ = 0;
  int waited_ = 0;
};

}  // namespace tb::term
