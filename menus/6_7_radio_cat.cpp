// 6-7: Radio CAT port configuration. Chooses the CAT protocol (Kenwood, Yaesu, Icom, or N for none,
// an addition), the Icom CI-V addresses, the FT-736 wide FM filter, which Doppler corrections are
// sent and whether CAT runs the full orbit or only at AOS. The serial device itself comes from the
// command line (--radio cat:DEVICE builds the driver for the rig chosen here when trakbox starts);
// the corrections and F/A apply at once. trakbox's additions at the first question: D turns dial
// follow on linear transponders on or off, U names a second radio for the uplink (a spec as
// --uplink-radio takes: a model of the radio registry, a family, Hamlib) or none, L lists the radio
// registry (radio/registry.h, as trakbox --radio list), P sets the operating practice (the knob's rest
// before the other link moves, the least Doppler change sent for SSB/CW and for FM); D, U and P apply
// at once.
#include <cctype>
#include <charconv>
#include <cstdio>

#include "menus/6_configuration.h"
#include "radio/cat.h"
#include "radio/factory.h"
#include "radio/registry.h"
#include "store/model.h"
#include "store/settings.h"
#include "tracker/station_loop.h"

namespace tb::menus {

namespace {

std::string hex2(std::uint8_t v) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%02X", v);
  return buf;
}

// A CI-V address: one or two hex digits with an optional H, 00 to DF (E0 is TrakBox's own, and
// FD/FE frame the messages).
std::uint8_t ask_address(term::Terminal& t, const char* which, std::uint8_t current) {
  for (;;) {
    std::string a = cfg::answer(t, std::string("Enter destination Address for ") + which + " (" + hex2(current) + ") ");
    if (a.empty()) return current;
    std::string_view v(a);
    if (v.back() == 'H' || v.back() == 'h') v.remove_suffix(1);
    int n = 0;
    const auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), n, 16);
    if (!v.empty() && v.size() <= 2 && ec == std::errc() && p == v.data() + v.size() && n < radio::icom::kController)
      return static_cast<std::uint8_t>(n);
    t.line("  '" + a + "' is not a CI-V address: expected hex 00 to DF (E0 is TrakBox's own)");
  }
}

// Operating practice: how long the knob must rest before the other link moves, and the least
// Doppler change sent per mode, each in the settings table's range. Applied at once.
void edit_practice(term::Terminal& t, Services& s, radio::RadioConfig& c) {
  radio::RadioConfig r = s.model.radio;
  const store::Bounds rest = store::bounds("radio.dial_rest_ms"), ssb = store::bounds("radio.doppler_step_ssb_hz"),
                      fm = store::bounds("radio.doppler_step_fm_hz");
  r.dial_rest_ms = static_cast<int>(cfg::ask_number(t, "Knob rest before the other link moves, ms (0-10000) ? ",
                                                    r.dial_rest_ms, rest.lo, rest.hi, true));
  r.doppler_step_ssb_hz = static_cast<radio::Hz>(cfg::ask_number(
      t, "Least Doppler change sent, SSB/CW, Hz (10-1000) ? ", static_cast<double>(r.doppler_step_ssb_hz), ssb.lo, ssb.hi, true));
  r.doppler_step_fm_hz = static_cast<radio::Hz>(cfg::ask_number(
      t, "Least Doppler change sent, FM, Hz (10-10000) ? ", static_cast<double>(r.doppler_step_fm_hz), fm.lo, fm.hi, true));
  if (!commit(t, s, store::bit(store::Area::radio), "menu 6-7 practice", [&](store::Model& m) { m.radio = r; })) return;
  c.dial_rest_ms = r.dial_rest_ms;
  c.doppler_step_ssb_hz = r.doppler_step_ssb_hz;
  c.doppler_step_fm_hz = r.doppler_step_fm_hz;
}

}  // namespace

