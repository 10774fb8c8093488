#include "cli/pass_plot.h"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <vector>

#include "orbit/observe.h"

namespace tb::app {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

std::string hms(orbit::UtcTime t) { return orbit::format_iso8601(t, 0).substr(11, 8); }

bool ends_with(const std::string& s, const char* tail) {
  const std::string t(tail);
  if (s.size() < t.size()) return false;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - t.size() + i])) != t[i]) return false;
  return true;
}

// Words on the plot. In a PNG cairo draws them; in an SVG they are kept here and written as <text>
// elements once cairo has finished the file (cairo's SVG surface writes glyph outlines, which no
// one can select or search).
struct Label {
  double x, y, size;
  double width;   // cairo's advance: the SVG text is held to it (textLength), as it was placed
  double r, g, b;
  std::string text;
};
thread_local std::vector<Label>* svg_labels = nullptr;

void show_text(cairo_t* cr, double x, double y, const std::string& s) {
  if (!svg_labels) {
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, s.c_str());
    return;
  }
  cairo_matrix_t font;
  cairo_get_font_matrix(cr, &font);
  double r = 0, g = 0, b = 0, a = 1;
  cairo_pattern_get_rgba(cairo_get_source(cr), &r, &g, &b, &a);
  cairo_text_extents_t ext;
  cairo_text_extents(cr, s.c_str(), &ext);
  svg_labels->push_back({x, y, font.yy, ext.x_advance, r, g, b, s});
}

// The box of `s` written from baseline (x, y) at `size`: its advance wide, the line's height
// (0.8 of the size above the baseline, 0.25 below, whatever the glyphs) high.
LabelBox text_box(cairo_t* cr, double x, double y, const std::string& s, double size) {
  cairo_text_extents_t ext;
  cairo_text_extents(cr, s.c_str(), &ext);
  return {x, y - 0.8 * size, ext.x_advance, 1.05 * size};
}

bool clear_of(const std::vector<LabelBox>& placed, const LabelBox& b) {
  return std::none_of(placed.begin(), placed.end(), [&](const LabelBox& p) { return labels_touch(p, b); });
}

// Writes `s` (centred on x, or from it); its box joins `placed` when given.
void text_at(cairo_t* cr, double x, double y, const std::string& s, double size, bool centre = false,
             std::vector<LabelBox>* placed = nullptr) {
  cairo_set_font_size(cr, size);
  cairo_text_extents_t ext;
  cairo_text_extents(cr, s.c_str(), &ext);
  const double from = centre ? x - ext.width / 2 - ext.x_bearing : x;
  show_text(cr, from, y, s);
  if (placed) placed->push_back(text_box(cr, from, y, s, size));
}

std::string xml_escaped(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// The kept words into the SVG cairo wrote, before its closing tag.
std::optional<std::string> add_svg_labels(const std::string& path, const std::vector<Label>& labels) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return "'" + path + "': cannot read back";
  std::string svg;
  char buf[8192];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) svg.append(buf, n);
  std::fclose(f);
  const std::size_t end = svg.rfind("</svg>");
  if (end == std::string::npos) return "'" + path + "': cairo wrote no </svg>";
  std::string words = "<g font-family=\"sans-serif\">\n";
  for (const Label& l : labels) {
    char head[256];
    std::snprintf(head, sizeof head,
                  "<text x=\"%.2f\" y=\"%.2f\" font-size=\"%.1f\" textLength=\"%.2f\" lengthAdjust=\"spacingAndGlyphs\" "
                  "fill=\"rgb(%d,%d,%d)\">",
                  l.x, l.y, l.size, l.width, static_cast<int>(l.r * 255 + 0.5), static_cast<int>(l.g * 255 + 0.5),
                  static_cast<int>(l.b * 255 + 0.5));
    words += head + xml_escaped(l.text) + "</text>\n";
  }
  words += "</g>\n";
  svg.insert(end, words);
  f = std::fopen(path.c_str(), "wb");
  if (!f) return "'" + path + "': cannot write";
  const bool ok = std::fwrite(svg.data(), 1, svg.size(), f) == svg.size();
  if (std::fclose(f) != 0 || !ok) return "'" + path + "': write failed";
  return std::nullopt;
}

