"""The walkthroughs of menus 6 (6-0, 6-3, 6-4, 6-6, 6-9), 7, 8 and M (_walk.py's group_6_7_8 and
group_m): configuration, presets, parking, the station file, host mode, the standalone modes."""
import os
import re
import time

from _tbharness import check  # noqa: E402
from _walk_steps import (DATA, DIRECT, MAIN, PRESET, UPDATE, answer, az_diff, last_match,
                         monitor_positions, must, must_not, since, step)  # noqa: E402
from _walk_menus_2_3 import walk_menu_3_2, walk_menu_3_4  # noqa: E402


CONFIG = r"====== Configuration Menu ======"


def walk_6_0(ui, expect):
    ui.send("0\r")
    out = since(ui.prompt(r"Press any key to continue"), " Select: 0")  # this display, not an older one
    for rx in expect:
        must(out, rx, "6-0")
    ui.send(" ")
    return ui.prompt(UPDATE)


FACTORY_6_0 = [
    r"^Callsign:NOCALL  Lat:27\.4 Long:128\.7 Hgt:50\.0$",
    r"^ADC span value   AZ:   0 - 1023  EL:   0 -  511$",
    r"^Dead band        AZ:3\.0 EL:1\.0  Skew AZ:0\.0 EL:0\.0$",
    r"^Antenna parking  Off$",
    r"^Rotator limit    Off$",
    r"^CAT Rig          NONE AOS$",
    r"^Step control ADC value Center:550 Reff:560$",
    r"^Frequency step   100 Hz$",
    r"^Rotor start      South$",
    r"^COM port         9600 Baud 8-N-1$",
]


def walk_6_3(ui):
    ui.send("3\r")
    answer(ui, r"Azimuth Dead Band : 3\.0 ", "5\r", "6-3")
    answer(ui, r"Elevation Dead Band : 1\.0 ", "3\r", "6-3")
    answer(ui, r"Azimuth Skew value : 0\.0 ", "2.5\r", "6-3")
    out = ui.prompt(r"Azimuth Skew value : 0\.0 ")
    must(out, r"2\.5 is not a whole number", "skew is in whole ADC counts")
    ui.send("\r")
    answer(ui, r"Elevation Skew value : 0\.0 ", "\r", "6-3")
    ui.prompt(UPDATE)


def wait_arrived(ui, prompt_rx, az, el, timeout=30.0):
    """After a 6-6-2 or preset target: the live line until the antenna is there, then the prompt."""
    out = ui.prompt(prompt_rx, timeout)
    pos = monitor_positions(out)
    check(pos, f"a live antenna position was shown:\n{out[-1500:]}")
    _, got_az, _, got_el = pos[-1]
    check(az_diff(got_az, az) <= 2.0 and abs(got_el - el) <= 1.0,
          f"the antenna arrived at {az}/{el} (within the dead band): last shown {got_az}/{got_el}")
    return out


def open_direct(ui, key, what):
    """6-6 and menu 8 (key "6" in the Configuration Menu, "8" in the main menu) open the same
    sub-menu: its three choices, then its prompt."""
    step(ui, key + "\r", DIRECT,
         r"1\.Direct rotor control from key board\.\n2\.Enter direction value\.\n3\.Preset Control\.", what)


PRESETS = [(125, 15), (90, 22), (0, 45), (270, 10), (165, 0)]


