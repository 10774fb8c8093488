"""Menu M (multiple tracking in normal and priority mode, the '*', '!' and '&' markers) on real
passes of the shipped database, the tracking list from 3-2 and 3-4, the times from menu 5:
walked on the real binary over a serial line: trakbox --tty on one end of a socat pty pair at
9600 bps, this script the operator's terminal on the other. The transcripts are in _walk.py (the
same ones ui_walk_screen_m walks in full screen); the stored state is checked after each change
and after SIGTERM.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import _walk as w  # noqa: E402
from _tbharness import run_test  # noqa: E402


def main():
    w.walk_serial(w.group_m)


if __name__ == "__main__":
    run_test(main)
