"""The manual's transcripts for menus 2, 3-1..3-4, 6 (6-0, 6-3, 6-4, 6-6, 6-9), 7, 8 and M, written
once against the UI interface of _tbharness (LineUI: a serial line; ScreenUI: full screen in tmux)
and walked by the ui_walk_* tests on the real binary.

A walkthrough sends what an operator types, waits at each prompt the manual prints, and checks what
the terminal showed on the way; the tests check the stored state afterwards. Key conventions: '\\r'
is Enter, '\\x1a' Ctrl-Z; [Y/N] questions take one key without Enter (docs/menus/README.md).
"""
import json
import math
import os
import re
import subprocess
import sys
import time

from _tbharness import (BIN, SOURCE, Failure, check, factory_state, load_state, read_tle, run_test,  # noqa: E402
                        tle_to_amsat)
from _tbui import ScreenSession, SerialSession  # noqa: E402

MAIN = r"Select \[1-8,S,M\]:"
UPDATE = r" Select:"              # the UPDATE MENU and the Configuration Menu prompt
DIRECT = r"Select\[1-3,Q\]:"
PRESET = r" Select\[1-5,S,Q\]:"
SCROLL = r"- 'Q' for abort 'S' for scroll"
DATA = os.path.join(SOURCE, "data")

# The factory station (menu 4's defaults) that the passes below are computed for.
FACTORY_STATION = "27.391,128.657,50"


def must(text, rx, what):
    """rx must occur in what the terminal showed; returns the match."""
    m = re.search(rx, text, re.M)
    if not m:
        raise Failure(f"{what}: expected {rx!r} in:\n{text[-3000:]}")
    return m


def must_not(text, rx, what):
    m = re.search(rx, text, re.M)
    if m:
        raise Failure(f"{what}: {m.group(0)!r} must not appear in:\n{text[-3000:]}")


def answer(ui, label_rx, keys, what, timeout=10.0):
    """Waits at a prompt, then types the answer."""
    try:
        out = ui.prompt(label_rx, timeout)
    except Failure as e:
        raise Failure(f"{what}: {e}") from None
    ui.send(keys)
    return out


def monitor_positions(text):
    """Every 'AZ= 519 / 32.8deg EL= 462 / 90.0deg.' line shown: [(az_counts, az, el_counts, el)]."""
    return [(int(a), float(b), int(c), float(d))
            for a, b, c, d in re.findall(r"AZ=\s*(\d+) / ([\d.]+)deg EL=\s*(\d+) / (-?[\d.]+)deg\.", text)]


def since(text, marker):
    """The text after the last occurrence of marker (what a screen shows below it)."""
    return text.rsplit(marker, 1)[-1]


def last_match(text, rx, what):
    found = list(re.finditer(rx, text, re.M))
    if not found:
        raise Failure(f"{what}: expected {rx!r} in:\n{text[-3000:]}")
    return found[-1]


def az_diff(a, b):
    return abs((a - b + 180.0) % 360.0 - 180.0)


# ---------------------------------------------------------------------------------------------
# Menu 2: Display Schedule (the shipped database, the factory station, clock 2026-05-21 12:08:30)

