"""Idle holders cannot lock an endpoint (issue 14, defect 2), on the real binary: 20 connections are
opened and held silent on the rotctld port and on the Satrak port (more than the 16 each serves).
A client that arrives while they are held is refused in its protocol's own error format while the
holders are fresh; once they have been silent for the eviction time (10 s), a well-behaved client is
served on each endpoint, and a client that keeps polling (Gpredict's way) is never the one closed.
"""
import os
import socket
import subprocess
import sys
import tempfile
import shutil
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, Satrak, check, free_port, read_log, run_test, tcp_exchange  # noqa: E402

HOLDERS = 20


def rot_ask(port, line):
    """One rotctld exchange on a new connection; the reply text, or '' when closed without one."""
    return tcp_exchange(port, line.encode() + b"\n", b"\n", limit=0).decode(errors="replace")


def until(cond, limit):
    deadline = time.time() + limit
    while True:
        try:
            got = cond()
        except OSError:  # not listening yet
            got = None
        if got or time.time() > deadline:
            return got
        time.sleep(0.25)


def main():
    state = tempfile.mkdtemp(prefix="trakbox-flood-")
    rot, sat = free_port(), free_port()
    p = subprocess.Popen([BIN, "--state", state, "--clock", CLOCK, "--line", "--rotctld-port", str(rot),
                          "--satrak-port", str(sat)], stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                         stderr=subprocess.PIPE)
    holders = []
    try:
        check(until(lambda: rot_ask(rot, "_").startswith("trakbox"), 15), "rotctld answers")
        poller = socket.create_connection(("127.0.0.1", rot), timeout=5)
        for _ in range(HOLDERS):
            holders.append(socket.create_connection(("127.0.0.1", rot), timeout=5))
            holders.append(socket.create_connection(("127.0.0.1", sat), timeout=5))
        started = time.time()
        # Fresh holders: a newcomer is refused in the protocol's own words, not with silence.
        refused = rot_ask(rot, "p")
        check(refused == "RPRT -9\n" or time.time() - started >= 10, f"rotctld refusal: {refused!r}")

        def poll():
            poller.sendall(b"p\n")
            return poller.recv(4096)

        # Silent long enough: each newcomer is served, and the poller keeps its connection.
        def served_rot():
            poll()
            return rot_ask(rot, "p").count("\n") == 2

        check(until(served_rot, 40), "a well-behaved rotctld client is served while idle holders pile up")
        check(b"\n" in poll(), "the polling client was never closed")
        acu = until(lambda: _satrak_served(sat), 40)
        check(acu, "a well-behaved Satrak client is served while idle holders pile up")
        log = read_log(state)
        check("silent for" in log and "to serve a new client" in log, "the log says who made room")
        poller.close()
    finally:
        for h in holders:
            h.close()
        p.terminate()
        p.wait(20)
        shutil.rmtree(state, ignore_errors=True)


def _satrak_served(port):
    try:
        acu = Satrak(port, limit=2)
        ok = acu.ask("VERSION?").startswith("VERSION?,")
        acu.close()
        return ok
    except Exception:  # refused (ERR,8 then closed) while the holders are fresh
        return False


if __name__ == "__main__":
    run_test(main)
