"""The full-screen (ncurses) front end driven in tmux as a person would: keys with send-keys, the
screen read with capture-pane. Checks the status line, in-place live updates, the sky plot and
world map, menu 2's plot of a pass (P), an edit through menu 4, and that Ctrl-C leaves with the state saved.
"""
import json
import os
import re
import shutil
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbui import TmuxPane  # noqa: E402
from _tbharness import BIN, CLOCK, check, run_test  # noqa: E402

SESSION = f"trakbox-it-{os.getpid()}"


pane = TmuxPane(SESSION)
tmux, screen, wait_for, keys = pane.tmux, pane.screen, pane.wait_for, pane.keys


def main():
    state = tempfile.mkdtemp(prefix="trakbox-ui-")
    pane.start(f"{BIN} --state {state} --clock {CLOCK} --satrak-port 0")
    try:
        wait_for(r"Select \[1-8,S,M\]:")
        s = wait_for(r"UTC \| .* \| Rotor SIM OFF")
        last = s.rstrip("\n").splitlines()[-1]
        check(re.search(r"2026/05/21 12:0\d:\d\d UTC \| .* \| Rotor SIM OFF", last), f"status line: {last!r}")

        # S: single tracking with rotor control on; the ISS rises at 12:09:09 from this station.
        keys("S", "Enter")
        wait_for(r"Select :")
        keys("4", "Enter")
        s = wait_for(r"\[Satellite:\*ISS\]")
        s = wait_for(r"pass 12:09:09-12:15:35")
        time.sleep(2.5)
        s = screen()
        rows = re.findall(r"^\d\d:\d\d:\d\d\s+[\d.]+\s+-?[\d.]+", s, re.M)
        check(len(rows) == 1, f"the live row is redrawn in place, not scrolled: {rows}")
        check("Rotor control ON" in s, "S switches rotor control on")
        check(re.search(r"^\s*\.*A?\.*N", s, re.M) or " N" in s, "the sky plot's north mark")
        check("Q" in s and "#" in s and "@" in s, "world map with station, land and satellite")
        check(s.count("\x1b") == 0, "capture is plain text")
        first = rows[0]
        time.sleep(1.5)
        rows2 = re.findall(r"^\d\d:\d\d:\d\d\s+[\d.]+\s+-?[\d.]+", screen(), re.M)
        check(rows2 and rows2[0] != first, "the row changes every second")

        # E toggles rotor control off, the status line follows.
        keys("E")
        wait_for(r"Rotor control OFF")
        keys("q")
        wait_for(r"Select \[1-8,S,M\]:")

        # Menu 2's P: the schedule's pass drawn as the realtime display draws it, then the page again.
        keys("2", "Enter")
        wait_for(r"Select :")
        keys("4", "Enter")
        wait_for(r"Day of the Year \[T\] >")
        keys("Enter", "Enter", "Enter")
        wait_for(r"- 'Q' for abort 'S' for scroll")
        keys("P")
        s = wait_for(r"any key to return to the schedule")
        check(re.search(r"^ISS: pass 2026/05/21 AOS 12:09:09 az [\d.]+, max el [\d.]+ at 12:1\d:\d\d az [\d.]+, "
                        r"LOS 12:15:35 az [\d.]+", s, re.M), f"the pass in words: {s[:300]}")
        check("ISS  pass 12:09:09-12:15:35" in s and " N" in s and "o pass" in s, "its sky plot and legend")
        keys("Space")
        s = wait_for(r"DATE       TIME      AZ/EL")
        check("any key to return" not in s and "o pass" not in s, "the page again, the plot gone")
        keys("Q")
        wait_for(r"Select \[1-8,S,M\]:")

        # Menu 4 in full screen.
        keys("4", "Enter")
        wait_for(r"Callsign\s+: NOCALL")
        keys("VK2XYZ", "Enter")
        for _ in range(6):
            keys("Enter")
        wait_for(r"Horizon mask\s+: none\s*\nStation saved: VK2XYZ .*\n----- MAIN MENU -----")

        # Ctrl-C leaves trakbox; the state is saved.
        keys("C-c")
        wait_for(r"EXITED 0", timeout=15)
        doc = json.load(open(os.path.join(state, "trakbox-state.json")))
        check(doc["data"]["station"]["callsign"] == "VK2XYZ", "callsign saved")
        check(doc["data"]["rotor_control"] is False, "rotor control off as left")
    finally:
        tmux("kill-session", "-t", SESSION)
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
