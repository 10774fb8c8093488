"""`passes --plot` on crowded passes (issue 47): in the SVG it writes, no two words overlap or stand
closer than 2 px side by side. Each
<text> is held to the width cairo measured (textLength), so its box is the one placed: from x,
0.8 of the font size above the baseline to 0.25 below, textLength wide. The passes are the ones
whose AOS, TCA and LOS crowd: the shortest grazing passes of the shipped set over three days (the
smallest azimuth span from AOS to LOS, the labels near the horizon's compass letters and azimuth
numbers), and the highest (the TCA label by the zenith's ring labels)."""
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, SOURCE, check, in_temp_dir, run_test, sh  # noqa: E402

TLE = os.path.join(SOURCE, "data", "amateur.tle")
STATION = ["--station", "27.391,128.657,50"]
TEXT = re.compile(r'<text x="([-\d.]+)" y="([-\d.]+)" font-size="([\d.]+)" textLength="([\d.]+)"[^>]*>([^<]*)</text>')


def span(p):
    d = abs(p["aos_az_deg"] - p["los_az_deg"]) % 360
    return min(d, 360 - d)


def boxes(path):
    with open(path) as f:
        svg = f.read()
    out = []
    for x, y, size, width, words in TEXT.findall(svg):
        x, y, size, width = float(x), float(y), float(size), float(width)
        out.append((words, x, y - 0.8 * size, x + width, y + 0.25 * size))
    return out, svg.count("<text")


GAP = 2.0   # side by side, words closer than this read as one


def overlapping(b):
    return [(a[0], c[0]) for i, a in enumerate(b) for c in b[i + 1:]
            if a[1] < c[3] + GAP and c[1] < a[3] + GAP and a[2] < c[4] and c[2] < a[4]]


def walk(tmp):
    code, out, err = sh(BIN, "passes", TLE, *STATION, "--start", "2026-05-21T00:00:00Z", "--hours", "72", "--json",
                        timeout=120)
    check(code == 0, f"passes: {code} {err}")
    passes = [p for p in json.loads(out) if p["los_utc"]]
    crowded = sorted(passes, key=span)[:6] + sorted(passes, key=lambda p: -p["max_el_deg"])[:2]
    words = 0
    for k, p in enumerate(crowded):
        path = os.path.join(tmp, f"p{k}.svg")
        code, out, err = sh(BIN, "passes", TLE, *STATION, "--sat", p["sat"], "--start", p["aos_utc"][:19] + "Z",
                            "--hours", "0.5", "--plot", path)
        made = [f for f in os.listdir(tmp) if f.startswith(f"p{k}")]
        check(code == 0 and made, f"plot of {p['sat']} {p['aos_utc']}: {code} {err}")
        for name in made:
            b, count = boxes(os.path.join(tmp, name))
            check(len(b) == count and count >= 20, f"{name}: every <text> read with its textLength ({len(b)}/{count})")
            check(any(w[0].startswith("TCA ") for w in b), f"{name}: the TCA label is there")
            bad = overlapping(b)
            check(not bad, f"{p['sat']} {p['aos_utc']} ({span(p):.0f} deg from AOS to LOS, max {p['max_el_deg']:.1f}): "
                           f"labels overlap: {bad}")
            words += len(b)
    print(f"{len(crowded)} crowded passes plotted, {words} words, none overlapping")


run_test(lambda: in_temp_dir("trakbox-labels-", walk))
