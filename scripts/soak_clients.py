#!/usr/bin/env python3
"""The mixed clients of scripts/soak.sh: for --seconds, against a running trakbox's endpoints on
127.0.0.1, at once:

  satrak-poll   one long-lived Satrak connection asking STATUS? and TPOS? twice a second
  satrak-cmd    a new Satrak connection every 3 s for one GOTO=,AZ,EL or STOP=, then closed
  rotctl        Hamlib's `rotctl -m 2`: `p` every second, `P AZ EL` every third (a connection each)
  rigctl        Hamlib's `rigctl -m 2`: `f` every second, `F HZ` every third
  host          a host-mode connection asking ?A every second, leaving with Q and coming back
                every 20 s
  idle-PORT     three connections to each endpoint that never say anything, dropped and opened
                again every 45 s (the servers may evict them meanwhile: that is allowed)

Standard library only. Prints one summary line per client and exits 1 when a request went
unanswered (no reply, a dropped connection, a Hamlib client failing other than by a refusal).
"""
import argparse
import random
import re
import socket
import subprocess
import threading
import time

HOST = "127.0.0.1"


class Tally:
    def __init__(self, name):
        self.name = name
        self.ok = 0          # answered
        self.refused = 0     # answered with the protocol's error (e.g. a command refused while tracking)
        self.failed = 0      # no answer: timeout, connection refused or dropped
        self.errors = []
        self.lock = threading.Lock()

    def add(self, kind, detail=""):
        with self.lock:
            setattr(self, kind, getattr(self, kind) + 1)
            if kind == "failed" and len(self.errors) < 5:
                self.errors.append(f"{time.strftime('%H:%M:%S')} {detail}")

    def line(self):
        s = f"{self.name}: {self.ok} answered, {self.refused} refused, {self.failed} unanswered"
        return s + (f" (first: {'; '.join(self.errors)})" if self.errors else "")


def satrak_frame(payload):
    x = 0
    for b in payload.encode():
        x ^= b
    return ("$%s*%02X\r\n" % (payload, x)).encode()


class LineConn:
    """A TCP connection read up to a marker."""

    def __init__(self, port, timeout=10.0):
        self.s = socket.create_connection((HOST, port), timeout=timeout)
        self.buf = b""

    def until(self, marker):
        while marker not in self.buf:
            chunk = self.s.recv(4096)
            if not chunk:
                raise ConnectionError("closed by the server")
            self.buf += chunk
        head, self.buf = self.buf.split(marker, 1)
        return head

    def close(self):
        try:
            self.s.close()
        except OSError:
            pass


def satrak_ask(conn, payload):
    conn.s.sendall(satrak_frame(payload))
    reply = conn.until(b"\r\n").decode("latin-1")
    if not re.fullmatch(r"\$[^*]*\*[0-9A-Fa-f]{2}", reply):
        raise ValueError(f"malformed reply {reply!r}")
    return "refused" if ",ERR" in reply else "ok"


def satrak_poll(args, stop, t):
    conn = None
    queries = ["STATUS?", "TPOS?"]
    i = 0
    while not stop.is_set():
        try:
            if conn is None:
                conn = LineConn(args.satrak)
            t.add(satrak_ask(conn, queries[i % 2]))
        except (OSError, ValueError, ConnectionError) as e:
            t.add("failed", f"{queries[i % 2]}: {e}")
            if conn:
                conn.close()
            conn = None
        i += 1
        stop.wait(0.5)
    if conn:
        conn.close()


def satrak_cmd(args, stop, t):
    rnd = random.Random(1)
    i = 0
    while not stop.is_set():
        payload = "STOP=" if i % 4 == 3 else "GOTO=,%d,%d" % (rnd.randrange(0, 360), rnd.randrange(0, 80))
        try:
            conn = LineConn(args.satrak)
            try:
                t.add(satrak_ask(conn, payload))
            finally:
                conn.close()
        except (OSError, ValueError, ConnectionError) as e:
            t.add("failed", f"{payload}: {e}")
        i += 1
        stop.wait(3.0)


