// SGP4/SDP4 against Vallado's verification set (SGP4-VER.TLE, tcppver.out from Debian's
// python3-sgp4), plus focused cases with values computed independently by python-sgp4.
#include <doctest/doctest.h>
#include "test_paths.h"  // TRAKBOX_SOURCE_DIR, ...

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "orbit/elements.h"
#include "orbit/sgp4.h"
#include "support/gpredict_sets.h"

using namespace tb::orbit;
using tb::testing::iss_2018;
using tb::testing::make_elements;
using tb::testing::molniya_2018;

namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  REQUIRE_MESSAGE(in.good(), "cannot read " << path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

// One line of tcppver.out: minutes since epoch, position (km), velocity (km/s).
struct StateLine {
  double tsince;
  double rv[6];
};

// A satellite's block in tcppver.out: its "<satnum> xx" header and its state lines.
struct ExpectedBlock {
  int satnum = 0;
  std::vector<StateLine> lines;
};

std::vector<ExpectedBlock> read_tcppver(const std::string& path) {
  std::vector<ExpectedBlock> blocks;
  for (const std::string& line : split_lines(read_file(path))) {
    if (line.find("xx") != std::string::npos) {
      ExpectedBlock b;
      b.satnum = std::stoi(line);
      blocks.push_back(b);
      continue;
    }
    if (line.find_first_not_of(' ') == std::string::npos) continue;
    REQUIRE_MESSAGE(!blocks.empty(), "state line before any header: " << line);
    StateLine s{};
    std::istringstream in(line);
    in >> s.tsince >> s.rv[0] >> s.rv[1] >> s.rv[2] >> s.rv[3] >> s.rv[4] >> s.rv[5];
    REQUIRE_MESSAGE(!in.fail(), "unreadable state line: " << line);
    blocks.back().lines.push_back(s);
  }
  return blocks;
}

// Start, stop and step (minutes) that SGP4-VER.TLE appends after column 69 of each line 2.
struct TimeSpan {
  double start, stop, step;
};

std::vector<TimeSpan> read_time_spans(const std::string& text) {
  std::vector<TimeSpan> spans;
  for (const std::string& line : split_lines(text)) {
    if (line.rfind("2 ", 0) != 0) continue;
    REQUIRE(line.size() > 69);
    TimeSpan s{};
    std::istringstream in(line.substr(69));
    in >> s.start >> s.stop >> s.step;
    REQUIRE_MESSAGE(!in.fail(), "no start/stop/step on: " << line);
    spans.push_back(s);
  }
  return spans;
}

struct ErrorSeen {
  int satnum;
  Sgp4Error error;
  double tsince;
};

}  // namespace

