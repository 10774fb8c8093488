"""One IC-9700 in its satellite mode, natively (issue 28): trakbox --radio ic9700:PTY against an
IC-9700 responder of our own (_ic9700.py, no CI-V echo as on its USB port) on a socat pty pair.

RS-44 (2026-05-21, from a minute before its culmination, --clock): satellite mode goes on before
the first frequency; the downlink lands on Main and the uplink on Sub with their modes; no band
select thrash. The responder turns the Main dial +10 kHz and sends its transceive frame, as the
knob would: the downlink stays where the knob put it and the uplink (RS-44 inverts) moves -10 kHz
within 2 s plus the Tuner's knob-rest delay. The bytes per second on the CAT line are printed.

SO-50 (2026-05-21 14:10 UTC, near its culmination) with its 67.0 Hz tone, which this radio
refuses (FA): the refusal is reported and the Doppler goes on. Then RS-44 again with the echo on.
Every wait polls for its condition with a deadline.
"""
import os
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
from _ic9700 import IC9700  # noqa: E402
from _ptyradio import RS44_PASS, SO50_PASS, leave, listen, on_doppler, rs44_knob_turn, so50_doppler_goes_on, on_pass, tuned  # noqa: E402
from _tbharness import check, need, run_test  # noqa: E402


def on_ic9700(which, test, refuse_tone=False, echo=False):
    """An IC-9700 responder (USB: no echo; or a CI-V bus) on the pty, through one of the passes."""
    on_pass(which, lambda path: IC9700(path, echo=echo, refuse_tone=refuse_tone), "ic9700", test)


def rs44(rig, tb, state, clock_now):
    tuned("RS-44", lambda: rig.get("main"), lambda: rig.get("sub"), ("Main", "Sub"))
    with rig.lock:
        first = [f.hex(" ").upper() for _, f in rig.frames[:7]]
    check(first[0] == "FE FE A2 E0 16 5A 01 FD", f"satellite mode first: {first}")
    check(rig.satellite, "satellite mode is on")
    check(rig.mode["main"] == 0x01 and rig.mode["sub"] == 0x00, f"USB on Main, LSB on Sub: {rig.mode}")
    on_doppler("RS-44", lambda: rig.get("main"), lambda: rig.get("sub"), clock_now, 400)

    # Ten seconds of Doppler: frames and bytes on the line.
    t1, t2, rate = listen(rig, 10)
    freqs, selects = rig.count(0x05, t1), rig.count(0x07, t1)
    check(freqs >= 10, f"Doppler updates in 10 s: {freqs} frequency frames")
    check(selects <= freqs, f"no band-select thrash: {selects} selects for {freqs} frequencies")

    # The operator turns the Main (downlink) dial up 10 kHz.
    knob = rs44_knob_turn(lambda: rig.get("main"), lambda: rig.get("sub"),
                          lambda hz: rig.turn("main", hz), clock_now)
    log = leave(tb, state)
    time.sleep(0.2)
    with rig.lock:
        last = rig.frames[-1][1].hex(" ").upper()
    check(last == "FE FE A2 E0 16 5A 00 FD", f"satellite mode off at the end: {last}")
    check("downlink dial turned" in log, "the log names the turn of the dial")
    print(f"ic9700 RS-44 (echo {'on' if rig.echo else 'off'}): first update {first}; {freqs} frequency and {selects} select frames in 10 s, "
          f"{rate:.0f} bytes/s on the CAT line; {knob}")


def so50(rig, tb, state, clock_now):
    tuned("SO-50", lambda: rig.get("main"), lambda: rig.get("sub"), ("Main", "Sub"))
    check(rig.count(0x1B) >= 1, "the tone was asked for")
    first_down, d, u = so50_doppler_goes_on(lambda: rig.get("main"), lambda: rig.get("sub"), clock_now)
    check(rig.tone is None, "the refused tone is not on")
    log = leave(tb, state)
    check("refused FE FE A2 E0 1B 00 00 06 70 FD (NG)" in log, "the refused tone is in the log")
    print(f"ic9700 SO-50: tone refused and logged; Doppler {first_down} -> {d} on Main, {u} on Sub")


def main():
    need("socat")
    on_ic9700(RS44_PASS, rs44)
    on_ic9700(SO50_PASS, so50, refuse_tone=True)
    # The same radio on a CI-V bus (CI-V USB Echo Back ON): every frame echoed first.
    on_ic9700(RS44_PASS, rs44, echo=True)


if __name__ == "__main__":
    run_test(main)
