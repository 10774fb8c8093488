"""Remote control of the real program: trakbox runs (menus on a pipe kept open) with the Satrak
server, the rotctld/rigctld-compatible endpoints and host mode on free loopback ports;
`trakbox satrak`, Hamlib's own `rotctl -m 2` and `rigctl -m 2`, and a plain TCP client typing host
mode commands drive it.
"""
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, Failure, check, free_port, run_test, sh  # noqa: E402


def main():
    state = tempfile.mkdtemp(prefix="trakbox-remote-")
    sat_port, rot_port, rig_port, host_port = free_port(), free_port(), free_port(), free_port()
    tb = subprocess.Popen([BIN, "--state", state, "--clock", CLOCK, "--clock-rate", "10", "--line",
                           "--satrak-port", str(sat_port), "--rotctld-port", str(rot_port),
                           "--rigctld-port", str(rig_port), "--host-port", str(host_port), "--log-level", "debug"],
                          stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    try:
        deadline = time.time() + 15
        while True:
            code, out, err = sh(BIN, "satrak", f"127.0.0.1:{sat_port}", "VERSION?")
            if code == 0:
                break
            if time.time() > deadline:
                raise Failure(f"Satrak server never answered: {err}")
            time.sleep(0.3)
        check(out.startswith("VERSION?,"), f"VERSION? reply: {out!r}")

        # GOTO moves the simulated rotator; STATUS? and TPOS? report it moving, then there.
        code, out, err = sh(BIN, "satrak", f"127.0.0.1:{sat_port}", "GOTO=,120,30")
        check(code == 0 and "GOTO=,OK" in out, f"GOTO: {out!r} {err!r}")
        deadline = time.time() + 20
        while True:
            code, out, _ = sh(BIN, "satrak", f"127.0.0.1:{sat_port}", "TPOS?")
            m = re.search(r"TPOS\?,([\d.]+),([\d.-]+)", out)
            if m and abs(float(m.group(1)) - 120) < 1.5 and abs(float(m.group(2)) - 30) < 0.6:
                break
            if time.time() > deadline:
                raise Failure(f"the antenna did not reach 120/30: {out!r}")
            time.sleep(0.3)
        code, out, _ = sh(BIN, "satrak", f"127.0.0.1:{sat_port}", "BOGUS?")
        check(code == 1 and "ERR" in out, f"an unknown command is refused: {out!r}")

        # Hamlib's network rotator client moves the same antenna.
        code, out, err = sh("rotctl", "-m", "2", "-r", f"127.0.0.1:{rot_port}", "P", "200", "10")
        check(code == 0, f"rotctl P: {out} {err}")
        deadline = time.time() + 30
        while True:
            code, out, err = sh("rotctl", "-m", "2", "-r", f"127.0.0.1:{rot_port}", "p")
            nums = [float(x) for x in re.findall(r"-?\d+\.\d+", out)]
            if len(nums) >= 2 and abs(nums[0] - 200) < 1.5 and abs(nums[1] - 10) < 0.6:
                break
            if time.time() > deadline:
                raise Failure(f"rotctl never read 200/10: {out!r} {err!r}")
            time.sleep(0.3)

        # And Hamlib's network radio client tunes the (simulated) radio.
        code, out, err = sh("rigctl", "-m", "2", "-r", f"127.0.0.1:{rig_port}", "F", "145950000")
        check(code == 0, f"rigctl F: {out} {err}")
        code, out, err = sh("rigctl", "-m", "2", "-r", f"127.0.0.1:{rig_port}", "f")
        check("145950000" in out, f"rigctl f reads back: {out!r} {err!r}")

        # Host mode on TCP: the banner and prompt, AZ/EL moves the antenna, ?A reads it, a bad
        # command is one ERROR line, Q closes.
        with socket.create_connection(("127.0.0.1", host_port), timeout=10) as c:
            def until(marker, limit=10):
                data = b""
                end = time.time() + limit
                while marker not in data:
                    if time.time() > end:
                        raise Failure(f"host mode: no {marker!r} in {data!r}")
                    chunk = c.recv(4096)
                    if not chunk:
                        return data
                    data += chunk
                return data
            hello = until(b"TrakBox>>")
            check(hello.startswith(b"TrakBox host mode.\r\nCommand:"), f"host banner: {hello!r}")
            c.sendall(b"AZ45 EL20\r")
            check(until(b"TrakBox>>") == b"TrakBox>>", "AZ/EL answers with the prompt only")
            c.sendall(b"FDx\r")
            err = until(b"TrakBox>>")
            check(err.startswith(b"ERROR FD:") and err.count(b"\r\n") == 1, f"one ERROR line: {err!r}")
            deadline = time.time() + 40
            while True:
                c.sendall(b"?A\r")
                m = re.match(rb"AZ([\d.]+) EL([\d.]+)\r\nTrakBox>>", until(b"TrakBox>>"))
                check(m is not None, "?A answers AZxxx.x ELxx.x")
                if abs(float(m.group(1)) - 45) < 1.5 and abs(float(m.group(2)) - 20) < 1.1:
                    break
                if time.time() > deadline:
                    raise Failure(f"host mode AZ45 EL20: the antenna is at {m.group(0)!r}")
                time.sleep(0.3)
            c.sendall(b"Q\r")
            check(until(b"never") == b"", "Q closes the connection")

        # The log says who connected and, at --log-level debug, what each client asked and got.
        with open(os.path.join(state, "trakbox.log"), encoding="utf-8", errors="replace") as f:
            log = f.read()
        check(re.search(r"rotctld: client 127\.0\.0\.1:\d+ connected", log) is not None, "rotctld connections logged")
        check("'P 200 10' -> 'RPRT 0" in log or "'P 200.000000 10.000000' -> 'RPRT 0" in log,
              "rotctld P logged with its reply")
        check(re.search(r"satrak: client 127\.0\.0\.1:\d+: 'GOTO=,120,30' -> 'GOTO=,OK'", log) is not None,
              "Satrak GOTO logged with its reply")
        check("'FDx' -> 'ERROR FD:" in log, "a refused host command logged")
    finally:
        try:
            tb.stdin.close()  # input ends: trakbox saves and leaves
            tb.wait(15)
        except Exception:
            tb.kill()
            tb.wait()
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
