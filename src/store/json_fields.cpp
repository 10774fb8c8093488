#include "store/json_fields.h"

#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace tb::store::json_fields {
using nlohmann::json;

void bad(const std::string& where, const std::string& what) { throw std::runtime_error(where + ": " + what); }

std::string path(const std::string& where, const char* key) { return where.empty() ? key : where + "." + key; }

const json& field(const json& j, const std::string& where, const char* key) {
  if (!j.is_object()) bad(where.empty() ? "document" : where, "expected an object");
  const auto it = j.find(key);
  if (it == j.end()) bad(path(where, key), "missing");
  return *it;
}

double num(const json& j, const std::string& where, const char* key, double lo, double hi) {
  const json& v = field(j, where, key);
  if (!v.is_number()) bad(path(where, key), "expected a number");
  const double d = v.get<double>();
  if (!std::isfinite(d) || d < lo || d > hi)
    bad(path(where, key), "value " + v.dump() + " outside " + json(lo).dump() + " .. " + json(hi).dump());
  return d;
}

long long integer(const json& j, const std::string& where, const char* key, long long lo, long long hi) {
  const json& v = field(j, where, key);
  if (!v.is_number_integer()) bad(path(where, key), "expected a whole number");
  const long long n = v.get<long long>();
  if (n < lo || n > hi)
    bad(path(where, key), "value " + v.dump() + " outside " + std::to_string(lo) + " .. " + std::to_string(hi));
  return n;
}

bool boolean(const json& j, const std::string& where, const char* key) {
  const json& v = field(j, where, key);
  if (!v.is_boolean()) bad(path(where, key), "expected true or false");
  return v.get<bool>();
}

std::string text(const json& j, const std::string& where, const char* key, std::size_t max_len) {
  const json& v = field(j, where, key);
  if (!v.is_string()) bad(path(where, key), "expected a string");
  std::string s = v.get<std::string>();
  if (s.size() > max_len) bad(path(where, key), "longer than " + std::to_string(max_len) + " characters");
  return s;
}

}  // namespace tb::store::json_fields
