"""Menus 2 (schedule) and 3 (3-1 edit, 3-2 select, 3-4 multi track, 3-3 NASA and AMSAT uploads
ending in Ctrl-Z with the freq/mode file, and uploads that fail and leave the state file as it was):
walked on the real binary over a serial line: trakbox --tty on one end of a socat pty pair at
9600 bps, this script the operator's terminal on the other. The transcripts are in _walk.py (the
same ones ui_walk_screen_2_3 walks in full screen); the stored state is checked after each change
and after SIGTERM.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import _walk as w  # noqa: E402
from _tbharness import run_test  # noqa: E402

PAGE = 22  # the line front end is 80x24: a screenful of the schedule is 22 rows


def main():
    w.walk_serial(w.group_2_3, page_rows=PAGE)


if __name__ == "__main__":
    run_test(main)