TEST_CASE("SGP4 reproduces Vallado's tcppver.out for all 33 verification sets") {
  const std::string tle_path = TRAKBOX_SGP4_DATA_DIR "/SGP4-VER.TLE";
  const std::string tle_text = read_file(tle_path);
  const ParseResult parsed = parse_nasa(tle_text, tle_path, ParseOptions{.verify_checksums = false});
  const std::vector<TimeSpan> spans = read_time_spans(tle_text);
  const std::vector<ExpectedBlock> expected = read_tcppver(TRAKBOX_SGP4_DATA_DIR "/tcppver.out");
  REQUIRE(parsed.sets.size() == 33);
  REQUIRE(spans.size() == parsed.sets.size());
  REQUIRE(expected.size() == parsed.sets.size());

  std::size_t state_lines = 0;
  for (const ExpectedBlock& b : expected) state_lines += b.lines.size();

  constexpr double kTolerance = 2e-7;  // km and km/s, as python-sgp4's own test
  std::size_t compared = 0;
  double max_position_error = 0.0;
  double max_velocity_error = 0.0;
  std::string worst_position;  // where max_position_error was seen
  std::vector<ErrorSeen> errors;
  StateLine previous{};  // the reference program prints its last good state when t = 0 fails

  for (std::size_t i = 0; i < parsed.sets.size(); ++i) {
    const Elements& elements = parsed.sets[i];
    const ExpectedBlock& block = expected[i];
    CAPTURE(elements.catalog_number);
    REQUIRE(elements.catalog_number == block.satnum);
    const Sgp4 sat(elements);
    std::size_t next = 0;

    auto compare = [&](const StateLine& got) {
      REQUIRE_MESSAGE(next < block.lines.size(), "more output than tcppver.out at t=" << got.tsince);
      const StateLine& want = block.lines[next++];
      CAPTURE(want.tsince);
      CHECK(std::fabs(got.tsince - want.tsince) < kTolerance);
      for (int k = 0; k < 6; ++k) {
        const double err = std::fabs(got.rv[k] - want.rv[k]);
        CHECK_MESSAGE(err < kTolerance, "component " << k << ": got " << got.rv[k] << ", want "
                                                     << want.rv[k]);
        if (k < 3 && err > max_position_error) {
          max_position_error = err;
          worst_position = std::to_string(block.satnum) + " at t=" + std::to_string(want.tsince);
        }
        if (k >= 3) max_velocity_error = std::max(max_velocity_error, err);
      }
      ++compared;
    };
    auto state_at = [&](double t, const Propagation& p) {
      StateLine s{t, {p.state.r_km[0], p.state.r_km[1], p.state.r_km[2], p.state.v_km_s[0],
                      p.state.v_km_s[1], p.state.v_km_s[2]}};
      return s;
    };
    // Propagates to t and compares; false (and the error recorded) when SGP4 refuses.
    auto step = [&](double t) {
      const Propagation p = sat.propagate_minutes(t);
      if (!p.ok()) {
        errors.push_back({elements.catalog_number, p.error, t});
        return false;
      }
      previous = state_at(t, p);
      compare(previous);
      return true;
    };

    const Propagation at_epoch = sat.propagate_minutes(0.0);
    CHECK(at_epoch.error == sat.init_error());
    if (!at_epoch.ok()) {
      errors.push_back({elements.catalog_number, at_epoch.error, 0.0});
      StateLine stale = previous;
      stale.tsince = 0.0;
      compare(stale);
    } else {
      previous = state_at(0.0, at_epoch);
      compare(previous);
      const TimeSpan& span = spans[i];
      double t = span.start;
      bool failed = false;
      while (t <= span.stop) {
        if (!(t == span.start && span.start == 0.0) && !step(t)) {
          failed = true;
          break;
        }
        t += span.step;
      }
      if (!failed && t - span.stop < span.step - 1e-6) step(span.stop);
    }
    CHECK_MESSAGE(next == block.lines.size(), "tcppver.out has " << block.lines.size()
                                                                 << " lines, produced " << next);
  }

  CHECK(compared == state_lines);
  CHECK(state_lines == 667);
  MESSAGE("tcppver.out: " << compared << " state lines compared; max |dr| = " << max_position_error
                          << " km (" << worst_position << "), max |dv| = " << max_velocity_error
                          << " km/s");

  const std::vector<ErrorSeen> want_errors = {
      {22312, Sgp4Error::mean_eccentricity, 494.2028672},
      {28350, Sgp4Error::mean_eccentricity, 1560.0},
      {28872, Sgp4Error::decayed, 55.0},
      {29141, Sgp4Error::decayed, 440.0},
      {33333, Sgp4Error::semi_latus_rectum, 25.0},
      {33334, Sgp4Error::perturbed_eccentricity, 0.0},
      {20413, Sgp4Error::decayed, 1844345.0},
  };
  REQUIRE(errors.size() == want_errors.size());
  for (std::size_t k = 0; k < errors.size(); ++k) {
    CAPTURE(k);
    CHECK(errors[k].satnum == want_errors[k].satnum);
    CHECK(errors[k].error == want_errors[k].error);
    CHECK(errors[k].tsince == doctest::Approx(want_errors[k].tsince).epsilon(1e-9));
  }
}

