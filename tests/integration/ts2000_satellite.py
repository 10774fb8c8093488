"""One Kenwood TS-2000 in its satellite mode, natively (issue 28): trakbox --radio ts2000:PTY
against a TS-2000 responder of our own (_ts2000.py) on a socat pty pair.

RS-44 (2026-05-21, from a minute before its culmination, --clock): SA is read, VFO A taken off a
memory, satellite mode set (Main down, Sub up, TRACE off) and confirmed before the first frequency;
the downlink on FA (Main, USB) and the uplink on FB (Sub, LSB, set with CTRL on Sub). The responder
turns VFO A +10 kHz as the knob would: the downlink stays where the knob put it and the uplink
(RS-44 inverts) moves -10 kHz within 2 s plus the Tuner's knob-rest delay. At the end SA is put
back as found. The bytes per second on the CAT line are printed.

SO-50 (2026-05-21 14:10 UTC, near its culmination) with its 67.0 Hz tone, which this radio
refuses (?;): the refusal is reported and the Doppler goes on. Every wait polls with a deadline.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from _ptyradio import RS44_PASS, SO50_PASS, leave, listen, on_doppler, poll, rs44_knob_turn, so50_doppler_goes_on, on_pass, tuned  # noqa: E402
from _tbharness import check, need, run_test  # noqa: E402
from _ts2000 import TS2000  # noqa: E402


def rs44(rig, tb, state, clock_now):
    tuned("RS-44", lambda: rig.get("A"), lambda: rig.get("B"), ("VFO A (Main)", "VFO B (Sub)"))
    first = rig.sent()[:5]
    check(first == ["SA;", "FR;", "FR0;", "SA1010000;", "SA;"],
          f"SA read, VFO A off its memory, satellite mode set and confirmed first: {first}")
    check(rig.sa == "1010000", f"satellite mode on, uplink on Sub, CTRL on Main, TRACE off: SA{rig.sa}")
    check(rig.mode.get("M") == "2" and rig.mode.get("S") == "1", f"USB on Main, LSB on Sub: {rig.mode}")
    on_doppler("RS-44", lambda: rig.get("A"), lambda: rig.get("B"), clock_now, 400)

    # Ten seconds of Doppler: commands and bytes on the line.
    t1, t2, rate = listen(rig, 10)
    sent = rig.sent(t1)
    sets = sum(1 for c in sent if len(c) == 14 and c[0] == "F")
    reads = sum(1 for c in sent if c in ("FA;", "FB;"))
    check(sets >= 10, f"Doppler updates in 10 s: {sets} frequency commands")
    check(not any(c.startswith("SA1") for c in sent), f"satellite mode set once, not every update: {sent[:8]}")

    # The operator turns the Main (downlink) dial up 10 kHz.
    knob = rs44_knob_turn(lambda: rig.get("A"), lambda: rig.get("B"),
                          lambda hz: rig.turn("A", hz), clock_now)
    log = leave(tb, state)
    poll("SA put back as found at the end", lambda: rig.sent()[-1:] == ["SA0010000;"], 5)
    check("satellite mode on (SA1010000; found SA0010000;)" in log, "the log says satellite mode went on")
    check("downlink dial turned" in log, "the log names the turn of the dial")
    print(f"ts2000 RS-44: first {first}; {sets} frequency commands and {reads} reads in 10 s, "
          f"{rate:.0f} bytes/s on the CAT line; {knob}")


def so50(rig, tb, state, clock_now):
    tuned("SO-50", lambda: rig.get("A"), lambda: rig.get("B"), ("VFO A (Main)", "VFO B (Sub)"))
    check("TN01;" in rig.sent(), "the tone was asked for (TN01: 67.0 Hz)")
    check(rig.mode.get("M") == "4" and rig.mode.get("S") == "4", f"FM on Main and Sub: {rig.mode}")
    first_down, d, u = so50_doppler_goes_on(lambda: rig.get("A"), lambda: rig.get("B"), clock_now)
    check(rig.sa == "1010000", f"CTRL back on Main after the refusal: SA{rig.sa}")
    log = leave(tb, state)
    check("refused the tone 67.0 Hz (TN01;TO1; answered ?;)" in log, "the refused tone is in the log")
    print(f"ts2000 SO-50: tone refused and logged; Doppler {first_down} -> {d} on VFO A, {u} on VFO B")


def main():
    need("socat")
    # VFO A on a memory channel, as an operator may leave it: trakbox goes to VFO first.
    def on_memory(path):
        rig = TS2000(path)
        rig.fr = "2"
        return rig
    on_pass(RS44_PASS, on_memory, "ts2000", rs44)
    on_pass(SO50_PASS, lambda path: TS2000(path, refuse_tone=True), "ts2000", so50)


if __name__ == "__main__":
    run_test(main)
