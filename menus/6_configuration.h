// Menu 6 (Configuration) and its items, menu 8 (Direct Antenna control, the 6-6 sub-menu), and the
// pieces they share: prompts where Q leaves the item with nothing changed, the live monitor line,
// and committing a rotator configuration only when rotator::validate accepts it.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "menus/menus.h"
#include "rotator/config.h"

namespace tb::store { struct Model; }

namespace tb::menus {

// The items of the Configuration Menu; each returns to the list when finished or on Q.
void menu_6_0_display(term::Terminal& t, Services& s);
void menu_6_1_calibration(term::Terminal& t, Services& s);
void menu_6_2_adc_span(term::Terminal& t, Services& s);
void menu_6_3_dead_band_skew(term::Terminal& t, Services& s);
void menu_6_4_parking_limits(term::Terminal& t, Services& s);
void menu_6_5_monitor(term::Terminal& t, Services& s);
void menu_6_6_direct_control(term::Terminal& t, Services& s);  // the sub-menu, also menu 8
void menu_6_6_1_keyboard(term::Terminal& t, Services& s);
void menu_6_6_2_enter_value(term::Terminal& t, Services& s);
void menu_6_6_3_presets(term::Terminal& t, Services& s);
void menu_6_7_radio_cat(term::Terminal& t, Services& s);
void menu_6_8_mic_click(term::Terminal& t, Services& s);
void menu_6_9_default_parameter(term::Terminal& t, Services& s);
void menu_6_r_rotor_control(term::Terminal& t, Services& s);  // trakbox's own: rotor control, stored

// The 6-0 display, one string a line (without "Press any key to continue").
std::vector<std::string> configuration_lines(const store::Model& m);
// "ADC span value AZ:0003-0837 EL:0001-0460" (6-1).
std::string span_line(const rotator::RotatorConfig& c);
// " 1:0.0/0.0 2:0.0/0.0 ..." (6-6-3), wrapped onto a second line when long.
std::vector<std::string> preset_lines(const rotator::RotatorConfig& c);
// What ADC3 reads now (6-8 Measure): trakbox has no ADC3 input of its own, so this is a simulated
// discriminator (radio::SimulatedDiscriminator) fed with the followed satellite's downlink as it
// arrives at the radio and the frequency the radio reports it is tuned to. No signal (no satellite
// followed, below the horizon, no downlink, radio not tuned) reads the discriminator's centre.
int simulated_adc3(const Services& s);

namespace cfg {

// Q at a prompt of a configuration item: leave it, nothing changed.
struct Quit {};

// "%.1f", without "-0.0".
std::string fmt1(double v);
// Prints the prompt and reads the answer, trimmed; throws Quit for Q.
std::string answer(term::Terminal& t, std::string_view prompt);
// A number in [lo, hi] (whole: an integer value); Enter keeps `current` when there is one. A bad
// answer is explained and the prompt repeated.
double ask_number(term::Terminal& t, std::string_view prompt, std::optional<double> current, double lo, double hi,
                  bool whole = false);
// One key among `keys` (upper case, echoed); Q throws Quit; anything else repeats the question.
char ask_choice(term::Terminal& t, std::string_view prompt, std::string_view keys);

// Validates `next` (rotator::validate); on success makes it the model's, reconfigures the station
// and saves. Otherwise shows every problem and "Not changed." and leaves everything as it was.
bool commit_rotator(term::Terminal& t, Services& s, const rotator::RotatorConfig& next);

// A long message as lines of at most `width` characters, broken between words; lines after the
// first are indented by `indent`.
std::vector<std::string> wrap_words(std::string_view text, std::size_t width = 78, std::string_view indent = "  ");

// Direct control (6-1, 6-6-1, 6-6-2, 6-6-3) is the operator moving the antenna: it takes rotor
// control (the E switch) as the manual's examples assume, with one line saying so when it was off
// (saved, as E would be). No question: the manual's keystrokes work on a fresh unit (issue 18).
void take_rotor_control(term::Terminal& t, Services& s);

// The live "AZ= 519 / 32.8deg EL= 462 / 90.0deg." line, redrawn when it changes, with any
// rotator message (stall, fault) printed once above it.
class LiveMonitor {
 public:
  // `line` makes the monitor line (default: format_monitor_line of the rotator's status).
  LiveMonitor(term::Terminal& t, Services& s, std::vector<std::string> below = {},
              std::function<std::string()> line = {});
  ~LiveMonitor();
  LiveMonitor(const LiveMonitor&) = delete;
  LiveMonitor& operator=(const LiveMonitor&) = delete;
  // Redraws if anything changed (or always with force); `below` replaces the lines under it.
  void update(bool force = false);
  void set_below(std::vector<std::string> below);
  // A line printed once above the live block (the block is drawn again below it).
  void note(std::string_view text);
  // Waits for a key up to the live interval, updating; kTimeout when none. Throws InputClosed.
  int key();
  void end();

 private:
  term::Terminal& t_;
  Services& s_;
  std::vector<std::string> below_;
  std::function<std::string()> line_;
  std::vector<std::string> shown_;
  std::string message_;
  bool live_ = false;
};

// How often live rotator displays redraw and look at the keys.
inline constexpr auto kLiveInterval = std::chrono::milliseconds(500);

// Watches the antenna go to the target just commanded: live line until it is on target, stops
// (stall, fault) or a key is pressed ('5' also stops the motion).
void watch_until_arrived(term::Terminal& t, Services& s);

}  // namespace cfg
}  // namespace tb::menus
