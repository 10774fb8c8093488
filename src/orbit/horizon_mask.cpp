#include "orbit/horizon_mask.h"

#include <algorithm>
#include <cmath>
#include <mutex>

#include "util/exact_number.h"
#include "util/safe_text.h"
#include "util/text.h"

namespace tb::orbit {

HorizonMask::HorizonMask(Kind kind, std::vector<MaskPoint> points) : kind_(kind), points_(std::move(points)) {}

double HorizonMask::at(double az_deg) const {
  if (points_.empty()) return -90.0;
  double az = std::fmod(az_deg, 360.0);
  if (az < 0.0) az += 360.0;
  if (kind_ == Kind::stepped) {
    // Each step holds from its azimuth to the next; outside the list (before the first azimuth or
    // from the last), the last step's elevation carries round the circle.
    const std::size_t steps = points_.size() - 1;
    for (std::size_t i = steps; i-- > 0;)
      if (az >= points_[i].az_deg && az < points_[i + 1].az_deg) return points_[i].el_deg;
    return points_[steps - 1].el_deg;
  }
  if (points_.size() == 1) return points_[0].el_deg;
  // Between the two points around az, the last one joined to the first across 360.
  const auto next = std::upper_bound(points_.begin(), points_.end(), az,
                                     [](double a, const MaskPoint& p) { return a < p.az_deg; });
  const MaskPoint& b = next == points_.end() ? points_.front() : *next;
  const MaskPoint& a = next == points_.begin() ? points_.back() : *(next - 1);
  double span = b.az_deg - a.az_deg, off = az - a.az_deg;
  if (span <= 0.0) span += 360.0;
  if (off < 0.0) off += 360.0;
  if (span <= 0.0) return a.el_deg;
  return a.el_deg + (b.el_deg - a.el_deg) * std::min(1.0, off / span);
}

double HorizonMask::min_el() const {
  const std::size_t n = kind_ == Kind::stepped ? points_.size() - 1 : points_.size();
  double lo = 90.0;
  for (std::size_t i = 0; i < n; ++i) lo = std::min(lo, points_[i].el_deg);
  return lo;
}

double HorizonMask::max_el() const {
  const std::size_t n = kind_ == Kind::stepped ? points_.size() - 1 : points_.size();
  double hi = -90.0;
  for (std::size_t i = 0; i < n; ++i) hi = std::max(hi, points_[i].el_deg);
  return hi;
}

std::string HorizonMask::describe() const {
  const std::string range = text::one_decimal(min_el()) + ".." + text::one_decimal(max_el()) + " deg";
  if (kind_ == Kind::stepped)
    return "stepped, " + std::to_string(points_.size() - 1) + " steps, " + range;
  return "interpolated, " + std::to_string(points_.size()) + " points, " + range;
}

std::string HorizonMask::text() const {
  std::string out;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const bool last_step = kind_ == Kind::stepped && i + 1 == points_.size();
    if (i > 0) out += kind_ == Kind::stepped ? " " : "; ";
    out += text::exact_number(points_[i].az_deg);
    if (!last_step) out += " " + text::exact_number(points_[i].el_deg);
  }
  return out;
}

std::shared_ptr<const HorizonMask> shared_horizon_mask(const std::string& text) {
  static std::mutex guard;
  static std::string kept_text;
  static std::shared_ptr<const HorizonMask> kept;
  if (text.empty()) return nullptr;
  const std::lock_guard lock(guard);
  if (text != kept_text || !kept) {
    auto r = read_horizon_mask(text);
    kept = r.mask ? std::make_shared<const HorizonMask>(std::move(*r.mask)) : nullptr;
    kept_text = text;
  }
  return kept;
}

