"""Shipped data not found (issue 39): a binary run away from its data says, under the banner, the
directory it looked in and how to name another (--data, TRAKBOX_DATA), not only "the database is
empty" later in menu 3-2."""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, check, in_temp_dir, run_test  # noqa: E402
from _tbui import ScreenUI  # noqa: E402

PROMPT = r"Select \[1-8,S,M\]:"


def walk(tmp):
    nowhere = os.path.join(tmp, "no-such-data")
    ui = ScreenUI([BIN, "--state", os.path.join(tmp, "state"), "--data", nowhere, "--clock", CLOCK,
                   "--satrak-port", "0"], cols=120)
    try:
        screen = ui.prompt(PROMPT)
        flat = "".join(screen.split())  # (a long line wraps at the screen's edge, maybe mid-word)
        said = f"No shipped elements in {nowhere} (amateur.tle): the database is empty."
        check("".join(said.split()) in flat, f"the path tried is not on the screen:\n{screen}")
        check("--dataDIR" in flat, f"nor how to name another:\n{screen}")
        ui.leave()
    finally:
        ui.close()


def main():
    in_temp_dir("trakbox-data-missing-", walk)


if __name__ == "__main__":
    run_test(main)
