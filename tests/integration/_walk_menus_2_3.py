"""The walkthroughs of menus 2 and 3-1..3-4 (_walk.py's group_2_3): the schedule against the
command line's, the satellite database, selection, the uploads of NASA and AMSAT files and their failures."""
import json
import math
import os
import re
import subprocess

from _tbharness import BIN, check, read_tle, tle_to_amsat  # noqa: E402
from _walk_steps import (DATA, FACTORY_STATION, MAIN, SCROLL, UPDATE, answer, az_diff, must,
                         must_not, since, step)  # noqa: E402


def walk_menu_2(ui, page_rows):
    out = step(ui, "2\r", r"Select :", r"\*\*\* Tracking object satellite \*\*\*", "menu 2 lists the tracking list")
    must(out, r" 1\.\*AO-07\s+2\. AO-27\s+3\. FO-29\s+4\. ISS", "menu 2's list, '*' on the last chosen")
    ui.send("4\r")  # the ISS
    start = r"2026/05/21 12:\d\d:\d\d Starting Day/Time \? \[YY/MM/DD HH:MM:SS\] Day of the Year \[T\] >"
    ui.prompt(start)
    # The manual's own answer (564.17270) is no day of a year: refused with the reason, asked again.
    out = step(ui, "564.17270\r", start,
               r"day 564\.17270 is not in 2026: expected 1 to 365\.99999", "a day of the year beyond the year")
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
    out = step(ui, "3\r", UPDATE,
               r"======= UPDATE MENU =======\s*\n1\. EDIT: View/Edit satellite Element by hand", "the UPDATE MENU")
    out = step(ui, "1\r", r"Select :", r"\*\*\* Select object satellite \*\*\*", "3-1's title")
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
        out = step(ui, f"{n}\r", r"Select :",
                   rf"Satellite \({re.escape(names[n - 1])}\) selected as #{k}\n", f"pick {k}")
        must(out, rf"(^|\s){n}\.\*{re.escape(names[n - 1])}", "'*' on the satellite just selected")
    out = step(ui, f"{picks[0]}\r", r"Select :",
               rf"Satellite \({re.escape(names[picks[0] - 1])}\) is already selected as #1", "no duplicates")
    out = step(ui, "99\r", r"Select :",
               rf"Enter 1 to {len(names)}, or Q \(or Enter\) to finish", "a number outside the list")
    out = step(ui, "\r", UPDATE, rf"Tracking list: {len(picks)} satellite\(s\) selected\.", "3-2 ends with Enter")


def walk_menu_3_4(ui, count, listed):
    ui.send("4\r")
    q = r"How many satellites configure for multi tracking mode \? \(2-5\) "
    ui.prompt(q)
    out = step(ui, "6\r", q, r"'6': enter a number from 2 to 5", "3-4 takes 2 to 5")
    out = step(ui, f"{count}\r", UPDATE,
               rf"The first {count} satellites of the tracking list will be multi-tracked\.", "3-4's answer")
    if listed >= count:
        must_not(since(out, "How many satellites"), r"Note: the tracking list holds",
                 "no note: the list is long enough")


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
    step(ui, "3\r", r"Are you sure \? \[Y/N\] \? ", r"Stored data in memory will be lost\.\n", "3-3 warns first")
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
    out = step(ui, "\x1a", UPDATE, r"0 satellite\(s\) accepted, 0 record\(s\) skipped\.", "an empty upload", timeout=20)
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
