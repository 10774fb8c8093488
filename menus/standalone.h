// Standalone mode: no menus. The front-panel selector picks satellite N (1-15) of the tracking list;
// the two-line LCD shows time, satellite, azimuth and elevation (or A/E/P with the MA display), and
// the AOS LED blinks when the satellite is in range with tracking off, steady when tracking.
//
// The keyboard stands in for the front panel (docs/menus/m-standalone.md):
//   1-9      selector to position 1-9          + (or =)  selector one position up (to 15)
//   0        selector to 0 (terminal mode)      -         selector one position down (to 0)
//   E        the track switch (rotor control)   Q         leave (the program ends)
//   Enter    at position 0: leave standalone for the menus (sign-on and main menu)
// Going to 0 and back to a satellite position toggles single and multiple tracking when multiple
// tracking is possible (two or more satellites in the tracking list).
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "menus/menus.h"
#include "tracker/tracker.h"

namespace tb::menus {

// ---- the LCD and the AOS LED (pure) ----

inline constexpr std::size_t kLcdColumns = 16;
// Characters of the name on the top line: 16 less "HH:MM:SS" and the separator.
inline constexpr std::size_t kLcdNameColumns = 7;

struct Lcd {
  std::string top;     // "07:34:54 UO-14"
  std::string bottom;  // "Az 146.7El -62.8" or "A110 E20 P119.2"
  bool operator==(const Lcd&) const = default;
};

// Top line: time, separator (' ' single tracking, '!' or '&' multiple tracking), the name cut to
// 7 characters. Never longer than 16.
std::string lcd_top(orbit::UtcTime t, std::string_view name, char separator = ' ');
// Bottom line, azimuth/elevation: "Az 146.7El -62.8" (each value %6.1f: always 16 characters).
std::string lcd_azel(double az_deg, double el_deg);
// Bottom line with the satellite's LCD MA display on: "A110 E20 P119.2" (azimuth and elevation in
// whole degrees, phase 0-255 to 0.1, cut down, never 256.0).
std::string lcd_ma(double az_deg, double el_deg, double phase256);
// The LCD for a satellite now.
Lcd lcd_for(const tracker::SatNow& n, bool ma_display, char separator = ' ');
// The LCD when the selector points past the end of the tracking list: "No satellite #12".
Lcd lcd_no_satellite(orbit::UtcTime t, int position);

enum class Led { off, blinking, on };
// The AOS LED: off out of range; in range, blinking with the track switch off, steady when on.
Led aos_led(bool in_range, bool track_switch);
// Whether the LED is lit at t (blinking: lit in even seconds, dark in odd ones).
bool led_lit(Led led, orbit::UtcTime t);
// "on", "blink", "off".
const char* led_word(Led led);

// Line mode, one line per second: "|07:34:54 UO-14  |Az 146.7El -62.8| LED blink" (each LCD line
// padded to 16 between bars, then the LED).
std::string lcd_line(const Lcd& lcd, Led led);
// Full screen: the LCD in a frame with the LED beside it ("AOS (*)" lit, "AOS ( )" dark).
std::vector<std::string> lcd_panel(const Lcd& lcd, Led led, orbit::UtcTime t, bool track_switch);

// ---- the front-panel selector ----

inline constexpr int kSelectorPositions = 16;  // 0 (terminal) and 1-15
// The selector position a key moves to from `current`, or nullopt when the key is not a selector key.
std::optional<int> selector_key(int key, int current);

// Standalone mode until Q (returns) or the end of input (throws InputClosed). Enter at position 0
// calls terminal_mode (the sign-on and the main menu) and returns when it does.
void standalone(term::Terminal& t, Services& s, int selector, const std::function<void()>& terminal_mode);
// The same, with the sign-on and the main menu as terminal mode (menus/standalone_terminal.cpp).
void standalone(term::Terminal& t, Services& s, int selector);

}  // namespace tb::menus
