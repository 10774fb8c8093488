// The pass plot (issue 30): a PNG of the size asked, with the track's pixels where the pass puts
// the satellite (SGP4's az/el at times between AOS and LOS, mapped north up, east right, the
// horizon at the plot radius) and the sky away from the track left white.
#include <doctest/doctest.h>

#include <cairo.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/pass_plot.h"
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