def walk_6_6(ui):
    """6-6: the sub-menu, 2 (enter a direction, the manual's 210/20), 3 (presets, S to store the
    manual's five, then preset 4: 270/10, on this side of the South-start rotator's stop), 1
    (keyboard: up, stop, Enter)."""
    open_direct(ui, "6", "the 6-6 sub-menu")
    ui.send("2\r")
    out = ui.prompt(r"Azimuth: 180\.0 ")
    must(out, r"Rotor control switched ON \(E key in the realtime display switches it OFF\)\.",
         "6-6-2 on a fresh unit takes rotor control without a question")
    ui.send("210\r")
    answer(ui, r"Elevation: 0\.0 ", "20\r", "6-6-2")
    wait_arrived(ui, DIRECT, 210, 20)

    out = step(ui, "3\r", PRESET, r"^ 1:0\.0/0\.0 2:0\.0/0\.0 3:0\.0/0\.0 4:0\.0/0\.0 5:0\.0/0\.0$", "the five presets")
    ui.send("S\r")
    for n, (az, el) in enumerate(PRESETS, 1):
        answer(ui, rf" Preset position {n} Az: 0\.0 ", f"{az}\r", "preset az")
        answer(ui, r"\s{5,}El: 0\.0 ", f"{el}\r", "preset el")
    out = ui.prompt(PRESET)
    must(out, r"^ 1:125\.0/15\.0 2:90\.0/22\.0 3:0\.0/45\.0\n   4:270\.0/10\.0 5:165\.0/0\.0$",
         "the manual's list after S, on two lines")
    ui.send("4\r")
    wait_arrived(ui, PRESET, 270, 10)
    ui.send("Q\r")
    ui.prompt(DIRECT)

    ui.send("1\r")
    ui.wait(r"Left\(4\),Right\(6\),Up\(8\),Dwn\(2\),Stop\(5\)or Ret")
    ui.wait(r"AZ=\s*\d+ / [\d.]+deg EL=\s*\d+ / [\d.]+deg\.", after="Stop(5)or Ret")
    ui.send("8")  # up
    ui.wait(r"AZ=\s*\d+ / [\d.]+deg EL=\s*\d+ / (?:1[3-9]|[2-9]\d)\.\ddeg\.", timeout=10,
            after="Stop(5)or Ret")  # past 13 deg
    ui.send("5")  # stop
    ui.send("\r")
    out = ui.prompt(DIRECT)
    pos = monitor_positions(out)
    check(pos and pos[-1][3] >= 13.0, f"keyboard control raised the antenna from 10 deg: {pos[-3:]}")
    ui.send("Q\r")
    return pos[-1]


def enter_6_4(ui, parking_yes, shown, typed):
    """6-4 answered Y to both of its questions (parking_yes: the keys of the first answer): its six
    values, parking azimuth and elevation, then the azimuth and elevation limits (minimum, maximum),
    each prompt showing `shown` and answered with `typed` ("" keeps the value). Returns the screen up
    to the next prompt."""
    values = list(zip(["Azimuth Parking", "Elevation Parking", "Azimuth minmum", "Azimuth maximum",
                       "Elevation minmum", "Elevation maximum"], shown, typed))
    ui.send("4\r")
    ui.prompt(r"Set Antenna Parking position \? \[Y/N\] ")
    ui.send(parking_yes)
    for label, was, keys in values[:2]:
        answer(ui, rf"{label} value : {re.escape(f'{was:.1f}')} ", keys + "\r", "6-4")
    ui.prompt(r"Set Antenna rotation limit \? \[Y/N\] ")
    ui.send("Y\r")  # "Y <ENTER>": one answer; the next Enter keeps the minimum
    for label, was, keys in values[2:]:
        answer(ui, rf"{label} value : {re.escape(f'{was:.1f}')} ", keys + "\r", "6-4")
    return ui.prompt(UPDATE)


def walk_6_4(ui):
    out = enter_6_4(ui, "Y", (0, 0, 0, 360, 0, 90), ("90", "45", "", "340", "", "60"))
    # The factory South start: 0..340 holds the rotor stop, the limits split the travel (issue 21).
    # The walk runs with --cross-limit-sector yes (pointing limits the antenna may cross: its later
    # AZ/EL commands point on both sides); the manual's keystrokes stay as they are.
    must(out, r"may cross between passes", "6-4 says what is reachable when limits split the travel")
    must_not(since(out, "Set Antenna Parking position"), r"Not changed", "the manual's 6-4 example is valid")
    # A whole that does not hold together is refused, nothing changed.
    out = enter_6_4(ui, "Y\r", (90, 45, 0, 340, 0, 60), ("", "", "", "", "50", "40"))
    must(out, r"elevation limits 50(\.0)?\.\.40(\.0)?: maximum must not be below minimum", "why it is refused")
    must(out, r"Not changed\.", "a refused 6-4 changes nothing")


