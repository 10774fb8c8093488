"""Icom single-link rigs as one leg each (issue 61): the IC-7100 (88h), IC-706MKIIG (58h) and
IC-7300 (94h) against CI-V responders of our own (_ic9700.py at their addresses) on socat ptys.

RS-44 (2026-05-21, near its culmination, --clock): --radio ic7100 (the downlink, USB) with
--uplink-radio ic706mkiig (LSB): each on its one VFO, no band or VFO select, each frame at its
radio's address; the worst tuning error of each link over the pass is measured.
SO-50: FM on both; its 67.0 Hz tone goes to the IC-706MKIIG, which has no CTCSS trakbox sets: a
limit learnt once ("no CTCSS"), the Doppler goes on.
RS-44 with the IC-7300 as the downlink radio: it has no 70 cm, a limit learnt once ("no 70 cm"),
never a lost link; the IC-7100 carries the uplink all the same.
AO-07 in Mode A (a --data record: 29.450 MHz down, 145.900 MHz up, not inverting) on a pass of
2026-05-21: the IC-7300 on its 10 m downlink and the IC-7100 on the 2 m uplink, worst error printed.
"""
import os
import sys
import time
from datetime import datetime, timezone

sys.path.insert(0, os.path.dirname(__file__))
from _ic9700 import IC9700  # noqa: E402
from _ptyradio import RS44_PASS, SO50_PASS, SPOTS  # noqa: E402
from _rigs2026 import leave, limit_in_log, near, track, worst_error  # noqa: E402
from _tbharness import check, need, poll, run_test  # noqa: E402

AO07_MODE_A = ["AO-07 29.450 145.900 usb usb cat no down=29.400-29.500 up=145.850-145.950 inv=n"]
AO07_SPOTS = (29_450_000, 145_900_000)
AO07_PASS = datetime(2026, 5, 21, 9, 39, 0, tzinfo=timezone.utc)   # TCA 09:40:25, 68.7 deg (trakbox passes)


def civ(addr):
    return lambda path: IC9700(path, addr=addr)


def frames_to(rig):
    with rig.lock:
        return [f for _, f in rig.frames]


def rs44_pair(rigs, tb, state, clock_now):
    down, up = rigs
    d_spot, u_spot = SPOTS["RS-44"]
    near("RS-44's downlink on the IC-7100", lambda: down.get("main"), d_spot, 12_000)
    near("RS-44's uplink on the IC-706MKIIG", lambda: up.get("main"), u_spot, 5_000)
    check(down.mode["main"] == 0x01 and up.mode["main"] == 0x00, f"USB down, LSB up: {down.mode} {up.mode}")
    worst = worst_error("RS-44", SPOTS["RS-44"], lambda: down.get("main"), lambda: up.get("main"), clock_now, 8)
    check(worst[0] < 400 and worst[1] < 400, f"RS-44 worst {worst}")
    fd, fu = frames_to(down), frames_to(up)
    check(all(f[2] == 0x88 for f in fd) and all(f[2] == 0x58 for f in fu), "each frame at its radio's address")
    check(not any(f[4] == 0x07 for f in fd + fu), "no band or VFO select on a one-VFO leg")
    leave(tb, state)
    print(f"ic7100 + ic706mkiig RS-44: {len(fd)} / {len(fu)} frames; worst tuning error {worst[0]:.0f} Hz down "
          f"(IC-7100), {worst[1]:.0f} Hz up (IC-706MKIIG); first {fd[0].hex(' ').upper()}")


def so50_pair(rigs, tb, state, clock_now):
    down, up = rigs
    d_spot, u_spot = SPOTS["SO-50"]
    near("SO-50's downlink on the IC-7100", lambda: down.get("main"), d_spot, 12_000)
    near("SO-50's uplink on the IC-706MKIIG", lambda: up.get("main"), u_spot, 5_000)
    check(down.mode["main"] == 0x05 and up.mode["main"] == 0x05, f"FM on both: {down.mode} {up.mode}")
    first = down.get("main")
    poll("Doppler updates after the refused tone", lambda: abs(down.get("main") - first) >= 100, 20)
    worst = worst_error("SO-50", SPOTS["SO-50"], lambda: down.get("main"), lambda: up.get("main"), clock_now, 4)
    check(worst[0] < 1000 and worst[1] < 1000, f"SO-50 worst {worst}")
    check(not any(f[4] == 0x1B for f in frames_to(up)), "no tone frame to the IC-706MKIIG")
    log = leave(tb, state)
    line = limit_in_log(log, "IC-706MKIIG", "no CTCSS")
    print(f"ic7100 + ic706mkiig SO-50: worst {worst[0]:.0f} / {worst[1]:.0f} Hz; limit: {line.strip()}")


def rs44_ic7300(rigs, tb, state, clock_now):
    down, up = rigs
    near("RS-44's uplink on the IC-7100", lambda: up.get("main"), SPOTS["RS-44"][1], 5_000)
    time.sleep(2)
    check(down.get("main") == 145_000_000, f"the IC-7300 left alone: {down.get('main')}")
    check(not any(f[4] == 0x05 for f in frames_to(down)), "no 70 cm frequency sent to the IC-7300")
    log = leave(tb, state)
    line = limit_in_log(log, "IC-7300", "no 70 cm")
    said = [ln for ln in log.splitlines() if "no 70 cm" in ln]
    check(len(said) == 1, f"said once: {said}")
    check("reconnect" not in log.lower(), "no lost link for a refusal")
    print(f"ic7300 RS-44: {line.strip()}")


def ao07_mode_a(rigs, tb, state, clock_now):
    down, up = rigs
    near("AO-07's 10 m downlink on the IC-7300", lambda: down.get("main"), AO07_SPOTS[0], 2_000)
    near("AO-07's 2 m uplink on the IC-7100", lambda: up.get("main"), AO07_SPOTS[1], 6_000)
    check(down.mode["main"] == 0x01 and up.mode["main"] == 0x01, f"USB on both: {down.mode} {up.mode}")
    worst = worst_error("AO-07", AO07_SPOTS, lambda: down.get("main"), lambda: up.get("main"), clock_now, 6)
    check(worst[0] < 400 and worst[1] < 400, f"AO-07 worst {worst}")
    check(all(f[2] == 0x94 for f in frames_to(down)), "the IC-7300 at 94h")
    leave(tb, state)
    print(f"ic7300 + ic7100 AO-07 Mode A: worst tuning error {worst[0]:.0f} Hz down (10 m), {worst[1]:.0f} Hz up (2 m)")


def main():
    need("socat")
    track(RS44_PASS[0], RS44_PASS[1], ("ic7100:{}", civ(0x88)), rs44_pair, up=("ic706mkiig:{}", civ(0x58)))
    track(SO50_PASS[0], SO50_PASS[1], ("ic7100:{}", civ(0x88)), so50_pair, up=("ic706mkiig:{}", civ(0x58)))
    track(RS44_PASS[0], RS44_PASS[1], ("ic7300:{}", civ(0x94)), rs44_ic7300, up=("ic7100:{}", civ(0x88)))
    track(AO07_PASS, b"1", ("ic7300:{}", civ(0x94)), ao07_mode_a, up=("ic7100:{}", civ(0x88)), data=AO07_MODE_A)


if __name__ == "__main__":
    run_test(main)