namespace {

// "NAME line N: ", how every refusal begins.
std::string at(std::string_view name, int line) { return std::string(name) + " line " + std::to_string(line) + ": "; }
std::string num(double v) { return text::exact_number(v); }

struct Number {
  double value = 0.0;
  int line = 0;
};

// The numbers of one line (blanks or one comma between them), or the reason it has none.
std::optional<std::string> line_numbers(std::string_view line, int n, std::vector<Number>& out) {
  const bool csv = line.find(',') != std::string_view::npos;
  std::vector<std::string_view> fields;
  if (csv) {
    for (std::string_view f : text::split(line, ',')) fields.push_back(text::trim(f));
  } else {
    while (!(line = text::trim(line)).empty()) {
      const auto end = line.find_first_of(text::kBlanks);
      fields.push_back(line.substr(0, end));
      line = end == std::string_view::npos ? std::string_view{} : line.substr(end);
    }
  }
  for (std::string_view f : fields) {
    const auto v = text::parse_double(f);
    if (!v) return "'" + text::visible_bytes(f) + "' is not a number";
    out.push_back({*v, n});
  }
  if (csv && fields.size() != 2) return std::to_string(fields.size()) + " fields where a CSV line has az,el";
  return std::nullopt;
}

std::optional<std::string> check_points(const std::vector<Number>& nums, std::string_view name,
                                        std::vector<MaskPoint>& out) {
  for (std::size_t i = 0; i < nums.size(); ++i) {
    const bool az = i % 2 == 0;
    const Number& x = nums[i];
    if (az && (x.value < 0.0 || x.value > 360.0))
      return at(name, x.line) + "azimuth " + num(x.value) + " is outside 0..360";
    if (!az && (x.value < -90.0 || x.value > 90.0))
      return at(name, x.line) + "elevation " + num(x.value) + " is outside -90..90";
    if (az && !out.empty() && x.value <= out.back().az_deg)
      return at(name, x.line) + "azimuth " + num(x.value) + " does not follow " + num(out.back().az_deg) +
             " (azimuths increase)";
    if (az) out.push_back({x.value, 0.0});
    else out.back().el_deg = x.value;
  }
  return std::nullopt;
}

}  // namespace

namespace {

MaskReading read_lines(std::string_view text, std::string_view name, bool joined) {
  MaskReading r;
  std::vector<Number> nums;
  bool stepped = false;
  int n = 0, first_data = 0;
  for (std::string_view line : text::split(text, joined ? ';' : '\n')) {
    ++n;
    line = text::trim(line.substr(0, line.find('#')), text::kWhitespace);
    if (line.empty()) continue;
    if (!first_data && text::iequals(text::lower(std::string(line)), "az,el")) continue;  // a CSV's header
    if (!first_data) first_data = n;
    const std::size_t before = nums.size();
    if (auto why = line_numbers(line, n, nums)) {
      r.error = at(name, n) + *why;
      return r;
    }
    // Any line that is not one pair makes the file a step list, its numbers read as one sequence.
    if (nums.size() - before != 2) stepped = true;
  }
  if (nums.empty()) {
    r.error = std::string(name) + ": no points (AZ EL per line, or a step list AZ EL ... AZ)";
    return r;
  }
  if (stepped && nums.size() % 2 == 0) {
    r.error = at(name, nums.back().line) + "a step list ends with an azimuth (AZ EL AZ EL ... AZ): " +
              std::to_string(nums.size()) + " numbers";
    return r;
  }
  std::vector<MaskPoint> points;
  if (auto why = check_points(nums, name, points)) {
    r.error = *why;
    return r;
  }
  if (stepped && points.size() < 2) {
    r.error = at(name, first_data) + "a step list needs at least AZ EL AZ";
    return r;
  }
  r.mask = HorizonMask(stepped ? HorizonMask::Kind::stepped : HorizonMask::Kind::interpolated, std::move(points));
  return r;
}

}  // namespace

MaskReading read_horizon_mask(std::string_view text, std::string_view name) {
  // One line of pairs joined by ';' (what text() writes, a setting typed in): each pair is named.
  const bool joined = text.find('\n') == std::string_view::npos && text.find(';') != std::string_view::npos;
  MaskReading r = read_lines(text, name, joined);
  const std::string line_word = std::string(name) + " line ";
  if (joined && r.error.rfind(line_word, 0) == 0) r.error.replace(0, line_word.size(), std::string(name) + " pair ");
  return r;
}

}  // namespace tb::orbit