def walk_menu_2(ui, page_rows):
    ui.send("2\r")
    out = ui.prompt(r"Select :")
    must(out, r"\*\*\* Tracking object satellite \*\*\*", "menu 2 lists the tracking list")
    must(out, r" 1\.\*AO-07\s+2\. AO-27\s+3\. FO-29\s+4\. ISS", "menu 2's list, '*' on the last chosen")
    ui.send("4\r")  # the ISS
    start = r"2026/05/21 12:\d\d:\d\d Starting Day/Time \? \[YY/MM/DD HH:MM:SS\] Day of the Year \[T\] >"
    ui.prompt(start)
    # The manual's own answer (564.17270) is no day of a year: refused with the reason, asked again.
    ui.send("564.17270\r")
    out = ui.prompt(start)
    must(out, r"day 564\.17270 is not in 2026: expected 1 to 365\.99999", "a day of the year beyond the year")
    # [T]: the day of the year with its fraction; .631285 of day 141 is 15:09:03 on 21 May.
    ui.send("141.631285\r")
    answer(ui, r"Time Step Min \[1\]:", "60\r", "step minutes")
    answer(ui, r"Sec \[0\]:", "0\r", "step seconds")
    out = ui.prompt(SCROLL, timeout=20)
    rows1 = schedule_rows(out)
    check(len(rows1) == page_rows, f"a screenful is {page_rows} rows: got {len(rows1)}")
    check(rows1[0][0] == "2026/05/21 15:09:03", f"first row at the start time: {rows1[0]}")
    ui.send("S")
    out = ui.prompt(SCROLL, timeout=20)
    rows2 = schedule_rows(out)
    check(len(rows2) == page_rows, f"the second screenful has {page_rows} rows: got {len(rows2)}")
    rows = rows1 + rows2
    # The steps are exactly 60 minutes, and the table is what the schedule command computes.
    reference = cli_schedule("ISS", "2026-05-21T15:09:03Z", 3600, len(rows), 437_800_000)
    for (when, az, el, phase, doppler), ref in zip(rows, reference):
        check(when == ref["utc"][:19].replace("-", "/").replace("T", " "), f"row time {when} vs {ref['utc']}")
        check(az_diff(az, ref["az_deg"]) <= 0.051 and abs(el - ref["el_deg"]) <= 0.051,
              f"{when}: AZ/EL {az}/{el} vs {ref['az_deg']:.3f}/{ref['el_deg']:.3f}")
        check(math.floor(ref["phase256"] - 1e-4) <= phase <= math.floor(ref["phase256"] + 1e-4),
              f"{when}: phase {phase} vs {ref['phase256']}")
        check(abs(doppler - ref["doppler_hz"]) <= 1.0, f"{when}: Doppler {doppler} vs {ref['doppler_hz']:.1f}")
    ui.send("Q")
    ui.prompt(MAIN)


def schedule_rows(out):
    """The rows after the last header: (date time, az, el, phase, doppler)."""
    part = out.rsplit("DATE       TIME      AZ/EL       Phase Doppler", 1)
    check(len(part) == 2, f"the schedule header: {out[-2000:]}")
    rows = re.findall(r"^(\d{4}/\d\d/\d\d \d\d:\d\d:\d\d)\s+([\d.]+)/\s*(-?[\d.]+)\s+([\d.]+)\s+([+-]\d+)\s*$",
                      part[1], re.M)
    return [(w, float(a), float(e), float(p), int(d)) for w, a, e, p, d in rows]


def cli_schedule(sat, start, step, count, freq):
    r = subprocess.run([BIN, "schedule", os.path.join(DATA, "amateur.tle"), "--sat", sat, "--station",
                        FACTORY_STATION, "--start", start, "--step", str(step), "--count", str(count), "--freq",
                        str(freq), "--json"], capture_output=True, text=True, timeout=30)
    check(r.returncode == 0, f"trakbox schedule: {r.stderr}")
    return json.loads(r.stdout)


# ---------------------------------------------------------------------------------------------
# Menu 3-1: Edit (AO-73, #7 of the shipped database: the manual's A-21 example's radio values)

AO73_FIELDS = [  # label, value shown, prompt, answer ("" = Enter keeps it)
    (r"Satellite", r"AO-73", "", ""),
    (r"Epoch Year Y0", r"26", "Y0:", ""),
    (r"Epoch Time T0", r"140\.67569056", "T0:", ""),
    (r"Epoch Rev K0", r"67551", "K0:", "67560"),
    (r"Mean Anomaly M0", r"60\.8360", "M0:", ""),
    (r"Mean Motion N0", r"15\.09093359", "N0:", ""),
    (r"Inclination I0", r"97\.8265", "I0:", "97.83"),
    (r"Eccentricity E0", r"0\.0034836", "E0:", "1.5|"),  # refused, then Enter keeps it
    (r"Arg perigee W0", r"298\.9376", "W0:", ""),
    (r"R\.A\.A\.N\. O0", r"111\.5579", "O0:", ""),
    (r"Decay N1", r"5\.251000e-05", "N1:", ""),
    (r"Drag term B\*", r"3\.310200e-04", r"B\*:", ""),
    (r"Downlink Frq\.F1", r"145\.950", "F1:", "145.987"),
    (r"Offset for F1", r"0\.000", "F1OFFSET:", ""),
    (r"Uplink Frq\.F2", r"435\.140", "F2:", "435.016"),
    (r"Offset for F2", r"0\.000", "F2OFFSET:", ""),
    (r"Downlink mode", r"USB", "", "FM"),
    (r"Uplink mode", r"LSB", "", "fm"),
    (r"Doppler correct\.", r"CAT", "", "Mic-click"),
    (r"LCD MA display", r"No", "", "Y"),
]


