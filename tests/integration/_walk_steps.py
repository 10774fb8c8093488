"""The walkthroughs' shared steps (_walk.py): the menus' prompts, the checks of what the terminal
showed, answering a prompt, a step of keys, prompt and check, reading positions off the monitor."""
import os
import re

from _tbharness import SOURCE, Failure  # noqa: E402


MAIN = r"Select \[1-8,S,M\]:"
UPDATE = r" Select:"              # the UPDATE MENU and the Configuration Menu prompt
DIRECT = r"Select\[1-3,Q\]:"
PRESET = r" Select\[1-5,S,Q\]:"
SCROLL = r"- 'Q' for abort 'S' for scroll"
DATA = os.path.join(SOURCE, "data")

# The factory station (menu 4's defaults) that the passes below are computed for.
FACTORY_STATION = "27.391,128.657,50"


def must(text, rx, what):
    """rx must occur in what the terminal showed; returns the match."""
    m = re.search(rx, text, re.M)
    if not m:
        raise Failure(f"{what}: expected {rx!r} in:\n{text[-3000:]}")
    return m


def must_not(text, rx, what):
    m = re.search(rx, text, re.M)
    if m:
        raise Failure(f"{what}: {m.group(0)!r} must not appear in:\n{text[-3000:]}")


def answer(ui, label_rx, keys, what, timeout=10.0):
    """Waits at a prompt, then types the answer."""
    try:
        out = ui.prompt(label_rx, timeout)
    except Failure as e:
        raise Failure(f"{what}: {e}") from None
    ui.send(keys)
    return out


def step(ui, keys, prompt_rx, rx, what, timeout=10.0):
    """Types keys, waits for the next prompt, and what the terminal showed meanwhile must hold rx.
    Returns what it showed."""
    ui.send(keys)
    out = ui.prompt(prompt_rx, timeout)
    must(out, rx, what)
    return out


def monitor_positions(text):
    """Every 'AZ= 519 / 32.8deg EL= 462 / 90.0deg.' line shown: [(az_counts, az, el_counts, el)]."""
    return [(int(a), float(b), int(c), float(d))
            for a, b, c, d in re.findall(r"AZ=\s*(\d+) / ([\d.]+)deg EL=\s*(\d+) / (-?[\d.]+)deg\.", text)]


def since(text, marker):
    """The text after the last occurrence of marker (what a screen shows below it)."""
    return text.rsplit(marker, 1)[-1]


def last_match(text, rx, what):
    found = list(re.finditer(rx, text, re.M))
    if not found:
        raise Failure(f"{what}: expected {rx!r} in:\n{text[-3000:]}")
    return found[-1]


def az_diff(a, b):
    return abs((a - b + 180.0) % 360.0 - 180.0)


# ---------------------------------------------------------------------------------------------
# Menu 2: Display Schedule (the shipped database, the factory station, clock 2026-05-21 12:08:30)
