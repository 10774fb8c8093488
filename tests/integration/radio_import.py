"""`trakbox radio import` and `trakbox radio diff` on the real binary (issue 59, item 3).

Each importer on a sample file written here in its list's format (Gpredict 44909.trsp, SatPC32
Doppler.SQF and SubTone.SQF, the SatNOGS DB transmitter list, OscarWatch satellite_database.json):
first on the state file (no station runs), then through a running station's socket (the line front
end on a pipe). The modes appear in `radio diff` with their source; the operator moves RS-44's SSB
downlink in menu 3-1 and that value survives every later import, each reporting the conflict; the
SatNOGS transmitter that is not active is not offered; a bad file is refused naming its line and
changes nothing; the state file keeps it all after the station leaves.
"""
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, Terminal, check, load_state, run_test  # noqa: E402

DATA = os.path.join(os.path.dirname(__file__), "..", "..", "data")

TRSP = """[Mode U/V Linear]
UP_LOW=145935000
UP_HIGH=145995000
DOWN_LOW=435610000
DOWN_HIGH=435670000
MODE=USB
INVERT=true

[CW beacon]
DOWN_LOW=435605000
MODE=CW
"""

SQF = ("RS-44,435640,145965,USB,LSB,REV,0,0,SSB\r\n"
       "ISS,437800,145990,FM,FM,NOR,0,0,FM\r\n"
       "HO-113,435165,145875,USB,LSB,REV,0,0,SSB\r\n"
       "HO-113,435170,145870,CW,CW,REV,0,0,CW\r\n")

SUBTONE = "ISS,67.0\r\nSO-50,67.0\r\n"

SATNOGS = [
    {"uuid": "t1", "description": "Mode U/V linear", "alive": True, "status": "active", "type": "Transponder",
     "uplink_low": 145935000, "uplink_high": 145995000, "downlink_low": 435610000, "downlink_high": 435670000,
     "mode": "SSB", "invert": True, "baud": None, "norad_cat_id": 44909},
    {"uuid": "t2", "description": "FM voice repeater", "alive": True, "status": "active", "type": "Transceiver",
     "uplink_low": 145990000, "uplink_high": None, "downlink_low": 437800000, "downlink_high": None, "mode": "FM",
     "invert": False, "baud": None, "norad_cat_id": 25544},
    {"uuid": "t3", "description": "Packet digipeater", "alive": True, "status": "inactive", "type": "Transceiver",
     "uplink_low": 437550000, "uplink_high": None, "downlink_low": 437550000, "downlink_high": None, "mode": "AFSK",
     "invert": False, "baud": 9600, "norad_cat_id": 25544},
    {"uuid": "t4", "description": "BPSK telemetry", "alive": False, "status": "active", "type": "Transmitter",
     "uplink_low": None, "uplink_high": None, "downlink_low": 435525000, "downlink_high": None, "mode": "BPSK",
     "invert": False, "baud": 1200, "norad_cat_id": 44909},
]

OSCARWATCH = [
    {"name": "SO-50", "norad_id": "27607", "modes": [
        {"type": "FM VOICE", "downlink": 436795, "uplink": 145850, "downlink_mode": "FMN", "uplink_mode": "FMN",
         "doppler": "NOR", "ctcss": 67.0, "ctcss_arm": 74.4}]},
    {"name": "AO-7", "modes": [
        {"type": "CW beacon", "downlink": 145970, "uplink": 0, "downlink_mode": "CW", "uplink_mode": "CW",
         "doppler": "NOR"}]},
]


def radio(state, *args):
    r = subprocess.run([BIN, "radio", *args, "--state", state, "--data", DATA], capture_output=True, text=True,
                       timeout=60)
    return r.returncode, r.stdout, r.stderr


def imported(state, path, *more):
    code, out, err = radio(state, "import", path, *more)
    check(code == 0, f"radio import {os.path.basename(path)}: {code} {err}")
    return out


def diff(state):
    code, out, err = radio(state, "diff")
    check(code == 0, f"radio diff: {code} {err}")
    return out


def has(text, line, what):
    check(line in text.splitlines(), f"{what}: {line!r} in\n{text}")


def write(d, name, text):
    path = os.path.join(d, name)
    with open(path, "w", newline="") as f:
        f.write(text)
    return path


def edit_rs44_downlink(t, send, mhz):
    """Menu 3-1 on RS-44: Enter on the element lines, F1 typed, Enter on the rest."""
    send("3\r")
    t.expect(r"1\. EDIT")
    send("1\r")
    m = t.expect(r"(\d+)\.[ *]RS-44")
    t.expect(r"Select :")
    send(m.group(1) + "\r")
    send("\r" * 12)  # the 12 lines of the elements (Satellite .. Drag term B*) kept
    m = t.expect(r"Downlink Frq\.F1\s*: (\S+)\s+F1:")
    send(mhz + "\r" + "\r" * 7)
    t.expect(r"Satellite \(RS-44\) updated\.")
    send("Q\r")
    return m.group(1)