def walk_menu_3_1(ui):
    ui.send("3\r")
    out = ui.prompt(UPDATE)
    must(out, r"======= UPDATE MENU =======\s*\n1\. EDIT: View/Edit satellite Element by hand", "the UPDATE MENU")
    ui.send("1\r")
    out = ui.prompt(r"Select :")
    must(out, r"\*\*\* Select object satellite \*\*\*", "3-1's title")
    must(out, r" 1\.\*AO-07 .* 4\. ISS\s*\n 5\. SO-50 .* 7\. AO-73", "3-1 lists the tracking list")
    check(re.search(r"1[5-9]\. |20\. ", out) is None,
          "3-1 numbers the tracking list (the manual's up to 15), not the whole database")
    ui.send("7\r")
    for label, shown, prompt, reply in AO73_FIELDS:
        out = ui.prompt(rf"{label}\s*: {shown}\s+{prompt}")
        if label == "Satellite":
            must(out, r"====== Satellite data ======", "3-1's data heading")
        first, _, second = reply.partition("|")
        ui.send(first + "\r")
        if second or "|" in reply:
            out = ui.prompt(rf"{label}\s*: {shown}\s+{prompt}")
            must(out, r"1\.5 is out of range: expected 0 to 0\.9999999", "a bad eccentricity says why")
            ui.send(second + "\r")
    out = ui.prompt(UPDATE)
    must(out, r"Satellite \(AO-73\) updated\.", "3-1 stores after the last line")

    # Again: the stored values are shown, and Enter on every line keeps them exactly.
    ui.send("1\r")
    ui.prompt(r"Select :")
    ui.send("7\r")
    edited = {"Epoch Rev K0": "67560", "Inclination I0": r"97\.8300", "Downlink Frq\\.F1": r"145\.987",
              "Uplink Frq\\.F2": r"435\.016", "Downlink mode": "FM", "Uplink mode": "FM",
              "Doppler correct\\.": "Mic-click", "LCD MA display": "Yes"}
    for label, shown, prompt, _ in AO73_FIELDS:
        ui.prompt(rf"{label}\s*: {edited.get(label, shown)}\s+{prompt}")
        ui.send("\r")
    out = ui.prompt(UPDATE)
    must(out, r"Satellite \(AO-73\) updated\.", "a second pass stores the same values")


# ---------------------------------------------------------------------------------------------
# Menu 3-2: Select, 3-4: Multi Track (from the UPDATE MENU)

def walk_menu_3_2(ui, picks, names):
    """picks: database numbers to select in order; names: the database names."""
    ui.send("2\r")
    ui.prompt(r"Are you sure \? \[Y/N\] \? ")
    ui.send("N")  # any key but Y: back, nothing changed
    ui.prompt(UPDATE)
    ui.send("2\r")
    ui.prompt(r"Are you sure \? \[Y/N\] \? ")
    ui.send("Y\r")  # the manual's "Y <ENTER>": the Enter ends the Y answer (issue 18)
    out = ui.prompt(r"Select :")
    must(out, r" 1\. AO-07\s+2\. AO-27", "3-2 lists the database without a mark")
    for k, n in enumerate(picks, 1):
        ui.send(f"{n}\r")
        out = ui.prompt(r"Select :")
        must(out, rf"Satellite \({re.escape(names[n - 1])}\) selected as #{k}\n", f"pick {k}")
        must(out, rf"(^|\s){n}\.\*{re.escape(names[n - 1])}", "'*' on the satellite just selected")
    ui.send(f"{picks[0]}\r")
    out = ui.prompt(r"Select :")
    must(out, rf"Satellite \({re.escape(names[picks[0] - 1])}\) is already selected as #1", "no duplicates")
    ui.send("99\r")
    out = ui.prompt(r"Select :")
    must(out, rf"Enter 1 to {len(names)}, or Q \(or Enter\) to finish", "a number outside the list")
    ui.send("\r")
    out = ui.prompt(UPDATE)
    must(out, rf"Tracking list: {len(picks)} satellite\(s\) selected\.", "3-2 ends with Enter")


