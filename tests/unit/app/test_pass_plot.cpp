// The pass plot (issue 30): a PNG of the size asked, with the track's pixels where the pass puts
// the satellite (SGP4's az/el at times between AOS and LOS, mapped north up, east right, the
// horizon at the plot radius) and the sky away from the track left white.
#include <doctest/doctest.h>

#include <cairo.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/pass_plot.h"
#include "orbit/elements.h"
#include "orbit/sgp4.h"
#include "rotator/adc_model.h"
#include "test_paths.h"

#include <unistd.h>

using namespace tb;

namespace {
struct Rgb {
  int r, g, b;
};
Rgb pixel(cairo_surface_t* s, double x, double y) {
  const unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  const auto px = reinterpret_cast<const std::uint32_t*>(data + static_cast<int>(std::lround(y)) * stride)[std::lround(x)];
  return {static_cast<int>((px >> 16) & 0xFF), static_cast<int>((px >> 8) & 0xFF), static_cast<int>(px & 0xFF)};
}
}  // namespace

TEST_CASE("pass plot: a PNG with the track where the pass predicts it") {
  const auto sets = orbit::load_elements_file(std::string(TRAKBOX_SOURCE_DIR) + "/data/amateur.tle");
  const orbit::Elements* iss = nullptr;
  for (const auto& e : sets.sets)
    if (e.catalog_number == 25544) iss = &e;
  REQUIRE(iss);
  const orbit::Sgp4 sat(*iss);
  const orbit::Observer station{27.391, 128.657, 50.0};
  const auto pass = orbit::next_pass(sat, station, orbit::from_civil(2026, 5, 21, 13, 30, 0));
  REQUIRE(pass);
  app::PassPicture pic;
  pic.title = "ISS";
  pic.pass = *pass;
  pic.track = app::sample_pass(sat, station, *pass);
  pic.plan = rotator::plan_pass(pic.track, rotator::PassGeometry::from(rotator::AdcModel(
                                               rotator::RotatorConfig{}, station::RotorStart::south)),
                                std::nullopt);
  const auto path = std::filesystem::temp_directory_path() / ("trakbox-plot-" + std::to_string(::getpid()) + ".png");
  REQUIRE_FALSE(app::write_pass_plot(pic, path.string()));
  std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> png(
      cairo_image_surface_create_from_png(path.c_str()), cairo_surface_destroy);
  std::filesystem::remove(path);
  REQUIRE(cairo_surface_status(png.get()) == CAIRO_STATUS_SUCCESS);
  CHECK(cairo_image_surface_get_width(png.get()) == app::kPlotSize);
  CHECK(cairo_image_surface_get_height(png.get()) == app::kPlotSize);
  // The track: blue at the satellite's place a quarter, half and three quarters through the pass
  // (away from the AOS/TCA/LOS dots).
  for (const double f : {0.25, 0.4, 0.65, 0.8}) {
    const auto t = orbit::add_seconds(pass->aos, f * orbit::minutes_between(pass->aos, pass->los) * 60.0);
    const orbit::Observation o = orbit::observe(sat, station, t);
    double x, y;
    app::plot_position(o.look.az_deg, o.look.el_deg, x, y);
    const Rgb c = pixel(png.get(), x, y);
    CAPTURE(f);
    CAPTURE(x);
    CAPTURE(y);
    CHECK(c.b > 150);
    CHECK(c.r < 80);
  }
  // Where the pass never goes: the zenith (max el 22.3) and the point opposite TCA are white.
  for (const auto& [az, el] : {std::pair{0.0, 90.0}, std::pair{pass->tca_az_deg + 180.0, pass->max_el_deg}}) {
    double x, y;
    app::plot_position(az, el, x, y);
    const Rgb c = pixel(png.get(), x + 5, y + 5);
    CHECK(c.r == 255);
    CHECK(c.g == 255);
    CHECK(c.b == 255);
  }
  // The plot's geometry: north up, east right, the horizon at the radius.
  double x, y;
  app::plot_position(90.0, 0.0, x, y);
  CHECK(x == doctest::Approx(app::kPlotCentre + app::kPlotRadius));
  CHECK(y == doctest::Approx(app::kPlotCentre));
  app::plot_position(0.0, 45.0, x, y);
  CHECK(x == doctest::Approx(app::kPlotCentre));
  CHECK(y == doctest::Approx(app::kPlotCentre - app::kPlotRadius / 2));
}

