// 6-6 Direct antenna control (also menu 8): 1 keyboard control, 2 enter a direction, 3 presets.
// Direct control stops tracking (StationLoop::point / stop_antenna do that) and stays inside the
// rotation limits (the rotator controller clamps every target and keyboard drive to them). It moves
// the antenna only with rotor control on: when it is off the operator is asked to switch it on.
#include <cctype>
#include <cmath>

#include "menus/6_configuration.h"
#include "rotator/controller.h"
#include "store/model.h"
#include "tracker/station_loop.h"

namespace tb::menus {

namespace {


// Points at a compass position and watches it go there; says so when the limits moved the target.
void go_to(term::Terminal& t, Services& s, rotator::AzEl where) {
  const rotator::AzEl got = s.station.point(where);
  if (rotator::azimuth_distance(got.az, where.az) > 0.05 || std::abs(got.el - where.el) > 0.05)
    t.line("Limited to Az " + cfg::fmt1(got.az) + " El " + cfg::fmt1(got.el) + " (antenna rotation limit)");
  cfg::watch_until_arrived(t, s);
}

}  // namespace

void menu_6_6_direct_control(term::Terminal& t, Services& s) {
  auto show = [&] {
    t.line("1.Direct rotor control from key board.");
    t.line("2.Enter direction value.");
    t.line("3.Preset Control.");
  };
  run_menu(t, show, "Select[1-3,Q]:", [&](char key) {
    if (key == 'Q') return MenuStep::back;
    try {
      switch (key) {
        case '1': menu_6_6_1_keyboard(t, s); break;
        case '2': menu_6_6_2_enter_value(t, s); break;
        case '3': menu_6_6_3_presets(t, s); break;
        default: return MenuStep::unknown;
      }
    } catch (const cfg::Quit&) {
      t.end_live();
    }
    return MenuStep::again;
  });
}

void menu_6_6_1_keyboard(term::Terminal& t, Services& s) {
  cfg::take_rotor_control(t, s);
  s.station.stop_antenna();  // tracking stops; nothing moves until a key says so
  t.line("Left(4),Right(6),Up(8),Dwn(2),Stop(5)or Ret");
  cfg::LiveMonitor m(t, s);
  for (;;) {
    const int k = m.key();
    if (k == term::kTimeout) continue;
    if (k == term::kEnter || k == '\n' || k == 'q' || k == 'Q') break;
    if (k > 0 && k < 128) s.station.rotator().manual_key(static_cast<char>(k));
  }
  s.station.stop_antenna();  // leaving keyboard control: motion stopped
  m.update();
}

void menu_6_6_2_enter_value(term::Terminal& t, Services& s) {
  cfg::take_rotor_control(t, s);
  const auto now = s.station.antenna();
  const double el_top = 90.0;
  const auto az = cfg::ask_number(t, "Azimuth: " + (now ? cfg::fmt1(now->az) : std::string("---.-")) + "  ",
                                  now ? std::optional(now->az) : std::nullopt, 0.0, 360.0);
  const auto el = cfg::ask_number(t, "Elevation: " + (now ? cfg::fmt1(now->el) : std::string("--.-")) + "  ",
                                  now ? std::optional(now->el) : std::nullopt, 0.0, el_top);
  go_to(t, s, {az, el});
}

void menu_6_6_3_presets(term::Terminal& t, Services& s) {
  auto show = [&] {
    for (const auto& l : preset_lines(s.model.rotator)) t.line(l);
  };
  run_menu(t, show, " Select[1-5,S,Q]: ", [&](char key) {
    if (key == 'Q') return MenuStep::back;
    if (key == 'S') {
      rotator::RotatorConfig c = s.model.rotator;
      for (std::size_t i = 0; i < c.presets.size(); ++i) {
        auto& p = c.presets[i];
        const std::string head = " Preset position " + std::to_string(i + 1) + " ";
        p.az = cfg::ask_number(t, head + "Az: " + cfg::fmt1(p.az) + "  ", p.az, 0.0, 360.0);
        p.el = cfg::ask_number(t, std::string(head.size(), ' ') + "El: " + cfg::fmt1(p.el) + "  ", p.el, 0.0,
                               c.el_top_deg());
      }
      cfg::commit_rotator(t, s, c);
      return MenuStep::again;
    }
    if (key < '1' || key > '5') return MenuStep::unknown;
    cfg::take_rotor_control(t, s);
    go_to(t, s, s.model.rotator.presets[static_cast<std::size_t>(key - '1')]);
    return MenuStep::again;
  });
}

}  // namespace tb::menus