def walk_menu_3_4(ui, count, listed):
    ui.send("4\r")
    q = r"How many satellites configure for multi tracking mode \? \(2-5\) "
    ui.prompt(q)
    ui.send("6\r")
    out = ui.prompt(q)
    must(out, r"'6': enter a number from 2 to 5", "3-4 takes 2 to 5")
    ui.send(f"{count}\r")
    out = ui.prompt(UPDATE)
    must(out, rf"The first {count} satellites of the tracking list will be multi-tracked\.", "3-4's answer")
    if listed >= count:
        must_not(since(out, "How many satellites"), r"Note: the tracking list holds", "no note: the list is long enough")


# ---------------------------------------------------------------------------------------------
# Menu 3-3: Update (uploads ending in Ctrl-Z)

FREQMODE = """ISS 437.800 145.990 fm fm cat no
AO-27 436.795 145.850 fm fm cat no
QO-100 10489.550/-9750.000 2400.050 usb usb cat no
iss 437.800 145.990 fm fm cat no
FO-29 43x.1 145.950 usb lsb cat no
AO-07 145.950 432.150 usb lsb mic ma
"""


def start_upload(ui, fmt):
    ui.send("3\r")
    out = ui.prompt(r"Are you sure \? \[Y/N\] \? ")
    must(out, r"Stored data in memory will be lost\.\n", "3-3 warns first")
    ui.send("Y\r")  # the manual's transcript: "? Y <ENTER>"; the Enter is not a format
    ui.prompt(r"File format NASA/AMSAT \(N/A\) : ")
    ui.send(fmt)
    ui.prompt(r"Upload Kepeledata file\. \(EOF:ctrl\+Z\)")


def walk_upload_nasa(ui):
    """The shipped 20-satellite NASA file, then a freq/mode file with good and bad lines."""
    sats = read_tle(os.path.join(DATA, "amateur.tle"))
    start_upload(ui, "N")
    ui.upload(open(os.path.join(DATA, "amateur.tle")).read())
    out = ui.prompt(r"Upload freq/mode data file\. \(EOF:ctrl\+Z\)", timeout=20)
    for k, (name, _, _) in enumerate(sats, 1):
        must(out, rf"^NASA>#{k} {re.escape(name)}$", "NASA>#n NAME for every set")
    must(out, r"^20 satellite\(s\) accepted, 0 record\(s\) skipped\.$", "the summary")
    ui.upload(FREQMODE)
    out = ui.prompt(UPDATE, timeout=20)
    for k, name in enumerate(["ISS", "AO-27", "QO-100", "AO-07"], 1):
        must(out, rf"Satellite \({re.escape(name)}\) updated and selected as # {k}$", "the manual's acknowledgement")
    must(out, r'Skipped line 5, field 2 \(downlink frequency\): found "43x\.1"', "a bad field says where")
    must(out, r"Skipped line 4: no satellite named \(iss\) in the database", "names are case-sensitive")
    must(out, r"4 satellite\(s\) updated and selected, 2 record\(s\) skipped\.", "the freq/mode summary")
    must(out, r"\*\*\* Satellite database \*\*\*\n 1\. AO-07\s+2\. AO-27\s+3\. FO-29\s+4\.\*ISS",
         "the new database is listed, '*' on #1 of the new list")
    must(out, r"======= UPDATE MENU =======", "back to the UPDATE MENU")


BAD_NASA = """AO-07
1 07530U 74089B   26141.31992461 -.00000054  00000-0 -48931-4 0  9993
2 07530 101.9910 154.2858 0012269 180.6108 191.1977 12.53697584357151
"""


