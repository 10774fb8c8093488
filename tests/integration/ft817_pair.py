"""Two Yaesu FT-817s, one link each (issue 28): trakbox --radio ft817:PTY1 --uplink-radio ft817:PTY2
against two FT-817 responders of our own (_ft847.py with ft817=True) on socat pty pairs.

RS-44 (2026-05-21, from a minute before its culmination, --clock): the downlink on the first radio
(USB), the uplink on the second (LSB), each read back (03). The first radio's dial is turned +10 kHz
as the knob would: the downlink stays where the knob put it and the second radio (RS-44 inverts)
moves -10 kHz within 2 s plus the knob rest. The bytes per second on each CAT line are printed.
SO-50: FM on both, the 67.0 Hz tone (06 70 06 70 0B, then the encoder 4A ... 0A) on the uplink radio
only, and the Doppler.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from _ft847 import FT847  # noqa: E402
from _ptyradio import RS44_PASS, SO50_PASS, leave, listen, on_doppler, rs44_knob_turn, so50_on_fm, on_pass, tuned  # noqa: E402
from _tbharness import check, need, run_test  # noqa: E402


def ft817(path):
    return FT847(path, ft817=True)


def rs44(rigs, tb, state, clock_now):
    down, up = rigs
    tuned("RS-44", lambda: down.get("main"), lambda: up.get("main"), ("the first FT-817", "the second"))
    check(down.mode.get("main") == 0x01 and up.mode.get("main") == 0x00, f"USB down, LSB up: {down.mode} {up.mode}")
    on_doppler("RS-44", lambda: down.get("main"), lambda: up.get("main"), clock_now, 400)
    t1, t2, rate_down = listen(down, 10)
    rate_up = up.line_bytes(t1, t2) / (t2 - t1)
    knob = rs44_knob_turn(lambda: down.get("main"), lambda: up.get("main"), lambda hz: down.turn("main", hz), clock_now)
    log = leave(tb, state)
    check("downlink dial turned" in log, "the log names the turn of the dial")
    print(f"ft817 pair RS-44: {rate_down:.0f} bytes/s on the downlink radio's line, {rate_up:.0f} on the uplink's; {knob}")


def so50(rigs, tb, state, clock_now):
    down, up = rigs
    first_down, d, u = so50_on_fm(lambda: down.get("main"), lambda: up.get("main"), ("the first FT-817", "the second"),
                                  lambda: (down.mode.get("main"), up.mode.get("main")), clock_now)
    check("06 70 06 70 0B" in up.sent() and up.encoder.get("main"), f"67.0 Hz on the uplink radio: {up.sent()[:8]}")
    check(not any(c.endswith(("0B", "0A")) for c in down.sent()), f"no tone on the downlink radio: {down.sent()[:8]}")
    leave(tb, state)
    print(f"ft817 pair SO-50: tone on the uplink radio; Doppler {first_down} -> {d} down, {u} up")


def main():
    need("socat")
    on_pass(RS44_PASS, ft817, "ft817", rs44, uplink_model="ft817")
    on_pass(SO50_PASS, ft817, "ft817", so50, uplink_model="ft817")


if __name__ == "__main__":
    run_test(main)
