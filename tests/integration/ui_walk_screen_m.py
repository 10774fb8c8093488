"""Menu M (multiple tracking in normal and priority mode, the '*', '!' and '&' markers) on real
passes of the shipped database, the tracking list from 3-2 and 3-4, the times from menu 5:
walked in full screen (_walk.walk_screen says how), the transcripts of ui_walk_line_m.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
import _walk as w  # noqa: E402

if __name__ == "__main__":
    w.screen_test(w.group_m)