def walk_upload_failures(ui):
    """Uploads that give nothing usable: the stored database stays exactly as it was."""
    # A record with a bad checksum (the last digit of line 1 altered).
    start_upload(ui, "N")
    ui.upload(BAD_NASA)
    out = ui.prompt(UPDATE, timeout=20)
    must(out, r"Line 2 skipped: checksum \(column 69\): found '3', expected", "the damaged line, column and why")
    must(out, r"0 satellite\(s\) accepted, 1 record\(s\) skipped\.", "nothing accepted")
    must(out, r"No satellite data accepted: the stored database is unchanged\.", "the database is kept")
    must_not(since(out, "Upload Kepeledata file. (EOF:ctrl+Z)"), r"Upload freq/mode data file",
             "no freq/mode step after a failed upload")
    # A malformed file: NASA lines where AMSAT blocks were announced.
    start_upload(ui, "A")
    ui.upload("\n".join(ln for s in read_tle(os.path.join(DATA, "amateur.tle"))[:2] for ln in s) + "\n")
    out = ui.prompt(UPDATE, timeout=20)
    must(out, r"No AMSAT element set found in the upload: the stored database is unchanged\.", "wrong format")
    # Ctrl-Z alone.
    start_upload(ui, "N")
    ui.send("\x1a")
    out = ui.prompt(UPDATE, timeout=20)
    must(out, r"0 satellite\(s\) accepted, 0 record\(s\) skipped\.", "an empty upload")
    must(out, r"the stored database is unchanged\.", "an empty upload keeps the database")


AMSAT_NAMES = ["AO-07", "AO-27", "FO-29", "ISS", "SO-50", "AO-73"]


def amsat_bulletin():
    sats = {n: (n, l1, l2) for n, l1, l2 in read_tle(os.path.join(DATA, "amateur.tle"))}
    blocks = [tle_to_amsat(*sats[n]) for n in AMSAT_NAMES]
    return ("SB KEPS @ AMSAT $ORBS-141.D\nOrbital Elements 141.AMSAT\n\n" + "\n".join(blocks) + "\n/EX\n")


def walk_upload_amsat(ui):
    start_upload(ui, "A")
    ui.upload(amsat_bulletin())
    out = ui.prompt(r"Upload freq/mode data file\. \(EOF:ctrl\+Z\)", timeout=20)
    for k, name in enumerate(AMSAT_NAMES, 1):
        must(out, rf"^AMSAT>#{k} {re.escape(name)}$", "AMSAT>#n NAME")
    must(out, r"^6 satellite\(s\) accepted, 0 record\(s\) skipped\.$", "the AMSAT summary")
    ui.send("\x1a")  # no freq/mode file
    out = ui.prompt(UPDATE, timeout=20)
    must(out, r"No freq/mode data: known satellites kept their frequencies; the tracking list is the first 6",
         "Ctrl-Z alone: no freq/mode file")
    must(out, r" 1\.\*AO-07\s+2\. AO-27\s+3\. FO-29\s+4\. ISS\s*\n 5\. SO-50\s+6\. AO-73", "the new database")


