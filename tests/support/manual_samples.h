#pragma once
// Samples printed in the TrakBox manual, written once for the tests that replay them.

namespace tb::testing {

// Menu 6-9's station information file, as the manual prints it (CR LF line ends, as a terminal
// program uploads it).
inline constexpr const char* kManualStationFile =
    "1 WA7GXD 32.259 -110.778 842 S\r\n"
    "2 3 1017 5 454\r\n"
    "3 5 3 0 0\r\n"
    "4 ICOM A 10 14\r\n"
    "5 1 90 0 1 270 90 0 45\r\n";

}  // namespace tb::testing
