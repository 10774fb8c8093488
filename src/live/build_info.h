#pragma once

namespace tb::app {
// Set by CMake (project version).
inline constexpr const char* kVersion = TRAKBOX_VERSION;
}  // namespace tb::app