void polyline(cairo_t* cr, const std::vector<std::pair<double, double>>& pts) {
  for (std::size_t i = 0; i < pts.size(); ++i) {
    double x, y;
    plot_position(pts[i].first, pts[i].second, x, y);
    if (i == 0) cairo_move_to(cr, x, y);
    else cairo_line_to(cr, x, y);
  }
}

// Azimuths the rotator cannot reach: a grey wedge outside its travel.
void draw_unreachable(cairo_t* cr, const rotator::PassPlan& plan) {
  const double c = kPlotCentre;
  const auto& g = plan.geometry;
  const double width = g.az_travel.width();
  if (!g.az_travel.empty() && width < 360.0 - 1e-9) {
    const double lo = g.az_travel.hi + rotator::rotor_start_deg(g.start);  // unreachable from hi ...
    const double span = 360.0 - width;                                     // ... to lo + 360
    cairo_move_to(cr, c, c);
    for (int i = 0; i <= 64; ++i) {
      double x, y;
      plot_position(lo + span * i / 64.0, 0.0, x, y);
      cairo_line_to(cr, x, y);
    }
    cairo_close_path(cr);
    cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
    cairo_fill(cr);
  }
}

// The horizon mask: from the horizon up to the mask's elevation at each azimuth (a degree apart, and
// either side of each of its points, so that a step stands upright).
void draw_mask(cairo_t* cr, const orbit::HorizonMask& m) {
  std::vector<double> az;
  for (int a = 0; a <= 360; ++a) az.push_back(a);
  for (const auto& pt : m.points())
    for (const double d : {-1e-6, 1e-6}) az.push_back(std::clamp(pt.az_deg + d, 0.0, 360.0));
  std::sort(az.begin(), az.end());
  cairo_new_path(cr);
  for (std::size_t i = 0; i < az.size(); ++i) {
    double x, y;
    plot_position(az[i], std::max(0.0, m.at(az[i])), x, y);
    if (i == 0) cairo_move_to(cr, x, y);
    else cairo_line_to(cr, x, y);
  }
  cairo_close_path(cr);
  const double c = kPlotCentre;
  cairo_new_sub_path(cr);
  cairo_arc_negative(cr, c, c, kPlotRadius, 0.0, -2 * std::numbers::pi);
  cairo_close_path(cr);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  cairo_set_source_rgba(cr, 0.55, 0.35, 0.15, 0.35);
  cairo_fill(cr);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
}

// Elevation rings every 30 degrees, the horizon heavier; compass lines and letters.
void draw_grid(cairo_t* cr, std::vector<LabelBox>& placed) {
  const double c = kPlotCentre, R = kPlotRadius;
  cairo_set_source_rgb(cr, 0.55, 0.55, 0.55);
  for (int el = 0; el < 90; el += 30) {
    cairo_set_line_width(cr, el == 0 ? 2.0 : 1.0);
    cairo_new_path(cr);  // no line from the last label's end to the ring
    cairo_arc(cr, c, c, R * (90.0 - el) / 90.0, 0, 2 * std::numbers::pi);
    cairo_stroke(cr);
    if (el > 0) text_at(cr, c + 3, c - R * (90.0 - el) / 90.0 - 3, std::to_string(el) + "\xc2\xb0", 11, false, &placed);
  }
  cairo_set_line_width(cr, 1.0);
  cairo_new_path(cr);
  cairo_move_to(cr, c - R, c);
  cairo_line_to(cr, c + R, c);
  cairo_move_to(cr, c, c - R);
  cairo_line_to(cr, c, c + R);
  cairo_stroke(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  text_at(cr, c, c - R - 8, "N", 16, true, &placed);
  text_at(cr, c, c + R + 22, "S", 16, true, &placed);
  text_at(cr, c + R + 14, c + 6, "E", 16, true, &placed);
  text_at(cr, c - R - 14, c + 6, "W", 16, true, &placed);
}

// Where the antenna cannot follow: red over the track.
void draw_lost(cairo_t* cr, const PassPicture& p) {
  cairo_set_source_rgb(cr, 0.85, 0.0, 0.0);
  cairo_set_line_width(cr, 3.0);
  bool open = false;
  for (const auto& t : p.track) {
    const bool lost = p.plan->lost_at(t.az_deg, t.el_deg);
    double x, y;
    plot_position(t.az_deg, std::max(t.el_deg, -2.0), x, y);
    if (lost && !open) cairo_move_to(cr, x, y);
    if (lost) cairo_line_to(cr, x, y);
    if (!lost && open) cairo_stroke(cr);
    open = lost;
  }
  if (open) cairo_stroke(cr);
}

}  // namespace

