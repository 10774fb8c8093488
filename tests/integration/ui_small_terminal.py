"""A terminal smaller than 80x24 (issue 39): the full-screen menus say "terminal too small" instead of
wrapping mid-word; keys typed meanwhile still reach the prompt that waits (none lost, none sent
elsewhere), and the screen is drawn again once the terminal is large enough."""
import os
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, check, in_temp_dir, load_state, need, run_test  # noqa: E402
from _tbui import ScreenUI  # noqa: E402

PROMPT = r"Select \[1-8,S,M\]:"


def walk(state):
    ui = ScreenUI([BIN, "--state", state, "--clock", CLOCK, "--satrak-port", "0"], cols=100, rows=40)
    try:
        ui.prompt(PROMPT)
        ui._tmux("resize-window", "-t", ui.session, "-x", "40", "-y", "12")
        screen = ui.wait(r"terminal too small", timeout=10)
        flat = "".join(screen.split())
        check("terminaltoosmall(needs80x24,is40x12)" in flat, f"the message and the sizes:\n{screen}")
        check("MAINMENU" not in flat, f"not the menu wrapped at 40 columns:\n{screen}")
        # Menu 4 chosen while too small: the key goes to the main menu's prompt, as typed.
        ui.send("4")
        time.sleep(0.5)
        ui._tmux("resize-window", "-t", ui.session, "-x", "100", "-y", "40")
        screen = ui.wait(r"Callsign\s+:", timeout=10)
        check("terminal too small" not in screen, f"the message is gone once it fits:\n{screen}")
        ui.send("\x1b")  # Esc leaves menu 4 unchanged
        ui.prompt(PROMPT)
        ui.leave()
    finally:
        ui.close()
    check(load_state(os.path.join(state, "trakbox-state.json"))["station"]["callsign"] == "NOCALL", "nothing changed")


def main():
    need("tmux")
    in_temp_dir("trakbox-small-", walk)


if __name__ == "__main__":
    run_test(main)
