"""`trakbox host`: host mode on stdin/stdout, as a script drives it. AZ/EL moves the simulated
rotator (the clock runs 10 times faster), ?A follows it, errors are one line, Q ends the program
with the state saved.
"""
import os
import re
import subprocess
import sys
import tempfile
import time
import shutil

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, Terminal, check, run_test  # noqa: E402


def main():
    state = tempfile.mkdtemp(prefix="trakbox-host-")
    p = subprocess.Popen([BIN, "host", "--state", state, "--clock", CLOCK, "--clock-rate", "10", "--satrak-port", "0"],
                         stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        t = Terminal(p.stdout.fileno())
        send = lambda s: (p.stdin.write(s.encode()), p.stdin.flush())  # noqa: E731
        t.expect(r"TrakBox host mode\.")
        t.expect(r"Command:MUxxx,MDxxx,FUxxx,FDxxx,AZxxx_ELxx,Sxxx,Q,\?A,\?")
        t.expect(r"TrakBox>>")
        send("?A\r")
        m = t.expect(r"AZ(\d+\.\d) EL(-?\d+\.\d)")
        start_az = float(m.group(1))
        send("AZ120 EL30\r")
        t.expect(r"TrakBox>>")
        # 10x clock: the 6 deg/s rotator covers the way in a few seconds of real time.
        deadline = time.time() + 20
        az = el = None
        while time.time() < deadline:
            send("?A\r")
            m = t.expect(r"AZ(\d+\.\d) EL(-?\d+\.\d)")
            az, el = float(m.group(1)), float(m.group(2))
            if abs(az - 120) < 1.5 and abs(el - 30) < 0.5:
                break
            time.sleep(0.3)
        check(az is not None and abs(az - 120) < 1.5 and abs(el - 30) < 0.5,
              f"antenna reached AZ120 EL30 from AZ{start_az}: now AZ{az} EL{el}")
        send("AZ400 EL10\r")
        m = t.expect(r"ERROR AZ/EL: azimuth 400 out of range[^\n]*")
        check("\n" not in m.group(0), "an error is one line")
        send("FD43590000\rMDUSB\rXYZ\r")
        t.expect(r"ERROR unknown command 'XYZ'")
        send("Q\r")
        code = p.wait(15)
        check(code == 0, f"exit status {code}")
        check("\x1b" not in t.transcript, "no escape codes")
        check("AZ120 EL30" not in t.transcript.split("TrakBox>>")[0], "no echo of the commands")
        check(re.search(r'"rotor_control": true', open(os.path.join(state, "trakbox-state.json")).read()),
              "AZ/EL took control and it was saved")
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