TEST_CASE("pass plot: SVG by the extension, and a name without one refused") {
  app::PassPicture pic;
  pic.title = "none";
  const auto path = std::filesystem::temp_directory_path() / ("trakbox-plot-" + std::to_string(::getpid()) + ".svg");
  REQUIRE_FALSE(app::write_pass_plot(pic, path.string()));
  CHECK(std::filesystem::file_size(path) > 500);
  std::filesystem::remove(path);
  const auto err = app::write_pass_plot(pic, "/tmp/plot.gif");
  REQUIRE(err);
  CHECK(err->find(".png or .svg") != std::string::npos);
}

namespace {
std::string slurp(const std::filesystem::path& p) {
  std::FILE* f = std::fopen(p.c_str(), "rb");
  REQUIRE(f);
  std::string s;
  char buf[8192];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) s.append(buf, n);
  std::fclose(f);
  return s;
}

// The ISS pass of 2026-05-21 after 13:30 over the factory station, as `passes --plot` draws it.
struct IssPicture {
  orbit::Elements iss;
  orbit::Observer station{27.391, 128.657, 50.0};
  app::PassPicture pic;
  IssPicture() {
    const auto sets = orbit::load_elements_file(std::string(TRAKBOX_SOURCE_DIR) + "/data/amateur.tle");
    for (const auto& e : sets.sets)
      if (e.catalog_number == 25544) iss = e;
    const orbit::Sgp4 sat(iss);
    const auto pass = orbit::next_pass(sat, station, orbit::from_civil(2026, 5, 21, 13, 30, 0));
    REQUIRE(pass);
    pic.title = "ISS <A&B>";  // outside text: escaped in the SVG
    pic.station = "station 27.3910 N 128.6570 E 50 m";
    pic.element_age = "elements age 0.4 days at AOS";
    pic.pass = *pass;
    pic.track = app::sample_pass(sat, station, *pass);
  }
};
}  // namespace

TEST_CASE("pass plot: the SVG's words are <text> (selectable), with the station, the element age, minute and azimuth ticks (issue 39)") {
  IssPicture p;
  const auto path = std::filesystem::temp_directory_path() / ("trakbox-plot-text-" + std::to_string(::getpid()) + ".svg");
  REQUIRE_FALSE(app::write_pass_plot(p.pic, path.string()));
  const std::string svg = slurp(path);
  std::filesystem::remove(path);
  CHECK(svg.find("glyph") == std::string::npos);  // no outlines of letters
  CHECK(svg.find(">ISS &lt;A&amp;B&gt;  2026-05-21 UTC  max el ") != std::string::npos);
  // Two lines (on one they ran under the compass N).
  CHECK(svg.find(" y=\"38.00\" font-size=\"11.0\"") != std::string::npos);
  CHECK(svg.find(">station 27.3910 N 128.6570 E 50 m</text>") != std::string::npos);
  CHECK(svg.find(" y=\"52.00\" font-size=\"11.0\"") != std::string::npos);
  CHECK(svg.find(">elements age 0.4 days at AOS</text>") != std::string::npos);
  for (const char* word : {">N</text>", ">E</text>", ">S</text>", ">W</text>", ">30</text>", ">330</text>", ">AOS "})
    CHECK_MESSAGE(svg.find(word) != std::string::npos, word);
  // A minute label every other minute along the track: the first even minute after AOS.
  auto m = std::chrono::ceil<std::chrono::minutes>(p.pic.pass.aos);
  if (std::chrono::duration_cast<std::chrono::minutes>(m.time_since_epoch()).count() % 2) m += std::chrono::minutes(1);
  const std::string hhmm = ">" + orbit::format_iso8601(m, 0).substr(11, 5) + "</text>";
  CHECK_MESSAGE(svg.find(hhmm) != std::string::npos, hhmm);
  CHECK(svg.rfind("</svg>") > svg.rfind("</text>"));
}