namespace {

// Values below come from Debian's python3-sgp4 2.15 (a separate implementation of the same paper):
//   /usr/bin/python3 -c 'from sgp4.api import Satrec, WGS72
//     s = Satrec.twoline2rv(L1, L2, WGS72); print(s.sgp4_tsince(0.0), s.no_unkozai, s.a,
//     s.altp * s.radiusearthkm, s.alta * s.radiusearthkm, s.jdsatepoch, s.jdsatepochF)'
// with the two element sets of Debian gpredict's satellites.dat in tests/support/gpredict_sets.h.

void check_state(const Propagation& p, const Vec3& r, const Vec3& v) {
  REQUIRE(p.ok());
  for (int k = 0; k < 3; ++k) {
    CHECK(std::fabs(p.state.r_km[k] - r[k]) < 1e-8);
    CHECK(std::fabs(p.state.v_km_s[k] - v[k]) < 1e-11);
  }
}

}  // namespace

TEST_CASE("Near-earth set at epoch and after 1000 minutes agrees with python-sgp4") {
  const Sgp4 sat(iss_2018());
  CHECK(sat.init_error() == Sgp4Error::none);
  CHECK_FALSE(sat.deep_space());
  check_state(sat.propagate_minutes(0.0), {-20.314287227236353, 4643.403562446339, 4932.52142131598},
              {-6.938734108007585, -2.401148423763746, 2.2287655921251206});
  check_state(sat.propagate_minutes(1000.0), {6026.504784633851, 3090.0292477120606, -353.3527280930272},
              {-1.9021976955192201, 4.3790296017768515, 6.003752674393402});
  CHECK(sat.mean_motion_rad_per_min() == doctest::Approx(0.0678067732383622).epsilon(1e-14));
  CHECK(sat.semi_major_axis_er() == doctest::Approx(1.063500739910827).epsilon(1e-14));
  CHECK(sat.perigee_km() == doctest::Approx(402.5431547901696).epsilon(1e-12));
  CHECK(sat.apogee_km() == doctest::Approx(407.48942871211483).epsilon(1e-12));
  CHECK(sat.period_minutes() == doctest::Approx(2.0 * std::numbers::pi / 0.0678067732383622).epsilon(1e-14));
  CHECK(sat.epoch_jd().whole == 2458138.5);
  CHECK(sat.epoch_jd().fraction == doctest::Approx(0.89808844).epsilon(1e-13));
  CHECK(sat.epoch() == from_year_day(2018, 20.89808844));
}

TEST_CASE("Deep-space resonant set at epoch and after 1000 minutes agrees with python-sgp4") {
  const Sgp4 sat(molniya_2018());
  CHECK(sat.init_error() == Sgp4Error::none);
  CHECK(sat.deep_space());
  check_state(sat.propagate_minutes(0.0), {-13322.868072997519, 16157.217157452547, 14587.805539639601},
              {-1.9098226896805612, -0.10661247938974983, 3.545357364668382});
  check_state(sat.propagate_minutes(1000.0), {-21067.40343868286, -3886.8841745809323, 40735.00967480089},
              {0.47741610693271186, -1.4438915983091156, -0.009283411567508512});
  CHECK(sat.mean_motion_rad_per_min() == doctest::Approx(0.008751699198886674).epsilon(1e-14));
  CHECK(sat.semi_major_axis_er() == doctest::Approx(4.164136208078709).epsilon(1e-14));
  CHECK(sat.perigee_km() == doctest::Approx(660.6910622003136).epsilon(1e-11));
  CHECK(sat.apogee_km() == doctest::Approx(39701.88472482788).epsilon(1e-12));
}

