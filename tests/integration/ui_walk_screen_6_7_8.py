"""Menus 6 (6-0 display, 6-3 dead band and skew, 6-6 direct control with presets, 6-4 parking and
limits, 6-9 default parameters with good and bad station file uploads), 7 (host mode) and 8 (direct
antenna control):
walked in full screen (_walk.walk_screen says how), the transcripts of ui_walk_line_6_7_8.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import _walk as w  # noqa: E402

if __name__ == "__main__":
    w.screen_test(w.group_6_7_8)