# Hamlib clients: a non-zero exit whose message is the daemon's refusal is an answer.
REFUSAL = re.compile(r"rejected|not available|Invalid|not implemented|out of range", re.I)


def hamlib_client(tool, port, commands, stop, t):
    i = 0
    while not stop.is_set():
        cmd = commands(i)
        try:
            p = subprocess.run([tool, "-m", "2", "-r", f"{HOST}:{port}", *cmd], capture_output=True,
                               text=True, timeout=20)
            if p.returncode == 0 and not re.search(r"error", p.stdout + p.stderr, re.I):
                t.add("ok")
            elif REFUSAL.search(p.stdout + p.stderr):
                t.add("refused")
            else:
                t.add("failed", f"{' '.join(cmd)}: exit {p.returncode} {(p.stdout + p.stderr).strip()[-200:]!r}")
        except subprocess.TimeoutExpired:
            t.add("failed", f"{' '.join(cmd)}: no answer in 20 s")
        i += 1
        stop.wait(1.0)


def host_client(args, stop, t):
    conn = None
    opened = 0.0
    while not stop.is_set():
        try:
            if conn is None:
                conn = LineConn(args.host)
                conn.until(b"TrakBox>>")
                opened = time.time()
            conn.s.sendall(b"?A\r")
            reply = conn.until(b"TrakBox>>").decode("latin-1")
            if re.match(r"AZ[\d.]+ EL-?[\d.]+\r\n$", reply):
                t.add("ok")
            elif reply.startswith("ERROR"):
                t.add("refused")
            else:
                t.add("failed", f"?A: {reply!r}")
            if time.time() - opened > 20:
                conn.s.sendall(b"Q\r")
                conn.close()
                conn = None
        except (OSError, ConnectionError) as e:
            t.add("failed", f"?A: {e}")
            if conn:
                conn.close()
            conn = None
        stop.wait(1.0)
    if conn:
        conn.close()


def idlers(port, stop, t, count=3, hold=45.0):
    while not stop.is_set():
        held = []
        for _ in range(count):
            try:
                held.append(socket.create_connection((HOST, port), timeout=10))
                t.add("ok")
            except OSError as e:
                t.add("failed", f"connect: {e}")
        stop.wait(hold)
        for s in held:
            s.close()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seconds", type=float, required=True)
    ap.add_argument("--satrak", type=int, required=True)
    ap.add_argument("--rotctld", type=int, required=True)
    ap.add_argument("--rigctld", type=int, required=True)
    ap.add_argument("--host", type=int, required=True)
    args = ap.parse_args()

    stop = threading.Event()
    tallies = []

    def start(name, fn, *fargs):
        t = Tally(name)
        tallies.append(t)
        th = threading.Thread(target=fn, args=(*fargs, stop, t), daemon=True)
        th.start()
        return th

    rnd = random.Random(2)
    threads = [
        start("satrak-poll", satrak_poll, args),
        start("satrak-cmd", satrak_cmd, args),
        start("rotctl", hamlib_client, "rotctl", args.rotctld,
              lambda i: ["P", str(rnd.randrange(0, 360)), str(rnd.randrange(0, 80))] if i % 3 == 2 else ["p"]),
        start("rigctl", hamlib_client, "rigctl", args.rigctld,
              lambda i: ["F", str(145_800_000 + 10 * rnd.randrange(0, 1000))] if i % 3 == 2 else ["f"]),
        start("host", host_client, args),
    ]
    for name, port in (("satrak", args.satrak), ("rotctld", args.rotctld), ("rigctld", args.rigctld),
                       ("host", args.host)):
        threads.append(start(f"idle-{name}", idlers, port))
    stop.wait(args.seconds)
    stop.set()
    for th in threads:
        th.join(30)
    for t in tallies:
        print(t.line())
    return 1 if any(t.failed for t in tallies) else 0


if __name__ == "__main__":
    raise SystemExit(main())
