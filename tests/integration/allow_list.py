"""Only the stations named may steer the antenna (issue 20): with --allow 127.0.0.1/32, a client bound
to 127.0.0.2 is refused on every TCP endpoint (Satrak, rotctld, rigctld, host mode), in the
protocol's own words, and the refusal is logged with its address; a client from 127.0.0.1 is
served. With --allow 127.0.0.0/8 the 127.0.0.2 client is served too. Listening beyond loopback
without --allow draws a warning at start."""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, check, frame, free_port, run_test, tcp_exchange  # noqa: E402


def start(state, ports, allow):
    sat, rot, rig, host = ports
    args = [BIN, "--state", state, "--clock", CLOCK, "--line", "--satrak-port", str(sat), "--rotctld-port", str(rot),
            "--rigctld-port", str(rig), "--host-port", str(host)]
    for a in allow:
        args += ["--allow", a]
    return subprocess.Popen(args, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


CASES = [  # (index of the port, request, what a served client sees, the refusal)
    (0, frame("VERSION?"), b"$VERSION?,", b"$ERR,8*"),
    (1, b"p\n", b"\n", b"RPRT -9\n"),
    (2, b"f\n", b"\n", b"RPRT -9\n"),
    (3, b"?A\r\n", b"TrakBox>>AZ", b"ERROR not allowed"),
]


def main():
    state = tempfile.mkdtemp(prefix="trakbox-allow-")
    try:
        ports = [free_port() for _ in range(4)]
        p = start(state, ports, ["127.0.0.1/32"])
        try:
            for i, req, served, refused in CASES:
                got = tcp_exchange(ports[i], req, served, source="127.0.0.1")
                check(served in got, f"port {i}: 127.0.0.1 is served: {got!r}")
                got = tcp_exchange(ports[i], req, b"\n", source="127.0.0.2")
                check(got.startswith(refused), f"port {i}: 127.0.0.2 refused in the protocol's words: {got!r}")
        finally:
            p.terminate()
            p.wait(20)
        with open(os.path.join(state, "trakbox.log")) as f:
            log = f.read()
        check(log.count("connection from 127.0.0.2 refused: not in --allow") == 4, "each refusal logged")

        p = start(state, ports, ["127.0.0.0/8"])
        try:
            for i, req, served, _ in CASES:
                got = tcp_exchange(ports[i], req, served, source="127.0.0.2")
                check(served in got, f"port {i}: 127.0.0.2 is served when its range is allowed: {got!r}")
        finally:
            p.terminate()
            p.wait(20)

        # Beyond loopback, no --allow: a warning on standard error and in the log.
        q = subprocess.run([BIN, "--state", state, "--clock", CLOCK, "--line", "--satrak-port", "0",
                            "--rotctld-port", str(free_port()), "--listen", "0.0.0.0"], input=b"",
                           capture_output=True, timeout=30)
        err = q.stderr.decode()
        check("WARNING" in err and "anyone who can reach it can move the antenna" in err, f"the warning: {err!r}")
        q = subprocess.run([BIN, "--state", state, "--satrak-port", "0", "--allow", "10.0.0.0/33"], input=b"",
                           capture_output=True, timeout=30)
        check(q.returncode == 2 and "--allow" in q.stderr.decode(), "a bad range is refused, naming --allow")
    finally:
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
