"""Menu M (multiple tracking in normal and priority mode, the '*', '!' and '&' markers) on real
passes of the shipped database, the tracking list from 3-2 and 3-4, the times from menu 5:
walked on the real binary's full-screen front end in tmux (100x40, send-keys, capture-pane): the
same transcripts as ui_walk_line_m (_walk.py), asserted on what the screen shows; the stored state
is checked after each change and after Ctrl-C.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import _walk as w  # noqa: E402
from _tbharness import run_test  # noqa: E402


def main():
    w.walk_screen(w.group_m)


if __name__ == "__main__":
    run_test(main)
