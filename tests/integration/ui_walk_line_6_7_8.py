"""Menus 6 (6-0 display, 6-3 dead band and skew, 6-6 direct control with presets, 6-4 parking and
limits, 6-9 default parameters with good and bad station file uploads), 7 (host mode) and 8 (direct
antenna control):
walked on the real binary over a serial line: trakbox --tty on one end of a socat pty pair at
9600 bps, this script the operator's terminal on the other. The transcripts are in _walk.py (the
same ones ui_walk_screen_6_7_8 walks in full screen); the stored state is checked after each change
and after SIGTERM.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import _walk as w  # noqa: E402
from _tbharness import check, run_test  # noqa: E402


def beep_before_6_9(transcript):
    check("\x07Configure your station elements" in transcript, "6-9: a beep tone, then the question")


def main():
    w.walk_serial(w.group_6_7_8, transcript_checks=[beep_before_6_9])


if __name__ == "__main__":
    run_test(main)
