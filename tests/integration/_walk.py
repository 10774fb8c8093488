"""The manual's transcripts for menus 2, 3-1..3-4, 6 (6-0, 6-3, 6-4, 6-6, 6-9), 7, 8 and M, written
once against the UI interface of _tbharness (LineUI: a serial line; ScreenUI: full screen in tmux)
and walked by the ui_walk_* tests on the real binary.

A walkthrough sends what an operator types, waits at each prompt the manual prints, and checks what
the terminal showed on the way; the tests check the stored state afterwards. Key conventions: '\\r'
is Enter, '\\x1a' Ctrl-Z; [Y/N] questions take one key without Enter (docs/menus/README.md).
"""
import os
import sys

from _tbharness import check, factory_state, load_state, read_tle, run_test  # noqa: E402
from _tbui import ScreenSession, SerialSession  # noqa: E402
from _walk_steps import (DATA, MAIN, UPDATE, must)  # noqa: E402
from _walk_menus_2_3 import (check_state_after_3, start_upload, walk_menu_2, walk_menu_3_1,
                             walk_menu_3_2, walk_menu_3_4,
                             walk_upload_amsat, walk_upload_failures,
                             walk_upload_nasa)  # noqa: E402
from _walk_menus_6_m import (AFTER_6_4, FACTORY_6_0, PRESETS, check_rotator_after_6, start_6_9,
                             walk_6_0, walk_6_3, walk_6_4, walk_6_6,
                             walk_6_9, walk_6_9_bad, walk_menu_7,
                             walk_menu_8, walk_menu_m)  # noqa: E402

# What the ui_walk_* tests and firmware_files.py reach as _walk.NAME.
__all__ = ["DATA", "MAIN", "UPDATE", "must", "start_6_9", "start_upload", "group_2_3", "group_6_7_8", "group_m",
           "screen_test", "walk_serial"]


def group_2_3(s, page_rows):
    """Menus 2, 3-1, 3-2, 3-4, 3-3 (NASA + freq/mode, failures, AMSAT), the state after each."""
    ui = s.ui
    ui.prompt(MAIN, timeout=15)
    names = [n for n, _, _ in read_tle(os.path.join(DATA, "amateur.tle"))]

    walk_menu_2(ui, page_rows)

    walk_menu_3_1(ui)
    data = load_state(s.state_file)  # saved after the change, before the next prompt
    check(data["db"]["marked"] == 0 and data["rotor_control"] is False,
          "menu 2 tracked nothing: the '*' stays on AO-07, rotor control off")
    ao73 = data["db"]["satellites"][6]
    check(ao73["elements"]["name"] == "AO-73", f"#7 is AO-73: {ao73['elements']['name']}")
    check(ao73["elements"]["revolution"] == 67560 and ao73["elements"]["inclination_deg"] == 97.83,
          f"3-1 stored K0 and I0: {ao73['elements']}")
    check(ao73["elements"]["eccentricity"] == 0.0034836, "the refused eccentricity left the stored one")
    check(ao73["radio"]["downlink_hz"] == 145_987_000 and ao73["radio"]["uplink_hz"] == 435_016_000,
          f"3-1 stored F1 and F2 exactly: {ao73['radio']}")
    check((ao73["radio"]["downlink_mode"], ao73["radio"]["uplink_mode"]) == ("fm", "fm"), "modes")
    check(ao73["radio"]["doppler"] != "cat" and ao73["radio"]["lcd_ma_display"] is True,
          f"Mic-click and LCD MA: {ao73['radio']}")

    walk_menu_3_2(ui, [4, 2, 3, 7], names)
    data = load_state(s.state_file)
    check(data["db"]["selected"] == [3, 1, 2, 6], f"the tracking list in the order chosen: {data['db']}")
    check(data["db"]["marked"] == 3, "the '*' on the last satellite chosen (#4, AO-73), as 3-2 showed it")

    walk_menu_3_4(ui, 3, 4)
    before_uploads = load_state(s.state_file)
    check(before_uploads["db"]["multi_count"] == 3, "3-4 stored")

    walk_upload_nasa(ui)
    data = load_state(s.state_file)
    sats = data["db"]["satellites"]
    check([x["elements"]["name"] for x in sats] == names, "the uploaded NASA file is the database")
    check(all(x["elements"]["source"] == "nasa" for x in sats), "NASA sets")
    check(sats[6]["elements"]["revolution"] == 67551, "AO-73's elements are the uploaded ones again")
    check(sats[6]["radio"]["downlink_hz"] == 145_987_000, "AO-73's radio entry (3-1) kept by name")
    check(data["db"]["selected"] == [3, 1, 9, 0], f"the list in the freq/mode file's order: {data['db']}")
    qo100 = sats[9]["radio"]
    check(qo100["downlink_hz"] == 10_489_550_000 and qo100["downlink_offset_hz"] == -9_750_000_000,
          f"QO-100's converter offset: {qo100}")

    stored = open(s.state_file, "rb").read()
    walk_upload_failures(ui)
    check(open(s.state_file, "rb").read() == stored, "failed uploads leave the state file byte for byte")

    walk_upload_amsat(ui)
    ui.send("Q\r")
    ui.prompt(MAIN)

    code = s.stop()
    check(code == 0, f"exit status {code} after leaving")
    check_state_after_3(load_state(s.state_file), before_uploads)


