"""Menus 6 (6-0 display, 6-3 dead band and skew, 6-6 direct control with presets, 6-4 parking and
limits, 6-9 default parameters with good and bad station file uploads), 7 (host mode) and 8 (direct
antenna control):
walked on the real binary's full-screen front end in tmux (100x40, send-keys, capture-pane): the
same transcripts as ui_walk_line_6_7_8 (_walk.py), asserted on what the screen shows; the stored state
is checked after each change and after Ctrl-C.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import _walk as w  # noqa: E402
from _tbharness import run_test  # noqa: E402


def main():
    w.walk_screen(w.group_6_7_8)


if __name__ == "__main__":
    run_test(main)
