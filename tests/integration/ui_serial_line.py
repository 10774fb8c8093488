"""The TrakBox menus over a serial line: trakbox --tty on one end of a socat pty pair at 9600 bps,
this script as the operator's terminal on the other. Walks the manual's examples that are wired so
far, checks there are no escape codes, and checks the stored state afterwards.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import CLOCK, SerialPair, Terminal, Trakbox, check, run_test  # noqa: E402


def main():
    pair = SerialPair()
    tb = None
    fd = None
    try:
        tb = Trakbox(["--tty", pair.trakbox_side, "--baud", "9600", "--clock", CLOCK])
        fd = os.open(pair.terminal_side, os.O_RDWR | os.O_NOCTTY)
        t = Terminal(fd)

        # Sign-on and main menu (a fresh state: no RAM-lost message).
        t.expect(r"TrakBox 8052 v3\.10a")
        t.expect(r"----- MAIN MENU -----")
        t.expect(r"Select \[1-8,S,M\]:")
        check("Data in RAM was lost" not in t.transcript, "fresh start must not report lost RAM")

        # Menu 4: the manual's station example, typed a character at a time as a person would.
        t.send("4\r")
        t.expect(r"Callsign\s+: NOCALL")
        t.send("WA7GXD\r", pace=0.002)
        t.expect(r"Latitude.*: \+27\.391")
        t.send("32.259\r")
        t.expect(r"Longitude.*: \+128\.657")
        t.send("-110.778\r")
        t.expect(r"Height.*: 50\.000")
        t.send("842\r")
        t.expect(r"Rotor start.*: South")
        t.send("S\r")
        t.expect(r"COM port baud rate\s*: 9600")
        t.send("\r")
        t.expect(r"Horizon mask\s*: none")
        t.send("\r")
        t.expect(r"Select \[1-8,S,M\]:")

        # A bad value is refused with the reason and asked again; Enter keeps the rest.
        t.send("4\r")
        t.expect(r"Callsign\s+: WA7GXD")
        t.send("\r")
        t.expect(r"Latitude.*: \+32\.259")
        t.send("95\r")
        t.expect(r"95 is out of range: expected -90 to 90")
        t.expect(r"Latitude.*: \+32\.259")
        t.send("\r\r\r\r\r\r")
        t.expect(r"Select \[1-8,S,M\]:")

        # Menu 1: the list with the '*' marker, Enter takes it, the live display prints a line per
        # update, Q returns.
        t.send("1\r")
        t.expect(r"\*\*\* Tracking object satellite \*\*\*")
        t.expect(r" 1\.\*AO-07")
        t.send("4\r")
        t.expect(r"\[Satellite:\*ISS\]")
        t.expect(r"HH:MM:SS\s+deg\s+deg\s+Km\s+Km\s+deg\s+deg\s+<256>\s+Hz")
        rows = [t.expect(r"\r\n(\d\d:\d\d:\d\d)\s+[\d.]+\s+-?[\d.]+\s+[\d.]+") for _ in range(2)]
        check(rows[0].group(1) != rows[1].group(1), "the live display must update")
        t.send("q")
        t.expect(r"Select \[1-8,S,M\]:")

        # Menu 5: set the clock as in the manual's example.
        t.send("5\r")
        t.expect(r"Enter 'Ret' for Real Time Clock set")
        t.send("\r")
        t.expect(r"Set time: ")
        t.send("93/07/17 03:03:15\r")
        t.expect(r"ENTER when ready\.")
        t.send("\r")
        t.expect(r"Present Time:UTC 1993/07/17 03:03:1[5-6]")
        t.expect(r"Select \[1-8,S,M\]:")

        check("\x1b" not in t.transcript, "no escape codes on a serial line")
        check("\r\n" in t.transcript, "a serial terminal gets CR LF line ends")

        code = tb.stop()
        check(code == 0, f"trakbox exit status {code} after SIGTERM")
        state = json.load(open(tb.state_file))
        station = state["data"]["station"]
        check(station["callsign"] == "WA7GXD", f"callsign stored: {station}")
        check(station["lat_deg"] == 32.259 and station["lon_deg"] == -110.778, f"position stored: {station}")
        check(station["height_m"] == 842 and station["rotor_start"] == "south", f"height/rotor stored: {station}")

        # A restart keeps everything: the prompt shows the stored values.
        tb2 = Trakbox(["--tty", pair.trakbox_side, "--baud", "9600", "--clock", CLOCK], state_dir=tb.state_dir)
        try:
            t.expect(r"Select \[1-8,S,M\]:", timeout=15)
            t.send("4\r")
            t.expect(r"Callsign\s+: WA7GXD")
            t.send("\r\r\r\r\r\r\r")
            t.expect(r"Select \[1-8,S,M\]:")
            check(tb2.stop() == 0, "second run stops cleanly")
        finally:
            tb2.cleanup()
    finally:
        if fd is not None:
            os.close(fd)
        if tb:
            tb.cleanup()
        pair.close()


if __name__ == "__main__":
    run_test(main)