def check_rotator_after_6(rot):
    check(rot["az_dead_band"] == 5 and rot["el_dead_band"] == 3, f"6-3 dead bands: {rot}")
    check(rot["az_skew"] == 0 and rot["el_skew"] == 0, f"6-3 skews kept: {rot}")
    check(rot["presets"] == [[float(a), float(e)] for a, e in PRESETS], f"6-6-3 presets: {rot['presets']}")
    check(rot["parking_enabled"] is True and rot["parking"] == [90.0, 45.0], f"6-4 parking: {rot}")
    check(rot["limits_enabled"] is True and (rot["az_limit_min"], rot["az_limit_max"]) == (0.0, 340.0) and
          (rot["el_limit_min"], rot["el_limit_max"]) == (0.0, 60.0) and rot["cross_limit_sector"] is True,
          f"6-4 limits: {rot}")


AFTER_6_4 = [
    r"^Dead band        AZ:5\.0 EL:3\.0  Skew AZ:0\.0 EL:0\.0$",
    r"^Antenna parking  On  AZ:90\.0 EL:45\.0$",
    r"^Rotator limit    On  AZ:0\.0-340\.0 EL:0\.0-60\.0  cross between passes$",
    r"^Preset position  1:125\.0/15\.0 2:90\.0/22\.0 3:0\.0/45\.0 4:270\.0/10\.0 5:165\.0/0\.0$",
]


# ---------------------------------------------------------------------------------------------
# Menu 7: host mode (after 6-4: elevation limited to 60)

def walk_menu_8(ui):
    """Menu 8 is 6-6's sub-menu: enter a direction near the antenna (rotor control is on now)."""
    open_direct(ui, "8", "menu 8's sub-menu")
    ui.send("2\r")
    out = ui.prompt(r"Azimuth: \d+\.\d ")
    az = float(last_match(out, r"Azimuth: (\d+\.\d)\s*$", "the antenna azimuth").group(1))
    check(az_diff(az, 270) <= 2.0, f"the prompt shows where the antenna is (270 after preset 4): {az}")
    ui.send("280\r")
    ui.prompt(r"Elevation: \d+\.\d ")
    ui.send("20\r")
    wait_arrived(ui, DIRECT, 280, 20)
    ui.send("Q\r")
    ui.prompt(MAIN)


def walk_menu_7(ui):
    out = step(ui, "7\r", r"TrakBox>>",
               r"TrakBox host mode\.\nCommand:MUxxx,MDxxx,FUxxx,FDxxx,AZxxx_ELxx,Sxxx,Q,\?A,\?\n", "the banner")
    out = step(ui, "AZ120 EL30\r", r"TrakBox>>",
               r"^TrakBox>>AZ120 EL30\nTrakBox>>$", "AZ120 EL30 is answered by the prompt alone")
    ui.send("?A\r")
    out = ui.prompt(r"TrakBox>>")
    first = last_match(out, r"\?A\nAZ(\d{1,3}\.\d) EL(\d{1,2}\.\d)\n", "?A: where the antenna points").groups()
    out = step(ui, "?\r", r"TrakBox>>", r"AZxxx ELxxx\s+point the antenna", "? lists the commands")
    must(out, r"Q\s+quit to the main menu", "? lists Q")
    ui.send("XY12\r")
    out = ui.prompt(r"TrakBox>>")
    must(out, r"ERROR unknown command 'XY12': expected AZxxx ELxxx, MUxxx, MDxxx, FUxxx, FDxxx, Sxxx, \?A, \? or Q",
         "a bad command")
    out = step(ui, "AZ400 EL10\r", r"TrakBox>>",
               r"ERROR AZ/EL: azimuth 400 out of range: expected 0 to 360", "a bad azimuth")
    # The antenna is on its way to 120/30: ?A reads where it is now.
    deadline = time.time() + 10
    while True:
        ui.send("?A\r")
        out = ui.prompt(r"TrakBox>>")
        now = last_match(out, r"\?A\nAZ(\d{1,3}\.\d) EL(\d{1,2}\.\d)\n", "?A again").groups()
        if now != first:
            break
        check(time.time() < deadline, f"the antenna never moved after AZ120 EL30: ?A {now}")
        time.sleep(0.5)
    check(float(now[1]) > float(first[1]), f"climbing towards EL30: {first} -> {now}")
    out = step(ui, "AZ120 EL75\r", r"TrakBox>>",
               r"LIMIT AZ120\.0 EL60\.0", "the 6-4 elevation limit holds in host mode")
    ui.send("Q\r")
    ui.prompt(MAIN)


