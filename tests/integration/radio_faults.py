"""Faults that stay local, and a radio switched off mid-pass (issue 40): trakbox --radio ic9700:PTY
against the IC-9700 responder of _ic9700.py on a socat pty pair, through RS-44's pass (--clock).

1. The responder answers satellite mode (16 5A 01) as Hamlib's simulators/simic9700.c does, with a
   data frame holding the value instead of FB: the log says once that satellite mode was not
   confirmed, 16 5A is asked once, and both links are tuned (Main down, Sub up) on the Doppler.
2. The responder is switched off for 10 s mid-pass (no echo, no answer) and comes back out of
   satellite mode: within 5 s of answering again satellite mode is on again and both links sit on
   the satellite's Doppler. The fault is in the log once.
Every wait polls for its condition with a deadline.
"""
import os
import shutil
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
from _ic9700 import IC9700  # noqa: E402
from _ptyradio import RS44_PASS, expected, leave, on_doppler, on_pass, tuned, SPOTS  # noqa: E402
from _tbharness import check, run_test, skip  # noqa: E402


def data_for_satellite_mode(rig, tb, state, clock_now):
    tuned("RS-44", lambda: rig.get("main"), lambda: rig.get("sub"), ("Main", "Sub"))
    on_doppler("RS-44", lambda: rig.get("main"), lambda: rig.get("sub"), clock_now, 400)
    time.sleep(3)
    d, u = on_doppler("RS-44", lambda: rig.get("main"), lambda: rig.get("sub"), clock_now, 400)
    asked = sum(1 for _, f in rig.frames if f[4:6] == b"\x16\x5a" and f[6] == 1)
    check(asked == 1, f"satellite mode asked once: {asked}")
    log = leave(tb, state)
    said = log.count("satellite mode not confirmed")
    check(said == 1, f"the log says once that satellite mode was not confirmed ({said})")
    print(f"ic9700 answering 16 5A with data (simic9700): asked {asked}, said {said}; Main {d}, Sub {u}")


def switched_off(rig, tb, state, clock_now):
    tuned("RS-44", lambda: rig.get("main"), lambda: rig.get("sub"), ("Main", "Sub"))
    check(rig.satellite, "satellite mode on")
    time.sleep(2)
    rig.power(False)
    time.sleep(10)
    rig.power(True)
    back_at = time.time()

    def back():
        e_down, e_up = expected(clock_now(), "RS-44", *SPOTS["RS-44"])
        with rig.lock:
            return rig.satellite and abs(rig.hz["main"] - e_down) < 100 and abs(rig.hz["sub"] - e_up) < 100

    while not back() and time.time() - back_at < 8:
        time.sleep(0.05)
    after = time.time() - back_at
    check(back(), "back in satellite mode and on the Doppler")
    check(after <= 5.0, f"back {after:.2f} s after answering again")
    d, u = on_doppler("RS-44", lambda: rig.get("main"), lambda: rig.get("sub"), clock_now, 100)
    log = leave(tb, state)
    faults = log.count("no reply from the IC-9700")
    check(1 <= faults <= 2, f"the silence is in the log once (per message): {faults}")
    print(f"ic9700 switched off 10 s mid-pass: back in satellite mode, Main {d}, Sub {u}, {after:.2f} s after "
          "answering again")


def main():
    if not shutil.which("socat"):
        skip("socat not installed")
    on_pass(RS44_PASS, lambda path: IC9700(path, sat_answer="data"), "ic9700", data_for_satellite_mode)
    on_pass(RS44_PASS, lambda path: IC9700(path), "ic9700", switched_off)


if __name__ == "__main__":
    run_test(main)
