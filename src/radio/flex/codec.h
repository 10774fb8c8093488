// The SmartSDR TCP/IP API of the FlexRadio 6000 and 8000 series (TCP port 4992): the lines trakbox
// sends and the lines it reads. Pure functions: values in, text out (and back); the forms of
// docs/radio.md ("FlexRadio: the SmartSDR API") are their unit tests (tests/unit/radio/test_flex.cpp).
//
// From the radio: `V1.4.0.0` (the protocol's version) and `H6F4EC23D` (this connection's handle,
// 32-bit hex) on connect, then `R<seq>|<hex status>|<data>` replies to commands and
// `S<handle>|<object> ...` status lines (the handle of the client whose action caused it).
// To the radio: `C<seq>|<command>` ended by a line feed. Frequencies in MHz with six decimals (1 Hz).
// Encoders throw std::invalid_argument for a value the API cannot carry; Mode::none has no command.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "radio/bytes.h"

namespace tb::radio::flex {

// 435640000 -> "435.640000" (MHz, six decimals: 1 Hz).
std::string mhz(Hz hz);
// "C12|slice tune 0 435.640000\n": a command with its sequence number, ready to send.
std::string command(std::uint32_t seq, std::string_view body);

std::string tune(int slice, Hz hz);                       // slice tune 0 435.640000
std::optional<std::string> set_mode(int slice, Mode mode);  // slice set 0 mode=USB
// slice create freq=145.965000 mode=LSB (the mode left out when none): the reply's data is the
// new slice's index.
std::string create(Hz hz, Mode mode = Mode::none);
std::string set_tx(int slice);                            // slice set 1 tx=1: the transmit slice
// slice set 1 fm_tone_mode=CTCSS_TX fm_tone_value=67.0; 0: slice set 1 fm_tone_mode=OFF.
std::string set_tone(int slice, int tenths_hz);
inline std::string subscribe_slices() { return "sub slice all"; }
inline std::string list_slices() { return "slice list"; }
inline std::string ping() { return "ping"; }
inline std::string full_duplex(bool on) { return on ? "radio set full_duplex_enabled=1" : "radio set full_duplex_enabled=0"; }

// The SmartSDR name of a mode and back: USB, LSB, CW, FM (NFM and DFM read as FM).
std::optional<std::string> mode_name(Mode mode);
std::optional<Mode> mode_from_name(std::string_view name);

// "435.640000" (any number of decimals up to 6 significant after the point) -> 435640000.
std::optional<Hz> decode_mhz(std::string_view text);

// R<seq>|<hex status>|<data>[|<debug>]: status 0 is success.
struct Reply {
  std::uint32_t seq = 0;
  std::uint32_t status = 0;
  std::string data;     // the rest after the status (the new slice's index, the slice list, a message)
};
std::optional<Reply> decode_reply(std::string_view line);
// What an error status means (the API's table); "error 50000099" for one not in it.
std::string error_text(std::uint32_t status);

// S<handle>|slice <n> RF_frequency=435.640000 mode=USB tx=0 in_use=1 ...: a slice's fields that
// changed (any may be missing). Status lines of other objects are not slices (nullopt).
struct SliceStatus {
  std::uint32_t handle = 0;   // the client whose action caused it
  int index = 0;
  std::optional<Hz> hz;
  std::optional<Mode> mode;
  std::optional<bool> tx;
  std::optional<bool> in_use;
};
std::optional<SliceStatus> decode_slice_status(std::string_view line);

// "V1.4.0.0" -> "1.4.0.0"; "H6F4EC23D" -> 0x6F4EC23D.
std::optional<std::string> decode_version(std::string_view line);
std::optional<std::uint32_t> decode_handle(std::string_view line);
// slice list's data: "0 1" -> {0, 1}; nullopt when it is not a list of numbers.
std::optional<std::vector<int>> decode_slice_list(std::string_view data);

}  // namespace tb::radio::flex
