"""Issue 30, item 4: a first start the operator can follow. In tmux, full screen, on a fresh state:
the main menu shows how to leave; Q asks "leave trakbox? [Y/N]" and Y saves and exits 0. --rotator
given once is stored like --uplink-radio: a later plain start drives it, says so under the
banner, and the status bar and 6-0 name it (Hamlib's dummy rotator, model 1, needs no device).
"""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, check, load_state, run_test  # noqa: E402
from _tbui import ScreenUI  # noqa: E402

PROMPT = r"Select \[1-8,S,M\]:"


def start(state, *extra):
    return ScreenUI([BIN, "--state", state, "--clock", CLOCK, "--satrak-port", "0", *extra], cols=120)


def main():
    state = tempfile.mkdtemp(prefix="trakbox-first-start-")
    try:
        ui = start(state, "--rotator", "hamlib:1:/dev/null")
        try:
            screen = ui.prompt(PROMPT)
            check("     Q. Leave trakbox." in screen, f"the main menu does not say how to leave:\n{screen}")
            ui.send("3")
            ui.prompt(r"Select:")
            ui.send("Q")      # back to the main menu
            ui.prompt(PROMPT)
            ui.send("Q")      # one Q too many: a question, not an exit
            screen = ui.prompt(r"leave trakbox\? \[Y/N\]")
            ui.send("N")
            ui.prompt(PROMPT)
            ui.leave()
        finally:
            ui.close()
        drivers = load_state(os.path.join(state, "trakbox-state.json"))["drivers"]
        check(drivers == {"rotator": "hamlib:1:/dev/null", "radio": ""}, f"stored drivers: {drivers}")

        ui = start(state)
        try:
            screen = ui.prompt(PROMPT)
            check("Rotator: hamlib:1:/dev/null (hamlib 1, stored;" in screen, f"the stored rotator is not said:\n{screen}")
            status = ui.wait(r"Rotor hamlib 1 ").split("\n")[-1]
            check("| Radio SIM " in status, f"status line: {status!r}")
            ui.send("6")
            ui.prompt(r"Select:")
            ui.send("0")
            screen = ui.prompt(r"Press any key to continue")
            check("Drivers          Rotor hamlib 1 (hamlib:1:/dev/null)  Radio SIM (simulated)" in screen,
                  f"6-0 does not name the drivers:\n{screen}")
        finally:
            ui.close()
    finally:
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
