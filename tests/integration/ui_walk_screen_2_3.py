"""Menus 2 (schedule) and 3 (3-1 edit, 3-2 select, 3-4 multi track, 3-3 NASA and AMSAT uploads
ending in Ctrl-Z with the freq/mode file, and uploads that fail and leave the state file as it was):
walked on the real binary's full-screen front end in tmux (100x40, send-keys, capture-pane): the
same transcripts as ui_walk_line_2_3 (_walk.py), asserted on what the screen shows; the stored state
is checked after each change and after Ctrl-C.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import _walk as w  # noqa: E402
from _tbharness import run_test  # noqa: E402

PAGE = 37  # 40 rows less the status line, the header and the prompt


def main():
    w.walk_screen(w.group_2_3, page_rows=PAGE)


if __name__ == "__main__":
    run_test(main)