bool labels_touch(const LabelBox& a, const LabelBox& b) {
  const double g = kLabelGap;
  return a.x < b.x + b.w + g && b.x < a.x + a.w + g && a.y < b.y + b.h && b.y < a.y + a.h;
}

LabelBox place_label(const std::vector<LabelBox>& placed, LabelBox want) {
  for (int tries = 0; tries < 16; ++tries) {
    const auto hit = std::find_if(placed.begin(), placed.end(), [&](const LabelBox& p) { return labels_touch(p, want); });
    if (hit == placed.end()) break;
    want.y = hit->y + hit->h;   // just below the one it would cover
  }
  return want;
}

namespace {

// A dot at (az, el) and its label beside it, away from the centre, clear of the labels placed.
void mark(cairo_t* cr, double az, double el, const std::string& label, std::vector<LabelBox>& placed) {
  const double c = kPlotCentre;
  double x, y;
  plot_position(az, std::max(el, -2.0), x, y);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_arc(cr, x, y, 4.5, 0, 2 * std::numbers::pi);
  cairo_fill(cr);
  const double dx = x > c ? -8.0 : 8.0;
  cairo_set_font_size(cr, 12);
  const double base = y + (y > c ? 16 : -8);
  LabelBox want = text_box(cr, x + dx, base, label, 12);
  if (dx < 0) want.x -= want.w;
  const LabelBox box = place_label(placed, want);
  placed.push_back(box);
  show_text(cr, box.x, box.y + 0.8 * 12, label);
}

// Azimuth ticks on the horizon every 10 degrees (longer every 30, numbered between the compass letters).
void draw_azimuth_ticks(cairo_t* cr, std::vector<LabelBox>& placed) {
  const double c = kPlotCentre, R = kPlotRadius;
  cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
  cairo_set_line_width(cr, 1.0);
  for (int az = 0; az < 360; az += 10) {
    const double len = az % 30 == 0 ? 10.0 : 5.0;
    const double sx = std::sin(az * kDeg), sy = -std::cos(az * kDeg);
    cairo_move_to(cr, c + R * sx, c + R * sy);
    cairo_line_to(cr, c + (R + len) * sx, c + (R + len) * sy);
  }
  cairo_stroke(cr);
  for (int az = 30; az < 360; az += 30) {
    if (az % 90 == 0) continue;  // N, E, S, W are written
    const double sx = std::sin(az * kDeg), sy = -std::cos(az * kDeg);
    text_at(cr, c + (R + 22) * sx, c + (R + 22) * sy + 4, std::to_string(az), 10, true, &placed);
  }
}

// The satellite's time along its track: a tick across it every minute, the minute written every
// other one (every 5 for a long pass) where it covers no other word, and an arrow the way it moves
// at the middle of the pass.
void draw_time_ticks(cairo_t* cr, const PassPicture& p, std::vector<LabelBox>& placed) {
  if (p.track.size() < 2) return;
  const double minutes = orbit::minutes_between(p.track.front().time, p.track.back().time);
  const int label_every = minutes > 20 ? 5 : 2;
  cairo_set_source_rgb(cr, 0.0, 0.2, 0.85);
  cairo_set_line_width(cr, 2.0);
  const auto xy = [](const rotator::TrackPoint& t, double& x, double& y) {
    plot_position(t.az_deg, std::max(t.el_deg, -2.0), x, y);
  };
  for (std::size_t i = 1; i < p.track.size(); ++i) {
    const auto m0 = std::chrono::floor<std::chrono::minutes>(p.track[i - 1].time);
    const auto m1 = std::chrono::floor<std::chrono::minutes>(p.track[i].time);
    if (m1 == m0) continue;  // a new minute starts between these two samples: tick at the later one
    double x0, y0, x1, y1;
    xy(p.track[i - 1], x0, y0);
    xy(p.track[i], x1, y1);
    const double len = std::hypot(x1 - x0, y1 - y0);
    if (len < 1e-6) continue;
    const double nx = -(y1 - y0) / len * 6.0, ny = (x1 - x0) / len * 6.0;  // across the track
    cairo_move_to(cr, x1 - nx, y1 - ny);
    cairo_line_to(cr, x1 + nx, y1 + ny);
    cairo_stroke(cr);
    const auto minute = std::chrono::duration_cast<std::chrono::minutes>(m1.time_since_epoch()).count() % 60;
    if (minute % label_every != 0) continue;
    const std::string hm = orbit::format_iso8601(m1, 0).substr(11, 5);
    cairo_set_font_size(cr, 10);
    if (clear_of(placed, text_box(cr, x1 + nx * 1.6 + 2, y1 + ny * 1.6 + 4, hm, 10)))
      text_at(cr, x1 + nx * 1.6 + 2, y1 + ny * 1.6 + 4, hm, 10, false, &placed);
  }
  // The arrow: at the middle sample, pointing along the track.
  const std::size_t mid = p.track.size() / 2;
  double x0, y0, x1, y1;
  xy(p.track[mid - 1], x0, y0);
  xy(p.track[mid], x1, y1);
  const double len = std::hypot(x1 - x0, y1 - y0);
  if (len < 1e-6) return;
  const double ux = (x1 - x0) / len, uy = (y1 - y0) / len;
  cairo_move_to(cr, x1 + ux * 9, y1 + uy * 9);
  cairo_line_to(cr, x1 - ux * 7 - uy * 7, y1 - uy * 7 + ux * 7);
  cairo_line_to(cr, x1 - ux * 7 + uy * 7, y1 - uy * 7 - ux * 7);
  cairo_close_path(cr);
  cairo_fill(cr);
}

// The title, the station and elements line, and the legend.
void draw_words(cairo_t* cr, const PassPicture& p, std::vector<LabelBox>& placed) {
  const orbit::Pass& ps = p.pass;
  cairo_set_source_rgb(cr, 0, 0, 0);
  char head[160];
  std::snprintf(head, sizeof head, "%s  %s UTC  max el %.1f\xc2\xb0", p.title.c_str(),
                orbit::format_iso8601(ps.aos, 0).substr(0, 10).c_str(), ps.max_el_deg);
  text_at(cr, 10, 20, head, 14, false, &placed);
  // Where from and how old the elements are: a picture kept without its command line says both.
  // On two lines: on one they ran under the compass N.
  double y = 38;
  for (const std::string* line : {&p.station, &p.element_age})
    if (!line->empty()) {
      text_at(cr, 10, y, *line, 11, false, &placed);
      y += 14;
    }
  std::string legend = "blue: satellite";
  if (p.plan) {
    legend += "   orange: antenna";
    if (p.plan->flip) legend += " (over the top)";
    if (!p.plan->coverage.full()) legend += "   red: antenna cannot follow";
  }
  if (p.mask) legend += "   brown: horizon mask";
  text_at(cr, 10, kPlotSize - 10, legend, 12, false, &placed);
}

void draw(cairo_t* cr, const PassPicture& p) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  if (p.plan) draw_unreachable(cr, *p.plan);
  if (p.mask) draw_mask(cr, *p.mask);
  // Every word's box: the minute labels skip a place taken, AOS/TCA/LOS move clear (issue 47:
  // TCA's time was written over a minute label and the compass letters on a low pass).
  std::vector<LabelBox> placed;
  draw_grid(cr, placed);
  draw_azimuth_ticks(cr, placed);
  draw_words(cr, p, placed);