# ---------------------------------------------------------------------------------------------
# Menu 6-9: Set default parameter, with the manual's station file

STATION_6_0 = [
    r"^Callsign:WA7GXD  Lat:32\.3 Long:-110\.8 Hgt:842\.0$",
    r"^ADC span value   AZ:   3 - 1017  EL:   5 -  454$",
    r"^Dead band        AZ:5\.0 EL:3\.0  Skew AZ:0\.0 EL:0\.0$",
    r"^Antenna parking  On  AZ:90\.0 EL:0\.0$",
    r"^Rotator limit    On  AZ:270\.0-90\.0 EL:0\.0-45\.0$",
    r"^Preset position  1:0\.0/0\.0 2:0\.0/0\.0 3:0\.0/0\.0 4:0\.0/0\.0 5:0\.0/0\.0$",
    r"^CAT Rig          ICOM AOS  RX:10H TX:14H$",
    r"^Rotor start      South$",
]

BAD_STATION = """1 WA7GXD 32.259 -110.778 842 S
2 3 1017 5 454
3 5 3 0
4 ICOM X 10 14
5 1 900 0 1 270 90 0 45
"""


def start_6_9(ui):
    step(ui, "9\r", r"Are you sure \? \[Y/N\] \? ", r"Stored data in memory will be lost\.\n", "6-9 warns")
    ui.send("Y")
    ui.prompt(r"Configure your station elements by uploading data file \? \[Y/N\] ")
    ui.send("Y")
    ui.prompt(r"Upload Station info data file \(EOF:ctrl-Z\)")


def walk_6_9(ui):
    start_6_9(ui)
    ui.upload(open(os.path.join(DATA, "station.txt")).read())
    out = ui.prompt(UPDATE)
    must(out, r"Station file loaded\. Verify it with 6-0", "the station file is taken")
    walk_6_0(ui, STATION_6_0)


def walk_6_9_bad(ui):
    start_6_9(ui)
    ui.upload(BAD_STATION)
    out = ui.prompt(UPDATE)
    must(out, r"line 3, item 5 \(elevation skew\): found nothing", "a missing item")
    must(out, r'line 4, item 3 \(F/A\): found "X", expected F \(full orbit\) or A \(AOS only\)', "a bad F/A")
    must(out, r'line 5, item 3 \(parking azimuth\): found "900", expected degrees 0 to 360', "degrees, not counts")
    must(out, r"Station file not applied: every parameter is at its default\.", "nothing of the file applied")


# ---------------------------------------------------------------------------------------------
# Menu M: multiple tracking. Tracking list ISS, AO-27, FO-29 (3-2), three multi-tracked (3-4).
# From the factory station on 2026-05-21: FO-29 is up until 12:12:07, AO-27 until 12:14:08, the ISS
# rises at 12:09:10; after 12:16 none is up until AO-27 at 13:38:13 and the ISS at 13:44:30
# (trakbox passes --station 27.391,128.657,50).

def set_clock(ui, when):
    """Menu 5, as the manual does it: Enter, the time, then ENTER when ready."""
    ui.send("5\r")
    ui.wait(r"Enter 'Ret' for Real Time Clock set")
    ui.send("\r")
    ui.prompt(r"Set time: ")
    ui.send(when + "\r")
    ui.prompt(r"ENTER when ready\. ")
    ui.send("\r")
    return ui.prompt(MAIN)


def start_m(ui, mode_key, marker, marked=1, choose="\r"):
    """M in mode_key's mode; the LCD list shows `marker` on entry `marked`; `choose` answers it."""
    ui.send("M\r")
    ui.prompt(r"Normal or Priority mode \? \[N/P\] \(Enter = [NP]\) ")
    # "N <ENTER>": one answer (issue 18)
    out = step(ui, mode_key if mode_key == "\r" else mode_key + "\r", r"Select :",
               r"\*\*\* LCD display satellite \*\*\*", "M asks for the LCD satellite")
    rows = r"\s+".join(rf"{n}\.{re.escape(marker) if n == marked else ' '}{name}"
                       for n, name in ((1, "ISS"), (2, "AO-27"), (3, "FO-29")))
    must(out, rf" {rows}\s*$", f"the three, '{marker}' on #{marked}")
    ui.send(choose)


