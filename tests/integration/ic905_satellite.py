"""The Icom IC-905 natively (issue 61): trakbox --radio ic905:PTY against an IC-905 responder (the
IC-9700 one of _ic9700.py at CI-V address ACh, with the IC-905's 6-byte frequencies from 10 GHz up).

RS-44 (2026-05-21, near its culmination, --clock): satellite mode (16 5A 01) before the first
frequency, the downlink on Main and the uplink on Sub, every frequency frame 5 BCD bytes; the worst
tuning error of each link over the pass is measured and printed.
QO-100 from Berlin (a --data directory whose record has no converter: the radio tunes 10489.550 MHz
itself): with `:xvtr` the downlink goes out as 6 BCD bytes (FE FE AC E0 05 xx xx 55 89 04 01 FD) and
the uplink (2400.050 MHz) as 5; without `:xvtr`, and with `:xvtr` on a radio whose transverter is
absent (it answers FA), the 10 GHz band is a limit learnt once and the uplink is tuned all the same.
"""
import os
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
from _ic9700 import IC9700  # noqa: E402
from _ptyradio import RS44_PASS, SPOTS  # noqa: E402
from _rigs2026 import BERLIN, expected, leave, near, track, worst_error  # noqa: E402
from _tbharness import check, need, run_test  # noqa: E402

QO100 = ["QO-100 10489.550 2400.050 usb usb cat no down=10489.500-10489.990 up=2400.000-2400.490 inv=n"]
QO100_SPOTS = (10_489_550_000, 2_400_050_000)


def ic905(xvtr=True):
    return lambda path: IC9700(path, addr=0xAC, xvtr=xvtr)


def frequency_frames(rig):
    with rig.lock:
        return [f for _, f in rig.frames if len(f) > 4 and f[4] == 0x05]


def rs44(rig, tb, state, clock_now):
    down, up = SPOTS["RS-44"]
    near("RS-44's downlink on Main", lambda: rig.get("main"), down, 12_000)
    near("RS-44's uplink on Sub", lambda: rig.get("sub"), up, 5_000)
    with rig.lock:
        first = rig.frames[0][1].hex(" ").upper()
    check(first == "FE FE AC E0 16 5A 01 FD", f"satellite mode first, at ACh: {first}")
    check(rig.mode["main"] == 0x01 and rig.mode["sub"] == 0x00, f"USB on Main, LSB on Sub: {rig.mode}")
    worst = worst_error("RS-44", SPOTS["RS-44"], lambda: rig.get("main"), lambda: rig.get("sub"), clock_now, 8)
    check(worst[0] < 400 and worst[1] < 400, f"RS-44 on Doppler: worst {worst[0]:.0f} Hz down, {worst[1]:.0f} Hz up")
    frames = frequency_frames(rig)
    check(frames and all(len(f) == 11 for f in frames), f"5 BCD bytes below 10 GHz: {[f.hex() for f in frames[:3]]}")
    leave(tb, state)
    print(f"ic905 RS-44: {len(frames)} frequency frames; worst tuning error {worst[0]:.0f} Hz on Main (down), "
          f"{worst[1]:.0f} Hz on Sub (up)")


def qo100_six_bytes(rig, tb, state, clock_now):
    e_down, e_up = expected(clock_now(), "QO-100", *QO100_SPOTS, station=BERLIN)
    near("QO-100's downlink on Main (10 GHz)", lambda: rig.get("main"), e_down, 2_000)
    near("QO-100's uplink on Sub (2.4 GHz)", lambda: rig.get("sub"), e_up, 2_000)
    frames = frequency_frames(rig)
    six = [f.hex(" ").upper() for f in frames if len(f) == 12]
    five = [f.hex(" ").upper() for f in frames if len(f) == 11]
    check(six and all(s.startswith("FE FE AC E0 05 ") and s.endswith(" 89 04 01 FD") for s in six),
          f"10489 MHz as 6 BCD bytes: {six[:2]}")
    check(five and all(s.endswith(" 00 24 FD") for s in five), f"2400 MHz as 5 BCD bytes: {five[:2]}")
    worst = worst_error("QO-100", QO100_SPOTS, lambda: rig.get("main"), lambda: rig.get("sub"), clock_now, 3,
                        station=BERLIN)
    check(worst[0] < 400 and worst[1] < 400, f"QO-100 worst {worst}")
    log = leave(tb, state)
    check("transverter" not in log, "the 10 GHz band is no limit with the transverter")
    print(f"ic905 QO-100 with :xvtr: downlink {six[0]} (6 bytes), uplink {five[0]} (5 bytes); "
          f"worst error {worst[0]:.0f} / {worst[1]:.0f} Hz")


def qo100_no_band(rig, tb, state, clock_now, why):
    e_down, e_up = expected(clock_now(), "QO-100", *QO100_SPOTS, station=BERLIN)
    near("QO-100's uplink on Sub (2.4 GHz) all the same", lambda: rig.get("sub"), e_up, 2_000)
    time.sleep(2)   # further Doppler updates: the limit is said once, the radio stays connected
    check(rig.get("main") == 145_000_000, f"Main left alone: {rig.get('main')}")
    log = leave(tb, state)
    said = [ln for ln in log.splitlines() if "IC-905" in ln and "transverter" in ln]
    check(len(said) == 1 and why in said[0], f"the 10 GHz band a limit, said once ({why!r}): {said}")
    check("reconnect" not in log.lower(), "no lost link for a refusal")
    return said[0]


def main():
    need("socat")
    track(RS44_PASS[0], RS44_PASS[1], ("ic905:{}", ic905()), rs44)
    qo = RS44_PASS[0]
    track(qo, b"1", ("ic905:{}:xvtr", ic905()), qo100_six_bytes, extra=("--station", BERLIN), data=QO100)
    seen = []
    track(qo, b"1", ("ic905:{}", ic905()),
          lambda *a: seen.append(qo100_no_band(*a, "only with its transverter")), extra=("--station", BERLIN), data=QO100)
    track(qo, b"1", ("ic905:{}:xvtr", ic905(xvtr=False)),
          lambda *a: seen.append(qo100_no_band(*a, "transverter is absent or off")), extra=("--station", BERLIN),
          data=QO100)
    for line in seen:
        print(f"ic905 QO-100 limit: {line.strip()}")


if __name__ == "__main__":
    run_test(main)