  std::vector<std::pair<double, double>> track;
  for (const auto& t : p.track) track.emplace_back(t.az_deg, std::max(t.el_deg, -2.0));
  // The antenna's planned path (under the track where it follows it).
  if (p.plan && !p.track.empty()) {
    std::vector<std::pair<double, double>> ant;
    for (const auto& t : p.track) {
      const rotator::AzEl a = p.plan->pointing_at(t.az_deg, t.el_deg);
      ant.emplace_back(a.az, std::max(a.el, -2.0));
    }
    cairo_set_source_rgba(cr, 1.0, 0.55, 0.0, 0.8);
    cairo_set_line_width(cr, 9.0);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    polyline(cr, ant);
    cairo_stroke(cr);
  }
  // The track.
  cairo_set_source_rgb(cr, 0.0, 0.2, 0.85);
  cairo_set_line_width(cr, 3.0);
  polyline(cr, track);
  cairo_stroke(cr);
  if (p.plan) draw_lost(cr, p);
  // AOS, TCA, LOS: a dot and the time, placed before the minute labels, which give way.
  const orbit::Pass& ps = p.pass;
  // AOS and LOS where they are: on the mask where it is higher than the -2 deg rule.
  const auto floor_at = [&p](double az) { return p.mask ? std::max(-2.0, p.mask->at(az)) : -2.0; };
  mark(cr, ps.aos_az_deg, floor_at(ps.aos_az_deg), "AOS " + hms(ps.aos), placed);
  mark(cr, ps.tca_az_deg, ps.max_el_deg, "TCA " + hms(ps.tca), placed);
  mark(cr, ps.los_az_deg, floor_at(ps.los_az_deg), "LOS " + hms(ps.los), placed);
  draw_time_ticks(cr, p, placed);
}


}  // namespace