def check_state_after_3(data, before_nasa):
    """The stored state after walk_menu_3_1, 3-2, 3-4, the NASA upload and the AMSAT upload."""
    db = data["db"]
    names = [s["elements"]["name"] for s in db["satellites"]]
    check(names == AMSAT_NAMES, f"the AMSAT upload is the database: {names}")
    for s in db["satellites"]:
        e = s["elements"]
        check(e["source"] == "amsat" and e["bstar"] == 0.0, f"{e['name']}: an AMSAT set (no B*): {e}")
    ref = {n: (n, l1, l2) for n, l1, l2 in read_tle(os.path.join(DATA, "amateur.tle"))}
    iss = db["satellites"][3]["elements"]
    l2 = ref["ISS"][2]
    check(iss["mean_motion_rev_per_day"] == float(l2[52:63]) and iss["inclination_deg"] == float(l2[8:16]),
          f"ISS elements as uploaded: {iss}")
    check(db["selected"] == [0, 1, 2, 3, 4, 5], f"no freq/mode file: the first satellites listed: {db['selected']}")
    radio = {s["elements"]["name"]: s["radio"] for s in db["satellites"]}
    # Radio entries follow the satellites by name through both uploads: AO-73's from 3-1, the
    # others from the freq/mode file.
    check(radio["AO-73"]["downlink_hz"] == 145_987_000 and radio["AO-73"]["uplink_hz"] == 435_016_000,
          f"AO-73 keeps the 3-1 frequencies: {radio['AO-73']}")
    check(radio["AO-73"]["downlink_mode"] == "fm" and radio["AO-73"]["lcd_ma_display"] is True,
          f"AO-73 keeps the 3-1 modes: {radio['AO-73']}")
    check(radio["AO-07"]["doppler"] != "cat" and radio["AO-07"]["lcd_ma_display"] is True,
          f"AO-07's freq/mode line (mic, ma): {radio['AO-07']}")
    check(radio["ISS"]["downlink_hz"] == 437_800_000 and radio["ISS"]["uplink_hz"] == 145_990_000,
          f"ISS's freq/mode line: {radio['ISS']}")
    check(db["multi_count"] == before_nasa["db"]["multi_count"], "3-4's count survives the uploads")


# ---------------------------------------------------------------------------------------------
# Menu 6: Configuration

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
    ui.send(key + "\r")
    out = ui.prompt(DIRECT)
    must(out, r"1\.Direct rotor control from key board\.\n2\.Enter direction value\.\n3\.Preset Control\.", what)


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

    ui.send("3\r")
    out = ui.prompt(PRESET)
    must(out, r"^ 1:0\.0/0\.0 2:0\.0/0\.0 3:0\.0/0\.0 4:0\.0/0\.0 5:0\.0/0\.0$", "the five presets")
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
    ui.send("7\r")
    out = ui.prompt(r"TrakBox>>")
    must(out, r"TrakBox host mode\.\nCommand:MUxxx,MDxxx,FUxxx,FDxxx,AZxxx_ELxx,Sxxx,Q,\?A,\?\n", "the banner")
    ui.send("AZ120 EL30\r")
    out = ui.prompt(r"TrakBox>>")
    must(out, r"^TrakBox>>AZ120 EL30\nTrakBox>>$", "AZ120 EL30 is answered by the prompt alone")
    ui.send("?A\r")
    out = ui.prompt(r"TrakBox>>")
    first = last_match(out, r"\?A\nAZ(\d{1,3}\.\d) EL(\d{1,2}\.\d)\n", "?A: where the antenna points").groups()
    ui.send("?\r")
    out = ui.prompt(r"TrakBox>>")
    must(out, r"AZxxx ELxxx\s+point the antenna", "? lists the commands")
    must(out, r"Q\s+quit to the main menu", "? lists Q")
    ui.send("XY12\r")
    out = ui.prompt(r"TrakBox>>")
    must(out, r"ERROR unknown command 'XY12': expected AZxxx ELxxx, MUxxx, MDxxx, FUxxx, FDxxx, Sxxx, \?A, \? or Q",
         "a bad command")
    ui.send("AZ400 EL10\r")
    out = ui.prompt(r"TrakBox>>")
    must(out, r"ERROR AZ/EL: azimuth 400 out of range: expected 0 to 360", "a bad azimuth")
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
    ui.send("AZ120 EL75\r")
    out = ui.prompt(r"TrakBox>>")
    must(out, r"LIMIT AZ120\.0 EL60\.0", "the 6-4 elevation limit holds in host mode")
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
    ui.send("9\r")
    out = ui.prompt(r"Are you sure \? \[Y/N\] \? ")
    must(out, r"Stored data in memory will be lost\.\n", "6-9 warns")
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
    ui.send(mode_key if mode_key == "\r" else mode_key + "\r")  # "N <ENTER>": one answer (issue 18)
    out = ui.prompt(r"Select :")
    must(out, r"\*\*\* LCD display satellite \*\*\*", "M asks for the LCD satellite")
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
    ui.send("S\r")
    out = ui.prompt(r"Select :")
    must(out, r" 1\. ISS\s+2\. AO-27\s+3\.\*FO-29\s*$", "single tracking's '*'")
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
