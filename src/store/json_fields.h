// Reading typed fields out of a JSON document, each failure a std::runtime_error that names the
// field by its path and says what was expected ("rotator.az_dead_band: value 2000 outside 0 .. 1023").
// Shared by the state document (model.cpp) and the Satrak settings (satrak/settings.cpp).
//
// `where` is the path of the object `j` ("station", "db.satellites[3].radio"); "" for the top level,
// whose fields are then named by their key alone.
#pragma once
#include <cstddef>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace tb::store::json_fields {

[[noreturn]] void bad(const std::string& where, const std::string& what);

// where + "." + key, or key alone at the top level.
std::string path(const std::string& where, const char* key);

// j[key]; throws when j is not an object or has no such key.
const nlohmann::json& field(const nlohmann::json& j, const std::string& where, const char* key);

// A finite number in [lo, hi].
double num(const nlohmann::json& j, const std::string& where, const char* key, double lo, double hi);

// A whole number in [lo, hi].
long long integer(const nlohmann::json& j, const std::string& where, const char* key, long long lo, long long hi);

bool boolean(const nlohmann::json& j, const std::string& where, const char* key);

// A string of at most max_len bytes.
std::string text(const nlohmann::json& j, const std::string& where, const char* key, std::size_t max_len);

}  // namespace tb::store::json_fields