void plot_position(double az_deg, double el_deg, double& x, double& y) {
  const double r = kPlotRadius * (90.0 - el_deg) / 90.0;
  x = kPlotCentre + r * std::sin(az_deg * kDeg);
  y = kPlotCentre - r * std::cos(az_deg * kDeg);
}

std::optional<std::string> plot_name_problem(const std::string& path) {
  if (ends_with(path, ".svg") || ends_with(path, ".png")) return std::nullopt;
  return "'" + path + "': expected a name ending .png or .svg";
}

std::optional<std::string> write_pass_plot(const PassPicture& p, const std::string& path) {
  const bool svg = ends_with(path, ".svg");
  if (auto why = plot_name_problem(path)) return why;
  std::vector<Label> labels;
  svg_labels = svg ? &labels : nullptr;
  struct Reset {
    ~Reset() { svg_labels = nullptr; }
  } reset;
  cairo_surface_t* surface = svg ? cairo_svg_surface_create(path.c_str(), kPlotSize, kPlotSize)
                                 : cairo_image_surface_create(CAIRO_FORMAT_RGB24, kPlotSize, kPlotSize);
  std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> s(surface, cairo_surface_destroy);
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS)
    return "'" + path + "': " + cairo_status_to_string(cairo_surface_status(surface));
  cairo_t* cr = cairo_create(surface);
  draw(cr, p);
  const cairo_status_t drawn = cairo_status(cr);
  cairo_destroy(cr);
  if (drawn != CAIRO_STATUS_SUCCESS) return "'" + path + "': " + cairo_status_to_string(drawn);
  cairo_surface_flush(surface);
  if (!svg) {
    const cairo_status_t w = cairo_surface_write_to_png(surface, path.c_str());
    if (w != CAIRO_STATUS_SUCCESS) return "'" + path + "': " + cairo_status_to_string(w);
  }
  cairo_surface_finish(surface);
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS)
    return "'" + path + "': " + cairo_status_to_string(cairo_surface_status(surface));
  if (svg) return add_svg_labels(path, labels);
  return std::nullopt;
}

std::vector<rotator::TrackPoint> sample_pass(const orbit::Sgp4& sat, const orbit::Observer& o, const orbit::Pass& p,
                                             double step_s) {
  std::vector<rotator::TrackPoint> out;
  for (const orbit::UtcTime when : rotator::pass_sample_times(p.aos, p.tca, p.los, step_s)) {
    const orbit::Observation ob = orbit::observe(sat, o, when);
    if (ob.ok()) out.push_back({when, ob.look.az_deg, ob.look.el_deg});
  }
  return out;
}

}  // namespace tb::app