TEST_CASE("Propagation is a pure function of the time: call order and copies do not matter") {
  const Sgp4 sat(molniya_2018());
  const Propagation far = sat.propagate_minutes(20000.0);
  const Propagation back = sat.propagate_minutes(-3000.0);
  const Propagation near = sat.propagate_minutes(1000.0);
  const Sgp4 copy = sat;  // NOLINT(performance-unnecessary-copy-initialization)
  const Sgp4 fresh(molniya_2018());
  REQUIRE(far.ok());
  REQUIRE(back.ok());
  REQUIRE(near.ok());
  for (const Sgp4* s : {&sat, &copy, &fresh}) {
    const Propagation a = s->propagate_minutes(1000.0);
    const Propagation b = s->propagate_minutes(20000.0);
    const Propagation c = s->propagate_minutes(-3000.0);
    CHECK(a.state.r_km == near.state.r_km);
    CHECK(a.state.v_km_s == near.state.v_km_s);
    CHECK(b.state.r_km == far.state.r_km);
    CHECK(c.state.r_km == back.state.r_km);
  }
}

TEST_CASE("propagate(UtcTime) is propagate_minutes of the minutes since epoch") {
  const Sgp4 sat(iss_2018());
  const UtcTime t = add_minutes(sat.epoch(), 90.5);
  const Propagation a = sat.propagate(t);
  const Propagation b = sat.propagate_minutes(minutes_between(sat.epoch(), t));
  REQUIRE(a.ok());
  CHECK(a.state.r_km == b.state.r_km);
  CHECK(a.state.v_km_s == b.state.v_km_s);
}

TEST_CASE("Element sets SGP4 cannot use are refused at construction") {
  SUBCASE("eccentricity 1 or more") {
    Elements e = iss_2018();
    e.eccentricity = 1.0;
    const Sgp4 sat(e);
    CHECK(sat.init_error() == Sgp4Error::mean_eccentricity);
    CHECK(sat.propagate_minutes(10.0).error == Sgp4Error::mean_eccentricity);
    CHECK(std::isnan(sat.semi_major_axis_er()));
  }
  SUBCASE("negative eccentricity") {
    Elements e = iss_2018();
    e.eccentricity = -0.01;
    CHECK(Sgp4(e).init_error() == Sgp4Error::mean_eccentricity);
  }
  SUBCASE("mean motion zero, negative or not a number") {
    for (double n : {0.0, -1.0, std::nan("")}) {
      Elements e = iss_2018();
      e.mean_motion_rev_per_day = n;
      const Sgp4 sat(e);
      CHECK(sat.init_error() == Sgp4Error::mean_motion);
      const Propagation p = sat.propagate_minutes(0.0);
      CHECK_FALSE(p.ok());
      CHECK(p.error == Sgp4Error::mean_motion);
    }
  }
  SUBCASE("perturbed eccentricity out of range at epoch (Vallado's 33334)") {
    const Elements e = make_elements("MOLNIYA 1-53", 13070, 2006, 174.85818871, 0.00000620, 0.1e-3, 68.4714,
                                      236.1303, 0.5602877, 123.7484, 302.5767, 0.00001000);
    const Sgp4 sat(e);
    CHECK(sat.init_error() == Sgp4Error::perturbed_eccentricity);
    CHECK(sat.propagate_minutes(100.0).error == Sgp4Error::perturbed_eccentricity);
  }
}

TEST_CASE("Every error code has its own description") {
  const Sgp4Error all[] = {Sgp4Error::none, Sgp4Error::mean_eccentricity, Sgp4Error::mean_motion,
                           Sgp4Error::perturbed_eccentricity, Sgp4Error::semi_latus_rectum,
                           Sgp4Error::decayed};
  std::vector<std::string> seen;
  for (Sgp4Error e : all) {
    const std::string text = describe(e);
    CHECK_FALSE(text.empty());
    CHECK(std::find(seen.begin(), seen.end(), text) == seen.end());
    seen.push_back(text);
  }
  CHECK(std::string(describe(Sgp4Error::decayed)).find("decayed") != std::string::npos);
}
