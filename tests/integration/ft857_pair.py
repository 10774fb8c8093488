"""The Yaesu FT-857 and FT-897 as one leg each (issue 61): --radio ft857:PTY1 --uplink-radio
ft897:PTY2 against FT-817-family responders (_ft847.py with ft817=True: the FT-857/897 speak the
FT-817's five-byte commands) on socat ptys.

RS-44 (2026-05-21, near its culmination, --clock): USB on the FT-857, LSB on the FT-897, each read
back (03); every command five bytes with the opcode 01 / 07 / 03, never 00 (LOCK ON on this
family); the worst tuning error of each link over the pass is measured.
SO-50 with the FT-857 alone: the downlink tuned in FM; the uplink is a limit learnt once ("no
uplink", said once), never a lost link.
"""
import os
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
from _ft847 import FT847  # noqa: E402
from _ptyradio import RS44_PASS, SO50_PASS, SPOTS  # noqa: E402
from _rigs2026 import leave, limit_in_log, near, track, worst_error  # noqa: E402
from _tbharness import check, need, run_test  # noqa: E402


def ft8x7(path):
    return FT847(path, ft817=True)


def rs44(rigs, tb, state, clock_now):
    down, up = rigs
    near("RS-44's downlink on the FT-857", lambda: down.get("main"), SPOTS["RS-44"][0], 12_000)
    near("RS-44's uplink on the FT-897", lambda: up.get("main"), SPOTS["RS-44"][1], 5_000)
    check(down.mode.get("main") == 0x01 and up.mode.get("main") == 0x00, f"USB down, LSB up: {down.mode} {up.mode}")
    worst = worst_error("RS-44", SPOTS["RS-44"], lambda: down.get("main"), lambda: up.get("main"), clock_now, 8)
    check(worst[0] < 400 and worst[1] < 400, f"RS-44 worst {worst}")
    sent = down.sent() + up.sent()
    check(all(c[-2:] in ("01", "07", "03") for c in sent), f"only 01 / 07 / 03: {sorted(set(c[-2:] for c in sent))}")
    check(any(c.endswith(" 03") for c in down.sent()), "the FT-857 read back (03)")
    leave(tb, state)
    print(f"ft857 + ft897 RS-44: {len(down.sent())} / {len(up.sent())} commands; worst tuning error {worst[0]:.0f} Hz "
          f"down (FT-857), {worst[1]:.0f} Hz up (FT-897); e.g. {down.sent()[0]}")


def so50_alone(rig, tb, state, clock_now):
    near("SO-50's downlink on the FT-857", lambda: rig.get("main"), SPOTS["SO-50"][0], 12_000)
    check(rig.mode.get("main") == 0x08, f"FM: {rig.mode}")
    time.sleep(2)
    log = leave(tb, state)
    line = limit_in_log(log, "FT-857", "needs a second radio")
    said = [ln for ln in log.splitlines() if "needs a second radio" in ln]
    check(len(said) == 1, f"said once: {said}")
    check("reconnect" not in log.lower(), "no lost link for a refusal")
    print(f"ft857 alone SO-50: {line.strip()}")


def main():
    need("socat")
    track(RS44_PASS[0], RS44_PASS[1], ("ft857:{}", ft8x7), rs44, up=("ft897:{}", ft8x7))
    track(SO50_PASS[0], SO50_PASS[1], ("ft857:{}", ft8x7), so50_alone)


if __name__ == "__main__":
    run_test(main)