def walk_menu_m(ui, names):
    """From the main menu with the shipped database at 12:08:30: the tracking list ISS, AO-27, FO-29
    (3-2), three multi-tracked (3-4), then M in normal and priority mode at times the passes fix."""
    ui.send("3\r")
    ui.prompt(UPDATE)
    walk_menu_3_2(ui, [4, 2, 3], names)
    walk_menu_3_4(ui, 3, 3)
    ui.send("Q\r")
    ui.prompt(MAIN)

    # S: single tracking marks the last satellite chosen (in 3-2, FO-29) with '*'.
    out = step(ui, "S\r", r"Select :", r" 1\. ISS\s+2\. AO-27\s+3\.\*FO-29\s*$", "single tracking's '*'")
    ui.send("Q\r")
    ui.prompt(MAIN)

    # Nothing of the three is up at 12:20: the table, '!' on the LCD satellite, the next AOS times.
    set_clock(ui, "26/05/21 12:20:00")
    start_m(ui, "N", "!", marked=3, choose="1\r")  # the ISS on the LCD from here on
    ui.wait(r"=========== Multiple Tracking \[2026/05/21\] Normal mode ===========")
    rows = ui.wait(r"Rotor control ON   LCD \|12:2\d:\d\d!ISS    \|Az[ \d.-]{6}El[ \d.-]{6}\| LED off")
    # AOS 13:44:29.661 and 13:38:12.744 (trakbox passes): to the second, either way.
    must(rows, r"^  1\.!ISS\s+[\d.]+\s+-[\d.]+\s+[\d.]+\s+13:44:(29|30)\s*$", "ISS: marked, next AOS 13:44:30")
    must(rows, r"^  2\. AO-27\s+[\d.]+\s+-[\d.]+\s+[\d.]+\s+13:38:1[23]\s*$", "AO-27: next AOS 13:38:13")
    must(rows, r"^  3\. FO-29\s+[\d.]+\s+-[\d.]+\s+[\d.]+\s+\d\d:\d\d:\d\d\s*$", "FO-29's row")
    ui.send("E")
    ui.wait(r"Rotor control OFF  LCD \|12:2\d:\d\d!ISS")
    ui.send("E")
    ui.wait(r"Rotor control ON   LCD \|12:2\d:\d\d!ISS")
    ui.send("Q")
    ui.prompt(MAIN)

    # 12:09:00: AO-27 (#2) and FO-29 (#3) are up, the ISS (#1) rises at 12:09:10.
    # Normal mode: AO-27 is tracked ('!') and kept after the ISS rises.
    set_clock(ui, "26/05/21 12:09:00")
    start_m(ui, "\r", "!")  # Enter keeps normal mode
    ui.wait(r"\[Satellite:!AO-27\]", timeout=15)
    out = ui.wait(r"\n12:09:1[3-9] +[\d.]+ +[\d.]+ ", timeout=25)
    if ui.full_screen:
        must(out, r"\[Satellite:!AO-27\]", "normal mode keeps AO-27 after the ISS rose")
    else:
        must_not(out.split("[Satellite:!AO-27]")[-1], r"\[Satellite:", "normal mode keeps AO-27 after the ISS rose")
    ui.send("Q")
    ui.prompt(MAIN)

    # Priority mode: AO-27 first ('&'), then the ISS takes over when it rises.
    set_clock(ui, "26/05/21 12:09:00")
    start_m(ui, "P", "&")
    ui.wait(r"\[Satellite:&AO-27\]", timeout=15)
    ui.wait(r"\[Satellite:&ISS\]", timeout=25)
    ui.wait(r"\n12:09:1\d +[\d.]+ +-?[\d.]+ ", timeout=10)
    ui.send("Q")
    ui.prompt(MAIN)
    ui.send("M\r")
    ui.prompt(r"Normal or Priority mode \? \[N/P\] \(Enter = P\) ")  # the choice is remembered
    ui.send("Q")
    ui.prompt(MAIN)


# ---------------------------------------------------------------------------------------------
# The groups the ui_walk_* tests run, each on a session (SerialSession or ScreenSession: .ui,
# .state_file, .stop()) started on a fresh state directory with the harness's CLOCK.
