"""Yaesu's ASCII CAT rigs as one leg each (issue 61): the FTX-1 (ID0840;) and the FT-991A
(ID0670;) against responders of our own (_newcat.py) on socat ptys.

RS-44 (2026-05-21, near its culmination, --clock): --radio ftx1 (the downlink on VFO-A: FA, MD02)
with --uplink-radio ft991 on VFO-B (FB, the VFO the FT-991A retunes while the mic is keyed; its MD
reaches VFO-A only, so the mode goes over with AB and FB is sent again); each radio asked ID; once;
never ST; the worst tuning error of each link over the pass is measured.
SO-50: the FT-991A on the uplink in FM with the dial locked (LK1) and the 67.0 Hz tone
(CN00000;CT02; then AB); then the other way round, the FTX-1 on the uplink (FB, MD14: its Sub): it
has no CTCSS trakbox sets, a limit learnt once ("no CTCSS"), and the Doppler goes on.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from _newcat import Newcat  # noqa: E402
from _ptyradio import RS44_PASS, SO50_PASS, SPOTS  # noqa: E402
from _rigs2026 import leave, limit_in_log, near, track, worst_error  # noqa: E402
from _tbharness import check, need, poll, run_test  # noqa: E402


def ftx1(path):
    return Newcat(path, ident="0840", md1=True, tones=False)


def ft991(path):
    return Newcat(path, ident="0670")


def no_st(*rigs):
    for r in rigs:
        check(not any(c.startswith("ST") for c in r.sent()), f"never ST: {r.sent()[:6]}")


def rs44(rigs, tb, state, clock_now):
    down, up = rigs
    near("RS-44's downlink on the FTX-1's VFO-A", lambda: down.get("a"), SPOTS["RS-44"][0], 12_000)
    near("RS-44's uplink on the FT-991A's VFO-B", lambda: up.get("b"), SPOTS["RS-44"][1], 5_000)
    check(down.mode["a"] == "2" and up.mode["b"] == "1", f"USB down, LSB on VFO-B: {down.mode} {up.mode}")
    worst = worst_error("RS-44", SPOTS["RS-44"], lambda: down.get("a"), lambda: up.get("b"), clock_now, 8)
    check(worst[0] < 400 and worst[1] < 400, f"RS-44 worst {worst}")
    check(down.sent()[0] == "ID;" and up.sent()[0] == "ID;", f"ID; first: {down.sent()[:2]} {up.sent()[:2]}")
    check(all(c == "ID;" or c[:2] in ("FA", "MD") for c in down.sent()), f"FTX-1: FA and MD0 only {down.sent()[:8]}")
    check(not any(c.startswith("FA") for c in up.sent()), "the FT-991A's VFO-A not tuned")
    no_st(down, up)
    leave(tb, state)
    print(f"ftx1 + ft991 RS-44: worst tuning error {worst[0]:.0f} Hz down (FTX-1 FA), {worst[1]:.0f} Hz up "
          f"(FT-991A FB); FTX-1 {down.sent()[:3]}, FT-991A {up.sent()[:6]}")


def so50_ft991_up(rigs, tb, state, clock_now):
    down, up = rigs
    near("SO-50's downlink on the FTX-1", lambda: down.get("a"), SPOTS["SO-50"][0], 12_000)
    near("SO-50's uplink on the FT-991A's VFO-B", lambda: up.get("b"), SPOTS["SO-50"][1], 5_000)
    poll("the 67.0 Hz tone (number 000) copied to VFO-B", lambda: up.tone["b"] == 0, 10)
    check(up.mode["b"] == "4" and up.lock_on, f"FM on VFO-B, the dial locked: {up.mode} LK {up.lock_on}")
    sent = up.sent()
    check("CN00000;" in sent and "CT02;" in sent, f"67.0 Hz: {sent[:12]}")
    worst = worst_error("SO-50", SPOTS["SO-50"], lambda: down.get("a"), lambda: up.get("b"), clock_now, 3)
    check(worst[0] < 1000 and worst[1] < 1000, f"SO-50 worst {worst}")
    no_st(down, up)
    leave(tb, state)
    check(up.sent()[-1] == "LK0;", f"the dial unlocked at the end: {up.sent()[-3:]}")
    print(f"ftx1 + ft991 SO-50: worst {worst[0]:.0f} / {worst[1]:.0f} Hz; FT-991A {[c for c in sent if c[:2] in ('CN', 'CT', 'LK', 'AB')][:5]}")


def so50_ftx1_up(rigs, tb, state, clock_now):
    down, up = rigs
    near("SO-50's downlink on the FT-991A's VFO-A", lambda: down.get("a"), SPOTS["SO-50"][0], 12_000)
    near("SO-50's uplink on the FTX-1's FB", lambda: up.get("b"), SPOTS["SO-50"][1], 5_000)
    check(up.mode["b"] == "4", f"FM on the FTX-1's Sub (MD14): {up.mode}")
    worst = worst_error("SO-50", SPOTS["SO-50"], lambda: down.get("a"), lambda: up.get("b"), clock_now, 3)
    check(worst[0] < 1000 and worst[1] < 1000, f"SO-50 worst {worst}")
    check(not any(c[:2] in ("CN", "CT") for c in up.sent()), "no tone command to the FTX-1")
    no_st(down, up)
    log = leave(tb, state)
    line = limit_in_log(log, "FTX-1", "no CTCSS")
    print(f"ft991 + ftx1 SO-50: worst {worst[0]:.0f} / {worst[1]:.0f} Hz; limit: {line.strip()}")


def main():
    need("socat")
    track(RS44_PASS[0], RS44_PASS[1], ("ftx1:{}", ftx1), rs44, up=("ft991:{}", ft991))
    track(SO50_PASS[0], SO50_PASS[1], ("ftx1:{}", ftx1), so50_ft991_up, up=("ft991:{}", ft991))
    track(SO50_PASS[0], SO50_PASS[1], ("ft991:{}", ft991), so50_ftx1_up, up=("ftx1:{}", ftx1))


if __name__ == "__main__":
    run_test(main)
