// A pass as a polar plot (issue 30, "pictures of a pass"): the sky seen from the station, north up
// and east right, the horizon the outer circle and the zenith the centre. The satellite's track
// (blue) with AOS, TCA and LOS marked and timed, a tick with the time every minute and an arrow the
// way it goes; azimuth ticks every 10 degrees on the horizon; the antenna's planned path (orange, from the
// rotator's pass plan: flip, limits); the part of the track the antenna cannot follow (red); the
// azimuths the rotator cannot reach (grey); the horizon mask (brown). Drawn with cairo, as PNG or SVG by the file's
// extension.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "orbit/horizon_mask.h"
#include "orbit/passes.h"
#include "rotator/pass_plan.h"

namespace tb::app {

struct PassPicture {
  std::string title;                       // "ISS (ZARYA)"
  std::string station;                     // "27.3910 N 128.6570 E 50 m" (the title's second line)
  std::string element_age;                 // "elements 0.3 days old" (likewise)
  orbit::Pass pass;
  std::vector<rotator::TrackPoint> track;  // AOS to LOS
  std::optional<rotator::PassPlan> plan;   // the antenna's plan, when the rotator is known
  // The station's horizon mask (issue 57), shaded brown from the horizon up to it; AOS and LOS are
  // marked on it.
  std::shared_ptr<const orbit::HorizonMask> mask;
};

inline constexpr int kPlotSize = 640;      // pixels (PNG) or points (SVG), square
inline constexpr double kPlotRadius = 270; // the horizon's radius
inline constexpr double kPlotCentre = 320; // x and y of the zenith

// Pixel position of az/el on the plot (elevations below 0 lie outside the horizon circle).
void plot_position(double az_deg, double el_deg, double& x, double& y);

// A label's box (x, y its top left; pixels). place_label: where `want` goes so that it touches
// none of `placed` (labels_touch): moved down by its own height until it is clear (AOS, TCA and
// LOS of a short pass near the horizon would otherwise be written over each other).
struct LabelBox {
  double x = 0, y = 0, w = 0, h = 0;
};
// Words side by side keep this far apart (pixels), or they read as one ("TCA 10:49:50 10:50").
inline constexpr double kLabelGap = 3.0;
// Whether a and b overlap, or stand closer than kLabelGap side by side.
bool labels_touch(const LabelBox& a, const LabelBox& b);
LabelBox place_label(const std::vector<LabelBox>& placed, LabelBox want);

// The reason a --plot name cannot be written (it must end .png or .svg, any case); nothing when it can.
std::optional<std::string> plot_name_problem(const std::string& path);

// Writes the picture to `path` (.png or .svg); the reason when it cannot. In SVG the words are
// <text> elements (selectable, searchable), not glyph outlines, each held to the width cairo measured
// when it was placed (textLength), so that labels kept apart stay apart in any viewer's font.
std::optional<std::string> write_pass_plot(const PassPicture& p, const std::string& path);

// Samples a pass every `step_s` seconds from AOS to LOS (LOS included), and every second near its
// culmination (rotator::pass_sample_times).
std::vector<rotator::TrackPoint> sample_pass(const orbit::Sgp4& sat, const orbit::Observer& o, const orbit::Pass& p,
                                             double step_s = 5.0);

}  // namespace tb::app
