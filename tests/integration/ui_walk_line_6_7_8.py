"""Menus 6 (6-0 display, 6-3 dead band and skew, 6-6 direct control with presets, 6-4 parking and
limits, 6-9 default parameters with the station file upload), 7 (host mode) and 8 (direct antenna
control) on the real binary over a serial line at 9600 bps (socat pty pair), with the stored state
checked after each change and after SIGTERM.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import _walk as w  # noqa: E402
from _tbharness import SerialSession, check, factory_state, load_state, run_test  # noqa: E402


def main():
    factory = factory_state()
    s = SerialSession()
    try:
        ui = s.ui
        ui.prompt(w.MAIN, timeout=15)
        ui.send("6\r")
        out = ui.prompt(w.UPDATE)
        w.must(out, r"====== Configuration Menu ======\n 0\. Display all configured value\n", "menu 6's list")
        w.must(out, r" 9\. Set default parameter\n Select:", "menu 6's list ends with 9")

        w.walk_6_0(ui, w.FACTORY_6_0)
        w.walk_6_3(ui)
        rot = load_state(s.state_file)["rotator"]
        check((rot["az_dead_band"], rot["el_dead_band"]) == (5, 3), f"6-3 saved at once: {rot}")

        w.walk_6_6(ui)
        ui.prompt(w.UPDATE)
        data = load_state(s.state_file)
        check(data["rotor_control"] is True, "Y to 'Switch rotor control ON' is stored")
        check(data["rotator"]["presets"] == [[float(a), float(e)] for a, e in w.PRESETS], "presets stored")

        ui.send("Q\r")
        ui.prompt(w.MAIN)
        w.walk_menu_8(ui)

        ui.send("6\r")
        ui.prompt(w.UPDATE)
        w.walk_6_4(ui)
        w.check_rotator_after_6(load_state(s.state_file)["rotator"])
        w.walk_6_0(ui, w.AFTER_6_4)
        ui.send("Q\r")
        ui.prompt(w.MAIN)

        w.walk_menu_7(ui)

        ui.send("6\r")
        ui.prompt(w.UPDATE)
        w.walk_6_9(ui)
        data = load_state(s.state_file)
        st, rot, radio = data["station"], data["rotator"], data["radio"]
        check(st["callsign"] == "WA7GXD" and (st["lat_deg"], st["lon_deg"], st["height_m"]) == (32.259, -110.778, 842),
              f"line 1 of the station file: {st}")
        check(rot["az_span"] == [3, 1017] and rot["el_span"] == [5, 454], f"line 2 (ADC counts): {rot}")
        check((rot["az_dead_band"], rot["el_dead_band"], rot["az_skew"], rot["el_skew"]) == (5, 3, 0, 0), "line 3")
        check(radio["rig"] == "icom" and radio["cat_policy"] == "aos_only" and
              (radio["icom_rx_address"], radio["icom_tx_address"]) == (0x10, 0x14), f"line 4: {radio}")
        check(rot["parking_enabled"] and rot["parking"] == [90.0, 0.0] and rot["limits_enabled"] and
              (rot["az_limit_min"], rot["az_limit_max"], rot["el_limit_min"], rot["el_limit_max"]) ==
              (270.0, 90.0, 0.0, 45.0), f"line 5 (degrees): {rot}")
        check(rot["presets"] == factory["rotator"]["presets"], "6-9 reset the presets of 6-6-3")
        check(data["db"]["satellites"] == [] and data["db"]["selected"] == [], "6-9: the kepele database is lost")
        check(data["rotor_control"] is False, "6-9: rotor control back to its default (off)")

        w.walk_6_9_bad(ui)
        ui.send("Q\r")
        ui.prompt(w.MAIN)
        check("\x07" in s.term.transcript, "6-9 sends a beep tone")
        check("\x1b" not in s.term.transcript, "no escape codes on a serial line")
        code = s.tb.stop()
        check(code == 0, f"exit status {code} after SIGTERM")
        data = load_state(s.state_file)
        # A refused station file leaves every parameter at its factory value, the database empty.
        for part in ("station", "rotator", "radio"):
            check(data[part] == factory[part], f"after a refused station file {part} is the factory one:\n"
                  f"{data[part]}\n{factory[part]}")
        check(data["db"]["satellites"] == [] and data["rotor_control"] is False, "defaults after 6-9")
    finally:
        s.close()


if __name__ == "__main__":
    run_test(main)
