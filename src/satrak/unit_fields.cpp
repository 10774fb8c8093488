// Reply field formatting and the request field reader of the Satrak unit (unit_internal.h).
#include <cctype>
#include <cmath>
#include <cstdio>

#include "satrak/settings.h"
#include "satrak/unit_internal.h"
#include "util/text.h"

namespace tb::satrak::detail {

namespace {
bool is_leap(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }
int days_in_month(int y, int m) {
  static constexpr int d[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return m == 2 && is_leap(y) ? 29 : d[m - 1];
}
}  // namespace

std::string num_text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::vector<std::string> StatusFields::fields() const {
  return {b(fault),        f2(true_az_deg),         f2(el_deg),
          b(x_plus_limit), b(x_minus_limit),        b(y_plus_limit),
          b(y_minus_limit), b(tracking),            std::to_string(window_status),
          b(rtc_updated_by_gps), std::to_string(gps_lock_delay_s), std::to_string(x_motion),
          std::to_string(y_motion), f2(x_deg),      f2(y_deg),
          b(auto_track)};
}

std::string field_text(std::string_view s) {
  std::string out;
  for (unsigned char c : s) out += (c < 0x20 || c == ',' || c == '*' || c == '$' || c >= 0x7F) ? ' ' : static_cast<char>(c);
  return out;
}

std::vector<std::string> civil_fields(orbit::UtcTime t, bool with_ms, bool two_digit_year) {
  const auto secs = std::chrono::floor<std::chrono::seconds>(t);
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(t - secs).count();
  const orbit::CivilTime c = orbit::to_civil(orbit::UtcTime(secs));
  std::vector<std::string> out = {std::to_string(c.hour),  std::to_string(c.minute),
                                  std::to_string(static_cast<int>(c.second)), std::to_string(c.day),
                                  std::to_string(c.month), std::to_string(two_digit_year ? c.year % 100 : c.year)};
  if (with_ms) out.push_back(std::to_string(ms));
  return out;
}

bool valid_http_url(std::string_view u) {
  const std::string l = text::lower(u);
  if (l.rfind("http://", 0) != 0 && l.rfind("https://", 0) != 0) return false;
  if (u.size() > limits::kUrlMax || !frame_text(u)) return false;
  for (unsigned char c : u)
    if (c == ' ' || c >= 0x7F) return false;
  return l.size() > (l[4] == 's' ? 8u : 7u);
}

bool valid_text_field(std::string_view s, std::size_t max_len) {
  if (s.size() > max_len || !frame_text(s)) return false;
  for (unsigned char c : s)
    if (c >= 0x7F) return false;
  return true;
}

Error coordinate_error(std::string_view s, std::string_view letters) {
  std::string t(text::trim(s));
  if (!t.empty() && std::isalpha(static_cast<unsigned char>(t.back()))) {
    const char up = text::to_upper(t.back());
    if (letters.find(up) == std::string_view::npos) return Error::bad_value;
    t.pop_back();
  }
  return parse_number(text::trim(t)) ? Error::out_of_range : Error::bad_value;
}

double Reader::number(std::size_t i, double lo, double hi) {
  if (err_) return 0.0;
  const auto v = parse_number(f_[i]);
  if (!v) {
    fail(Error::bad_value);
    return 0.0;
  }
  if (*v < lo || *v > hi) fail(Error::out_of_range);
  return *v;
}

long long Reader::integer(std::size_t i, long long lo, long long hi) {
  if (err_) return 0;
  auto v = parse_integer(f_[i]);
  if (!v) {
    const auto d = parse_number(f_[i]);
    if (d && std::floor(*d) == *d && std::abs(*d) < 9e15) v = static_cast<long long>(*d);
  }
  if (!v) {
    fail(Error::bad_value);
    return 0;
  }
  if (*v < lo || *v > hi) fail(Error::out_of_range);
  return *v;
}

bool Reader::flag(std::size_t i) {
  if (err_) return false;
  if (f_[i] == "0") return false;
  if (f_[i] == "1") return true;
  const auto v = parse_integer(f_[i]);
  fail(v ? Error::out_of_range : Error::bad_value);
  return false;
}

orbit::UtcTime Reader::civil(std::size_t i) {
  const long long h = integer(i, 0, 23), mi = integer(i + 1, 0, 59), s = integer(i + 2, 0, 59);
  const long long d = integer(i + 3, 1, 31), mo = integer(i + 4, 1, 12);
  long long y = integer(i + 5, 0, 2099);
  if (err_) return {};
  if (y < 100) y += 2000;
  if (y < 1970) fail(Error::out_of_range);
  if (err_) return {};
  if (d > days_in_month(static_cast<int>(y), static_cast<int>(mo))) {
    fail(Error::out_of_range);
    return {};
  }
  return orbit::from_civil(static_cast<int>(y), static_cast<int>(mo), static_cast<int>(d), static_cast<int>(h),
                           static_cast<int>(mi), static_cast<double>(s));
}

}  // namespace tb::satrak::detail
