"""One Yaesu FT-847 in its satellite mode, natively (issue 28): trakbox --radio ft847:PTY against an
FT-847 responder of our own (_ft847.py) on a socat pty pair.

RS-44 (2026-05-21, from a minute before its culmination, --clock): CAT on and satellite mode on
before the first frequency; the downlink on SAT RX (USB), the uplink on SAT TX (LSB), both read
back (13 / 23). The responder turns the SAT RX dial +10 kHz as the knob would: the downlink stays
where the knob put it and the uplink (RS-44 inverts) moves -10 kHz within 2 s plus the knob rest.
At the end satellite mode off, then CAT off. The bytes per second on the CAT line are printed.

SO-50 (2026-05-21 14:10 UTC): its 67.0 Hz tone (code 3F) and the encoder on SAT TX, FM both ways,
and the Doppler. Every wait polls with a deadline.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from _ft847 import FT847  # noqa: E402
from _ptyradio import RS44_PASS, SO50_PASS, leave, listen, on_doppler, poll, rs44_knob_turn, so50_on_fm, on_pass, tuned  # noqa: E402
from _tbharness import check, need, run_test  # noqa: E402


def rs44(rig, tb, state, clock_now):
    tuned("RS-44", lambda: rig.get("rx"), lambda: rig.get("tx"), ("SAT RX", "SAT TX"))
    first = rig.sent()[:2]
    check(first == ["00 00 00 00 00", "00 00 00 00 4E"], f"CAT on, then satellite mode, first: {rig.sent()[:8]}")
    check(rig.mode.get("rx") == 0x01 and rig.mode.get("tx") == 0x00, f"USB on SAT RX, LSB on SAT TX: {rig.mode}")
    on_doppler("RS-44", lambda: rig.get("rx"), lambda: rig.get("tx"), clock_now, 400)

    t1, t2, rate = listen(rig, 10)
    sent = rig.sent(t1)
    sets = sum(1 for c in sent if c.endswith(("11", "21")))
    reads = sum(1 for c in sent if c in ("00 00 00 00 13", "00 00 00 00 23"))
    check(sets >= 10, f"Doppler updates in 10 s: {sets} frequency commands")

    # The operator turns the SAT RX (downlink) dial up 10 kHz.
    knob = rs44_knob_turn(lambda: rig.get("rx"), lambda: rig.get("tx"), lambda hz: rig.turn("rx", hz), clock_now)
    log = leave(tb, state)
    poll("satellite mode off, then CAT off, at the end", lambda: rig.sent()[-2:] == ["00 00 00 00 8E", "00 00 00 00 80"], 5)
    check("downlink dial turned" in log, "the log names the turn of the dial")
    print(f"ft847 RS-44: {sets} frequency commands and {reads} reads in 10 s, {rate:.0f} bytes/s on the CAT line; {knob}")


def so50(rig, tb, state, clock_now):
    first_down, d, u = so50_on_fm(lambda: rig.get("rx"), lambda: rig.get("tx"), ("SAT RX", "SAT TX"),
                                  lambda: (rig.mode.get("rx"), rig.mode.get("tx")), clock_now)
    check("3F 00 00 00 2B" in rig.sent() and rig.encoder.get("tx"), f"67.0 Hz (3F) on SAT TX, encoder on: {rig.sent()[:12]}")
    leave(tb, state)
    print(f"ft847 SO-50: tone 3F on SAT TX; Doppler {first_down} -> {d} on SAT RX, {u} on SAT TX")


def main():
    need("socat")
    on_pass(RS44_PASS, FT847, "ft847", rs44)
    on_pass(SO50_PASS, FT847, "ft847", so50)


if __name__ == "__main__":
    run_test(main)
