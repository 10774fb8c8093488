#include "app/pass_plot.h"

#include <cairo-svg.h>
#include <cairo.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

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

void text_at(cairo_t* cr, double x, double y, const std::string& s, double size, bool centre = false) {
  cairo_set_font_size(cr, size);
  cairo_text_extents_t ext;
  cairo_text_extents(cr, s.c_str(), &ext);
  cairo_move_to(cr, centre ? x - ext.width / 2 - ext.x_bearing : x, y);
  cairo_show_text(cr, s.c_str());
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

// Elevation rings every 30 degrees, the horizon heavier; compass lines and letters.
void draw_grid(cairo_t* cr) {
  const double c = kPlotCentre, R = kPlotRadius;
  cairo_set_source_rgb(cr, 0.55, 0.55, 0.55);
  for (int el = 0; el < 90; el += 30) {
    cairo_set_line_width(cr, el == 0 ? 2.0 : 1.0);
    cairo_new_path(cr);  // no line from the last label's end to the ring
    cairo_arc(cr, c, c, R * (90.0 - el) / 90.0, 0, 2 * std::numbers::pi);
    cairo_stroke(cr);
    if (el > 0) text_at(cr, c + 3, c - R * (90.0 - el) / 90.0 - 3, std::to_string(el) + "\xc2\xb0", 11);
  }
  cairo_set_line_width(cr, 1.0);
  cairo_new_path(cr);
  cairo_move_to(cr, c - R, c);
  cairo_line_to(cr, c + R, c);
  cairo_move_to(cr, c, c - R);
  cairo_line_to(cr, c, c + R);
  cairo_stroke(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  text_at(cr, c, c - R - 8, "N", 16, true);
  text_at(cr, c, c + R + 22, "S", 16, true);
  text_at(cr, c + R + 14, c + 6, "E", 16, true);
  text_at(cr, c - R - 14, c + 6, "W", 16, true);
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

// A dot at (az, el) and its label beside it, away from the centre.
void mark(cairo_t* cr, double az, double el, const std::string& label) {
  const double c = kPlotCentre;
  double x, y;
  plot_position(az, std::max(el, -2.0), x, y);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_arc(cr, x, y, 4.5, 0, 2 * std::numbers::pi);
  cairo_fill(cr);
  const double dx = x > c ? -8.0 : 8.0;
  cairo_set_font_size(cr, 12);
  cairo_text_extents_t ext;
  cairo_text_extents(cr, label.c_str(), &ext);
  cairo_move_to(cr, dx < 0 ? x + dx - ext.width : x + dx, y + (y > c ? 16 : -8));
  cairo_show_text(cr, label.c_str());
}

void draw(cairo_t* cr, const PassPicture& p) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  if (p.plan) draw_unreachable(cr, *p.plan);
  draw_grid(cr);

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
  // AOS, TCA, LOS: a dot and the time.
  const orbit::Pass& ps = p.pass;
  mark(cr, ps.aos_az_deg, -2.0, "AOS " + hms(ps.aos));
  mark(cr, ps.tca_az_deg, ps.max_el_deg, "TCA " + hms(ps.tca));
  mark(cr, ps.los_az_deg, -2.0, "LOS " + hms(ps.los));

  // Title and legend.
  cairo_set_source_rgb(cr, 0, 0, 0);
  char head[160];
  std::snprintf(head, sizeof head, "%s  %s UTC  max el %.1f\xc2\xb0", p.title.c_str(),
                orbit::format_iso8601(ps.aos, 0).substr(0, 10).c_str(), ps.max_el_deg);
  text_at(cr, 10, 20, head, 14);
  std::string legend = "blue: satellite";
  if (p.plan) {
    legend += "   orange: antenna";
    if (p.plan->flip) legend += " (over the top)";
    if (!p.plan->coverage.full()) legend += "   red: antenna cannot follow";
  }
  text_at(cr, 10, kPlotSize - 10, legend, 12);
}

}  // namespace

void plot_position(double az_deg, double el_deg, double& x, double& y) {
  const double r = kPlotRadius * (90.0 - el_deg) / 90.0;
  x = kPlotCentre + r * std::sin(az_deg * kDeg);
  y = kPlotCentre - r * std::cos(az_deg * kDeg);
}

std::optional<std::string> write_pass_plot(const PassPicture& p, const std::string& path) {
  const bool svg = ends_with(path, ".svg");
  if (!svg && !ends_with(path, ".png")) return "'" + path + "': expected a name ending .png or .svg";
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
  return std::nullopt;
}

std::vector<rotator::TrackPoint> sample_pass(const orbit::Sgp4& sat, const orbit::Observer& o, const orbit::Pass& p,
                                             double step_s) {
  std::vector<rotator::TrackPoint> out;
  const double span = orbit::minutes_between(p.aos, p.los) * 60.0;
  for (double t = 0.0;; t += step_s) {
    const double at = std::min(t, span);
    const orbit::UtcTime when = orbit::add_seconds(p.aos, at);
    const orbit::Observation ob = orbit::observe(sat, o, when);
    if (ob.ok()) out.push_back({when, ob.look.az_deg, ob.look.el_deg});
    if (at >= span) break;
  }
  return out;
}

}  // namespace tb::app
