"""Menu 1's typed tuning in the real binary's full-screen menus, driven in tmux as a person would
(issue 47): RS-44 chosen a minute before its culmination, S typed 435.645 moves the passband +5 kHz
and the simulated radio's dials follow by the inverting transponder's rule (downlink up 5 kHz,
uplink down 5 kHz); T typed -300 moves the uplink dial 300 Hz down and is kept for RS-44; a spot
outside the passband and a TX offset out of range are refused on the screen, naming the value and
the range, and nothing changes."""
import json
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from _tbui import TmuxPane  # noqa: E402
from _tbharness import BIN, check, poll, run_test, sh  # noqa: E402

SESSION = f"trakbox-tune-{os.getpid()}"
CLOCK = "2026-05-21T10:57:00Z"   # a minute before RS-44's culmination over the factory station


pane = TmuxPane(SESSION)
tmux, screen, wait_for, keys = pane.tmux, pane.screen, pane.wait_for, pane.keys


def radio(state):
    """The simulated radio's dials and trakbox's tuning, from `trakbox status`."""
    code, out, err = sh(BIN, "status", "--state", state, "--json")
    check(code in (0, 1), f"status: {code} {err}")   # 1: running, with a problem named
    s = json.loads(out)
    r = s["radios"][0]
    return r["downlink_hz"], r["uplink_hz"], s["radios"][0].get("tuning") or {}


def settled(state, what, pred):
    """The dials once pred(tuning) holds and a tick has sent them (two readings a tick apart agree
    with the tuning's dials)."""
    def ready():
        down, up, t = radio(state)
        return (down, up, t) if pred(t) and down == t.get("downlink_dial_hz") and up == t.get("uplink_dial_hz") else None
    return poll(what, ready, 10)


def main():
    state = tempfile.mkdtemp(prefix="trakbox-tune-")
    pane.start(f"{BIN} --state {state} --clock {CLOCK} --satrak-port 0")
    try:
        wait_for(r"Select \[1-8,S,M\]:")
        keys("1", "Enter")
        s = wait_for(r"Select :")
        number = re.search(r"(\d+)\.[ *]?RS-44", s)
        check(number, f"RS-44 in the tracking list:\n{s}")
        keys(number.group(1), "Enter")
        s = wait_for(r"\[Satellite:\*RS-44\]")
        check("'S' type the spot  'R'/'T' type the RX/TX offset  'L' log a QSO  'M' mode" in s, f"the keys are listed:\n{s}")
        d0, u0, t0 = settled(state, "RS-44 tuned", lambda t: t.get("satellite") == "RS-44")
        check(t0["downlink_spot_hz"] == 435640000, f"the record's spot: {t0}")

        keys("S")
        wait_for(r"Spot \(downlink, MHz 435.645 or Hz 435645000\) >")
        keys("435.645", "Enter")
        wait_for(r"spot 435645000 Hz down, 145960000 Hz up")
        d1, u1, t1 = settled(state, "the dials after the spot", lambda t: t.get("downlink_spot_hz") == 435645000)
        # What the Doppler changed between the readings is taken out: the tuning's Doppler of each.
        dd = (d1 - t1["downlink_doppler_hz"]) - (d0 - t0["downlink_doppler_hz"])
        du = (u1 - t1["uplink_doppler_hz"]) - (u0 - t0["uplink_doppler_hz"])
        check(abs(dd - 5000) <= 100 and abs(du + 5000) <= 100, f"dials moved {dd:+} Hz down, {du:+} Hz up")
        print(f"menu 1 S 435.645: downlink dial {dd:+} Hz, uplink dial {du:+} Hz (Doppler taken out)")

        keys("T")
        wait_for(r"TX offset \(Hz, e.g. -300; 0 resets\) >")
        keys("--", "-300", "Enter")   # "--": tmux would read -300 as its options
        wait_for(r"RX offset 0 Hz, TX offset -300 Hz")
        d2, u2, t2 = settled(state, "the uplink dial after the TX offset", lambda t: t.get("tx_offset_hz") == -300)
        du2 = (u2 - t2["uplink_doppler_hz"]) - (u1 - t1["uplink_doppler_hz"])
        dd2 = (d2 - t2["downlink_doppler_hz"]) - (d1 - t1["downlink_doppler_hz"])
        check(abs(du2 + 300) <= 100 and abs(dd2) <= 100, f"TX offset: uplink {du2:+} Hz, downlink {dd2:+} Hz")
        print(f"menu 1 T -300: uplink dial {du2:+} Hz, downlink {dd2:+} Hz")

        keys("S")
        wait_for(r"Spot \(downlink")
        keys("437", "Enter")
        wait_for(r"spot 437000000 Hz is outside RS-44's downlink passband 435610000-435670000 Hz")
        keys("T")
        wait_for(r"TX offset \(Hz")
        keys("200000", "Enter")
        wait_for(r"TX offset 200000 Hz out of range: expected -100000 to 100000")
        _, _, t3 = radio(state)
        check(t3["downlink_spot_hz"] == 435645000 and t3["tx_offset_hz"] == -300, f"nothing changed: {t3}")

        # L in full screen (issue 60, item 5): the answer stays in the live block, as the tuning keys'.
        keys("L")
        wait_for(r"Log QSO: CALL \[GRID\] \[RST\] >")
        keys("W1AW FN31 59", "Enter")
        wait_for(r"Logged #1 W1AW RS-44 \S+ 10:5\d:\d\d UTC")
        keys("L")
        wait_for(r"Log QSO: CALL")
        keys("W1 AW ZZ", "Enter")
        wait_for(r"Not logged: ")
        keys("q")
        wait_for(r"Select \[1-8,S,M\]:")
        keys("C-c")
        wait_for(r"EXITED 0", 15)
        with open(os.path.join(state, "trakbox-state.json")) as f:
            kept = json.load(f)["data"]["radio"]["tx_corrections"]
        check(kept == {"RS-44 SSB": -300}, f"the TX offset kept in the state for RS-44's mode SSB: {kept}")
    finally:
        tmux("kill-session", "-t", SESSION)


run_test(main)