TEST_CASE("pass plot: an arrow the way the satellite moves, at the middle of the pass (issue 39)") {
  IssPicture p;
  const auto path = std::filesystem::temp_directory_path() / ("trakbox-plot-arrow-" + std::to_string(::getpid()) + ".png");
  REQUIRE_FALSE(app::write_pass_plot(p.pic, path.string()));
  std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> png(
      cairo_image_surface_create_from_png(path.c_str()), cairo_surface_destroy);
  std::filesystem::remove(path);
  REQUIRE(cairo_surface_status(png.get()) == CAIRO_STATUS_SUCCESS);
  // Across the track 2.5 px either side at the arrow (the middle sample; the 3 px track reaches
  // 1.5 px): blue; 3.5 px off the plain track at a quarter: white.
  auto across = [&](std::size_t i, double side) {
    double x0, y0, x1, y1;
    app::plot_position(p.pic.track[i - 1].az_deg, p.pic.track[i - 1].el_deg, x0, y0);
    app::plot_position(p.pic.track[i].az_deg, p.pic.track[i].el_deg, x1, y1);
    const double len = std::hypot(x1 - x0, y1 - y0);
    return pixel(png.get(), x1 - (y1 - y0) / len * side, y1 + (x1 - x0) / len * side);
  };
  const std::size_t mid = p.pic.track.size() / 2;
  for (const double side : {-2.5, 2.5}) {
    const Rgb at_arrow = across(mid, side);
    CHECK(at_arrow.b > 150);
    CHECK(at_arrow.r < 80);
  }
  // Away from the arrow and from the minute ticks (at the first sample of each minute).
  auto minute_of = [&](std::size_t i) { return std::chrono::floor<std::chrono::minutes>(p.pic.track[i].time); };
  std::size_t i = p.pic.track.size() / 4;
  while (minute_of(i - 2) != minute_of(i + 2)) ++i;
  const Rgb plain = across(i, -3.5);  // (the minute labels are on the other side)
  CHECK(plain.r > 200);
}

TEST_CASE("plot labels: a label that would cover another moves just below it, as often as needed") {
  using tb::app::LabelBox;
  using tb::app::place_label;
  std::vector<LabelBox> placed;
  // Nothing placed: where it was wanted.
  LabelBox a = place_label(placed, {100, 200, 80, 14});
  CHECK(a.y == 200);
  placed.push_back(a);
  // Overlapping AOS by 6 px: moved to AOS's bottom edge (214).
  LabelBox b = place_label(placed, {150, 206, 80, 14});
  CHECK(b.x == 150);
  CHECK(b.y == 214);
  placed.push_back(b);
  // Over both: below the second (228).
  LabelBox c = place_label(placed, {120, 203, 60, 14});
  CHECK(c.y == 228);
  // Beside them (no horizontal overlap): stays.
  CHECK(place_label(placed, {300, 206, 50, 14}).y == 206);
  // Side by side closer than kLabelGap (3 px) touches: "TCA 10:49:50" and a minute label 1 px
  // after it read as one.
  CHECK(tb::app::labels_touch({100, 200, 80, 14}, {181, 200, 30, 14}));
  CHECK_FALSE(tb::app::labels_touch({100, 200, 80, 14}, {183, 200, 30, 14}));
  CHECK_FALSE(tb::app::labels_touch({100, 200, 80, 14}, {100, 214, 30, 14}));   // the line below
}
