"""Menus 2 (schedule) and 3 (3-1 edit, 3-2 select, 3-4 multi track, 3-3 NASA and AMSAT uploads
ending in Ctrl-Z with the freq/mode file, and uploads that fail and leave the state file as it was):
walked in full screen (_walk.walk_screen says how), the transcripts of ui_walk_line_2_3.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import _walk as w  # noqa: E402

PAGE = 37  # 40 rows less the status line, the header and the prompt

if __name__ == "__main__":
    w.screen_test(w.group_2_3, page_rows=PAGE)