def offline_case(d, state):
    """No station runs: the imports go into the state file."""
    out = imported(state, write(d, "44909.trsp", TRSP))
    has(out, "RS-44 CW: added from gpredict (435.605 MHz CW)", "the .trsp's CW beacon is a new mode")
    has(out, "1 added, 0 updated, 0 conflicts (yours kept), 1 unchanged", "the transponder agrees with the shipped SSB")
    out = imported(state, write(d, "Doppler.SQF", SQF))
    has(out, "HO-113 CW: added from satpc32 (435.170 MHz CW, up 145.870 MHz CW)", "the SQF's CW line is a new mode")
    out = imported(state, write(d, "SubTone.SQF", SUBTONE))
    has(out, "0 added, 0 updated, 0 conflicts (yours kept), 2 unchanged", "the shipped tones agree with SubTone.SQF")
    out = diff(state)
    has(out, "RS-44 CW downlink 435.605 MHz (gpredict)", "diff names the .trsp as the CW beacon's source")
    has(out, "HO-113 CW uplink 145.870 MHz (satpc32)", "diff names SatPC32")
    has(out, "RS-44 SSB downlink 435.640 MHz (freq/mode file)", "the shipped values' source")
    # A bad file: refused naming the line and field; nothing changed.
    before = open(os.path.join(state, "trakbox-state.json"), "rb").read() if os.path.exists(os.path.join(state, "trakbox-state.json")) else None
    code, _, err = radio(state, "import", write(d, "bad.sqf", "RS-44,435640,145965,USB,LSB,REV,0,0,SSB\nRS-44,435.64\n"))
    check(code == 1 and "bad.sqf: line 2: found 2 fields" in err and "nothing changed" in err,
          f"a bad SQF is refused naming its line: {code} {err}")
    if before is not None:
        check(open(os.path.join(state, "trakbox-state.json"), "rb").read() == before, "the refused file changed nothing")


def station_case(d, state):
    """A station runs: the imports go through its socket; the operator's edit survives them."""
    p = subprocess.Popen([BIN, "--line", "--state", state, "--clock", CLOCK, "--satrak-port", "0", "--data", DATA],
                         stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        t = Terminal(p.stdout.fileno())
        send = lambda s: (p.stdin.write(s.encode()), p.stdin.flush())  # noqa: E731
        t.expect(r"Select \[1-8,S,M\]:")
        was = edit_rs44_downlink(t, send, "435.650")
        check(was == "435.640", f"3-1 showed RS-44's shipped downlink: {was}")
        t.expect(r"Select \[1-8,S,M\]:")

        out = imported(state, write(d, "transmitters.json", json.dumps(SATNOGS)))
        has(out, "RS-44 SSB downlink: kept your 435.650 MHz (operator); satnogs says 435.640 MHz",
            "SatNOGS' value for an edited field is reported, the operator's kept")
        check("437.550" not in out and "t3" not in out, f"the inactive transmitter is not offered:\n{out}")
        check(out.splitlines()[-1].endswith("; 2 transmitters not alive or not active, not offered"),
              f"the count of transmitters not offered:\n{out}")
        out = imported(state, write(d, "44909.trsp", TRSP))
        has(out, "RS-44 SSB downlink: kept your 435.650 MHz (operator); gpredict says 435.640 MHz",
            "a re-import of the .trsp keeps the edit and says so")
        out = imported(state, write(d, "Doppler.SQF", SQF))
        has(out, "RS-44 SSB downlink: kept your 435.650 MHz (operator); satpc32 says 435.640 MHz",
            "a re-import of the SQF keeps the edit and says so")
        out = imported(state, write(d, "satellite_database.json", json.dumps(OSCARWATCH)))
        has(out, "AO-07 CW: added from oscarwatch (145.970 MHz CW)", "OscarWatch's AO-7 is AO-07, its beacon a new mode")
        out = diff(state)
        has(out, "RS-44 SSB downlink 435.650 MHz (operator); satpc32 says 435.640 MHz", "diff shows the conflict")
        has(out, "AO-07 CW downlink 145.970 MHz (oscarwatch)", "diff names OscarWatch")
        check(not re.search(r"ISS \S+ downlink 437\.550", out), "no mode from the inactive transmitter")
        code, only, err = radio(state, "diff", "RS-44", "--conflicts")
        check(code == 0 and only.splitlines() == ["RS-44 SSB downlink 435.650 MHz (operator); satpc32 says 435.640 MHz"],
              f"diff RS-44 --conflicts: the one conflict: {code} {only!r} {err}")
        code, _, err = radio(state, "diff", "RS-99")
        check(code == 1 and "no satellite named 'RS-99'" in err, f"diff of an unknown satellite: {code} {err}")
        # --replace takes the list's value.
        out = imported(state, os.path.join(d, "44909.trsp"), "--replace")
        has(out, "RS-44 SSB downlink: 435.640 MHz from gpredict (was 435.650 MHz, operator)", "--replace takes the list's")
        send("Q\r")
    finally:
        try:
            p.stdin.close()
        except OSError:
            pass
        try:
            p.wait(20)
        except subprocess.TimeoutExpired:
            p.kill()
            p.wait()
    data = load_state(os.path.join(state, "trakbox-state.json"))
    rs44 = next(s for s in data["db"]["satellites"] if s["elements"]["name"] == "RS-44")
    names = [m["name"] for m in rs44["modes"]]
    check(names[:3] == ["SSB", "FT4", "CW"], f"RS-44's modes in the state file: {names}")
    ssb = rs44["modes"][0]
    check(ssb["sources"]["downlink"]["from"] == "gpredict", f"the SSB downlink's source is stored: {ssb['sources']}")


def main():
    with tempfile.TemporaryDirectory(prefix="trakbox-radio-import-") as d:
        state = os.path.join(d, "state")
        offline_case(d, state)
        station_case(d, state)


if __name__ == "__main__":
    run_test(main)