void menu_6_7_radio_cat(term::Terminal& t, Services& s) {
  radio::RadioConfig c = s.model.radio;
  const radio::RadioConfig before = c;
  t.line(std::string("Now: ") + radio::to_string(c.rig) + (c.cat_policy == radio::CatPolicy::aos_only ? " AOS" : " Full") +
         "   (N: no CAT rig, Q: leave unchanged)");
  auto extras = [&] {
    t.line(std::string("Dial follow ") + (s.model.radio.dial_follow ? "ON" : "OFF") + "   Uplink radio: " +
           (s.model.radio.uplink_radio.empty() ? "none (one radio)" : s.model.radio.uplink_radio) +
           "   (D: dial follow on/off, U: uplink radio, L: radio list)");
    t.line("Knob rest " + std::to_string(s.model.radio.dial_rest_ms) + " ms   Doppler step SSB/CW " +
           std::to_string(s.model.radio.doppler_step_ssb_hz) + " Hz, FM " + std::to_string(s.model.radio.doppler_step_fm_hz) +
           " Hz   (P: change them)");
  };
  extras();
  char rig = 0;
  while (!rig) {
    const char k = cfg::ask_choice(t, "CAT Rig KENWOOD,YAESU,ICOM [K/Y/I] ? ", "KYINDULP");
    if (k == 'P') {
      edit_practice(t, s, c);
      extras();
    } else if (k == 'D') {
      if (commit(t, s, store::bit(store::Area::radio), std::string(tracker::kDialFollowEdit),
                 [&](store::Model& m) { m.radio.dial_follow = !m.radio.dial_follow; })) {
        c.dial_follow = s.model.radio.dial_follow;
        s.station.tuner().set_config(s.model.radio);
      }
      extras();
    } else if (k == 'L') {   // the radio registry, as trakbox --radio list prints it
      std::string list = radio::radio_list_text();
      for (std::size_t at = 0, nl; at < list.size(); at = nl + 1) {
        nl = list.find('\n', at);
        if (nl == std::string::npos) nl = list.size();
        t.line(list.substr(at, nl - at));
      }
      extras();
    } else if (k == 'U') {
      const std::string spec =
          cfg::answer(t, "Uplink radio, as --radio (a model of the list L such as ft817:DEV, or icom:DEV, hamlib:MODEL:DEV, "
                         "rigctld:HOST:PORT ...; none) ? ");
      const std::string next = spec == "none" ? "" : spec;
      if (const auto parsed = radio::parse_radio_spec(next, "uplink radio"); !next.empty() && !parsed.spec) {
        t.line("  " + parsed.error);
      } else if (!spec.empty()) {
        radio::MakeRadio made;
        if (!next.empty()) made = radio::make_radio(*parsed.spec, s.model.radio, {}, radio::RadioRole::uplink);
        if (!next.empty() && !made.driver) {
          t.line("  " + made.error);
        } else {
          if (commit(t, s, store::bit(store::Area::radio), "uplink radio",
                     [&](store::Model& m) { m.radio.uplink_radio = next; })) {
            c.uplink_radio = next;
            s.station.set_uplink_radio(std::move(made.driver));
            t.line("Radio: " + s.station.radio().describe());
          }
        }
      }
      extras();
    } else {
      rig = k;
    }
  }
  switch (rig) {
    case 'K': c.rig = radio::Rig::kenwood; break;
    case 'Y': c.rig = radio::Rig::yaesu; break;
    case 'I': c.rig = radio::Rig::icom; break;
    default: c.rig = radio::Rig::none; break;
  }
  if (c.rig == radio::Rig::icom) {
    t.line("IC-275:10H IC-375/475:14H IC-970:2EH IC-271:20H IC-371/471:22H");
    c.icom_rx_address = ask_address(t, "RX", c.icom_rx_address);
    c.icom_tx_address = ask_address(t, "TX", c.icom_tx_address);
  }
  if (c.rig == radio::Rig::yaesu)
    c.ft736_wide_fm = cfg::ask_choice(t, "FT-736 FM filter changed for a wider one (UO-22) ? [Y/N] ", "YN") == 'Y';
  c.uplink_correction = cfg::ask_choice(t, "Uplink Doppler correction ? [Y/N] ", "YN") == 'Y';
  switch (cfg::ask_choice(t, "Downlink Doppler correction ? [Y/N/R] ", "YNR")) {
    case 'Y': c.downlink_correction = radio::DownlinkCorrection::on; break;
    case 'R': c.downlink_correction = radio::DownlinkCorrection::reverse; break;
    default: c.downlink_correction = radio::DownlinkCorrection::off; break;
  }
  c.cat_policy = cfg::ask_choice(t, "Select Full orbit or AOS CAT control ? [F/A] ", "FA") == 'F'
                     ? radio::CatPolicy::full_orbit
                     : radio::CatPolicy::aos_only;
  if (!commit(t, s, store::bit(store::Area::radio), "menu 6-7", [&](store::Model& m) { m.radio = c; })) return;
  t.line("Radio: " + s.station.radio().describe());
  if (c.rig != before.rig || c.icom_rx_address != before.icom_rx_address ||
      c.icom_tx_address != before.icom_tx_address || c.ft736_wide_fm != before.ft736_wide_fm)
    t.line("The new rig settings reach the radio driver when trakbox next starts (--radio cat:DEVICE).");
}

}  // namespace tb::menus