def group_6_7_8(s):
    """Menus 6-0, 6-3, 6-6, 8, 6-4, 7, 6-9 (good and bad station files), the state after each."""
    factory = factory_state()
    ui = s.ui
    ui.prompt(MAIN, timeout=15)
    ui.send("6\r")
    out = ui.prompt(UPDATE)
    must(out, r"====== Configuration Menu ======\n 0\. Display all configured value\n", "menu 6's list")
    must(out, r" 9\. Set default parameter\n R\. Rotor control \(kept over a restart\)\n Select:",
         "menu 6's list: 9, then trakbox's R")

    walk_6_0(ui, FACTORY_6_0)
    walk_6_3(ui)
    rot = load_state(s.state_file)["rotator"]
    check((rot["az_dead_band"], rot["el_dead_band"]) == (5, 3), f"6-3 saved at once: {rot}")

    walk_6_6(ui)
    ui.prompt(UPDATE)
    data = load_state(s.state_file)
    check(data["rotor_control"] is True, "rotor control taken by 6-6-2 is stored")
    check(data["rotator"]["presets"] == [[float(a), float(e)] for a, e in PRESETS], "presets stored")

    ui.send("Q\r")
    ui.prompt(MAIN)
    walk_menu_8(ui)

    ui.send("6\r")
    ui.prompt(UPDATE)
    walk_6_4(ui)
    check_rotator_after_6(load_state(s.state_file)["rotator"])
    walk_6_0(ui, AFTER_6_4)
    ui.send("Q\r")
    ui.prompt(MAIN)

    walk_menu_7(ui)

    ui.send("6\r")
    ui.prompt(UPDATE)
    walk_6_9(ui)
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

    walk_6_9_bad(ui)
    ui.send("Q\r")
    ui.prompt(MAIN)
    code = s.stop()
    check(code == 0, f"exit status {code} after leaving")
    data = load_state(s.state_file)
    # A refused station file leaves every parameter at its factory value, the database empty.
    for part in ("station", "rotator", "radio"):
        check(data[part] == factory[part], f"after a refused station file {part} is the factory one:\n"
              f"{data[part]}\n{factory[part]}")
    check(data["db"]["satellites"] == [] and data["rotor_control"] is False, "defaults after 6-9")


def group_m(s):
    """Menu M after 3-2 and 3-4, times set with menu 5; the state after leaving."""
    ui = s.ui
    ui.prompt(MAIN, timeout=15)
    names = [n for n, _, _ in read_tle(os.path.join(DATA, "amateur.tle"))]
    walk_menu_m(ui, names)
    code = s.stop()
    check(code == 0, f"exit status {code} after leaving")
    data = load_state(s.state_file)
    db = data["db"]
    check(db["selected"] == [3, 1, 2] and db["multi_count"] == 3, f"3-2 and 3-4: {db['selected']}")
    check(db["marked"] == 0, "the LCD satellite (#1, the ISS) is the marked one")
    check(data["priority_mode"] is True, "priority mode, the last choice, is stored")
    check(data["rotor_control"] is True, "M switches rotor control on (E twice left it on)")
    check(data["clock_offset_us"] != 0, "menu 5 stored the clock")


# ---------------------------------------------------------------------------------------------
# How the ui_walk_* tests run a group: on a fresh session of one front end, closed whatever happens.

# Limits that split the travel may be crossed between passes (see walk 6-4).
CROSSING = ("--cross-limit-sector", "yes")


def walk_serial(group, *args, transcript_checks=(), **kwargs):
    """The group over a serial line (socat pty pair, 9600 bps), then the rules of a serial terminal:
    no escape codes, CR LF line ends; each of transcript_checks(transcript) after them."""
    s = SerialSession(extra=CROSSING)
    try:
        group(s, *args, **kwargs)
        check("\x1b" not in s.term.transcript, "no escape codes on a serial line")
        check("\r\n" in s.term.transcript, "a serial terminal gets CR LF line ends")
        for extra in transcript_checks:
            extra(s.term.transcript)
    finally:
        s.close()


def walk_screen(group, *args, **kwargs):
    """The group on the real binary's full-screen front end in tmux (100x40, send-keys,
    capture-pane): the same transcripts as on the serial line, asserted on what the screen shows;
    the stored state is checked after each change and after Ctrl-C (the ui_walk_screen_* tests)."""
    s = ScreenSession(extra=CROSSING, cols=100, rows=40)
    try:
        group(s, *args, **kwargs)
    finally:
        s.close()


def screen_test(group, *args, **kwargs):
    """A ui_walk_screen_* script: walk_screen(group, ...) as one test named after the script."""
    run_test(lambda: walk_screen(group, *args, **kwargs), os.path.basename(sys.argv[0]))
