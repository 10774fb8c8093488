"""PstRotator's UDP both ways (issue 48).

1. A PstRotator client aims trakbox (`--pst-port P`, the simulated rotator): from a socket on the
   client's port P+1 (where PstRotator's replies go), <PST><AZIMUTH>173.0</AZIMUTH></PST> and
   <PST><ELEVATION>25.0</ELEVATION></PST> to P: the antenna goes there (status), `<PST>AZ?</PST>` and
   `<PST>EL?</PST>` are answered on P+1 with where it is; <STOP> stops it. Bad datagrams (not <PST>,
   an unknown tag, a number out of range) are refused, counted in the status's servers and logged,
   and move nothing.
2. trakbox aims a PstRotator responder (`--rotator pstrotator:127.0.0.1:Q`): the responder takes
   AZIMUTH / ELEVATION on Q, moves at 10 deg/s and answers AZ? / EL? to the sender's address on
   Q+1. A rotctld client's `P 120 30` (trakbox's --rotctld-port) reaches it as those two datagrams;
   the position is read back into the status.
"""
import json
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, SOURCE, check, free_port, leave_and_read_log, poll, reap, run_test, wait_listening  # noqa: E402


def udp_pair_port():
    """A UDP port P with P+1 free too."""
    for _ in range(50):
        p = free_port()
        try:
            with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as a, socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as b:
                a.bind(("127.0.0.1", p))
                b.bind(("127.0.0.1", p + 1))
            return p
        except OSError:
            continue
    raise RuntimeError("no pair of free UDP ports")


def status(state):
    r = subprocess.run([BIN, "status", "--state", state, "--json"], capture_output=True, text=True, timeout=30)
    return json.loads(r.stdout)


def position(state):
    p = status(state)["antenna"].get("position") or {}
    return p.get("az_deg"), p.get("el_deg")


def client_aims_trakbox(procs):
    port = udp_pair_port()
    state = tempfile.mkdtemp(prefix="trakbox-pst-server-")
    me = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    me.bind(("127.0.0.1", port + 1))
    me.settimeout(3)
    try:
        tb = subprocess.Popen([BIN, "--state", state, "--line", "--satrak-port", "0", "--elements-url", LOCAL, "--pst-port", str(port),
                               "--clock-rate", "20"],
                              stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        procs.append(tb)
        poll("the status socket", lambda: os.path.exists(os.path.join(state, "trakbox.sock")), 15)
        poll("the PstRotator server in the status",
             lambda: any(s["name"] == "pstrotator" for s in status(state)["servers"]), 15)
        me.sendto(b"<PST><AZIMUTH>173.0</AZIMUTH></PST>", ("127.0.0.1", port))
        me.sendto(b"<PST><ELEVATION>25.0</ELEVATION></PST>", ("127.0.0.1", port))
        poll("the antenna at 173 / 25", lambda: (lambda az, el: az is not None and abs(az - 173.0) < 1.5
                                                 and abs(el - 25.0) < 1.5)(*position(state)), 30, every=0.5)
        az, el = position(state)
        me.sendto(b"<PST>AZ?</PST>", ("127.0.0.1", port))
        got_az = me.recvfrom(256)[0].decode()
        me.sendto(b"<PST>EL?</PST>", ("127.0.0.1", port))
        got_el = me.recvfrom(256)[0].decode()
        m_az, m_el = re.fullmatch(r"AZ:(-?\d+\.\d)", got_az), re.fullmatch(r"EL:(-?\d+\.\d)", got_el)
        check(m_az and abs(float(m_az.group(1)) - az) < 1.0, f"AZ? answered {got_az!r} (status {az})")
        check(m_el and abs(float(m_el.group(1)) - el) < 1.0, f"EL? answered {got_el!r} (status {el})")
        # Bad datagrams: refused, counted, nothing moves.
        for bad in (b"AZ:10", b"<PST><QRA>KN34BJ</QRA></PST>", b"<PST><AZIMUTH>999</AZIMUTH></PST>"):
            me.sendto(bad, ("127.0.0.1", port))
        poll("three datagrams refused", lambda: next(s for s in status(state)["servers"]
                                                     if s["name"] == "pstrotator")["refused_bad"] == 3, 10)
        time.sleep(1.0)
        az2, _ = position(state)
        check(abs(az2 - 173.0) < 1.5, f"a refused datagram moved nothing: az {az2}")
        me.sendto(b"<PST><STOP>1</STOP></PST>", ("127.0.0.1", port))
        time.sleep(0.3)
        srv = next(s for s in status(state)["servers"] if s["name"] == "pstrotator")
        check(srv["taken"] == 5 and srv["refused_not_allowed"] == 0, f"5 datagrams taken: {srv}")
        log = leave_and_read_log(tb, state, procs)
        check("pstrotator: a datagram from 127.0.0.1 refused" in log, "the refusal is logged")
        print(f"pstrotator_udp server: aimed to 173/25 (status {az:.1f}/{el:.1f}), AZ? {got_az!r}, EL? {got_el!r}, "
              f"3 bad datagrams refused and counted, {srv}")
    finally:
        me.close()
        shutil.rmtree(state, ignore_errors=True)


LOCAL = "file://" + os.path.join(SOURCE, "data", "amateur.tle")


class Box:
    """A PstRotator-speaking box on UDP `port`: AZIMUTH / ELEVATION set its target (10 deg/s), AZ? / EL?
    are answered to the sender's address on port+1; every datagram kept."""

    def __init__(self, port):
        self.port = port
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.bind(("127.0.0.1", port))
        self.sock.settimeout(0.2)
        self.az, self.el, self.target, self.at = 10.0, 5.0, None, time.time()
        self.got, self.lock, self.stop = [], threading.Lock(), False
        threading.Thread(target=self.run, daemon=True).start()

    def move(self):
        now = time.time()
        if self.target:
            step = 10.0 * (now - self.at)
            want_az, want_el = self.target
            self.az = want_az if abs(want_az - self.az) <= step else self.az + step * (1 if want_az > self.az else -1)
            self.el = want_el if abs(want_el - self.el) <= step else self.el + step * (1 if want_el > self.el else -1)
        self.at = now

    def run(self):
        while not self.stop:
            try:
                data, (host, _) = self.sock.recvfrom(600)
            except socket.timeout:
                continue
            except OSError:
                return
            text = data.decode(errors="replace")
            with self.lock:
                self.got.append(text)
                self.move()
                m = re.fullmatch(r"<PST><(AZIMUTH|ELEVATION)>(-?[\d.]+)</\1></PST>", text)
                if m:
                    az, el = self.target or (self.az, self.el)
                    self.target = (float(m.group(2)), el) if m.group(1) == "AZIMUTH" else (az, float(m.group(2)))
                elif text == "<PST>AZ?</PST>":
                    self.sock.sendto(f"AZ:{self.az:.1f}".encode(), (host, self.port + 1))
                elif text == "<PST>EL?</PST>":
                    self.sock.sendto(f"EL:{self.el:.1f}".encode(), (host, self.port + 1))
                elif text == "<PST><STOP>1</STOP></PST>":
                    self.target = None

    def close(self):
        self.stop = True
        self.sock.close()


def trakbox_aims_box(procs):
    port = udp_pair_port()
    box = Box(port)
    state = tempfile.mkdtemp(prefix="trakbox-pst-client-")
    try:
        rot = free_port()
        tb = subprocess.Popen([BIN, "--state", state, "--line", "--satrak-port", "0", "--elements-url", LOCAL, "--rotctld-port", str(rot),
                               "--rotator", f"pstrotator:127.0.0.1:{port}"],
                              stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        procs.append(tb)
        wait_listening(rot, "rotctld", proc=tb)
        poll("the box read back", lambda: position(state)[0] is not None and abs(position(state)[0] - 10.0) < 0.5, 15)
        with socket.create_connection(("127.0.0.1", rot), timeout=5) as s:
            s.sendall(b"P 120 30\n")
            check(s.recv(64).startswith(b"RPRT 0"), "rotctld P accepted")
        def told(tag, want):
            for g in list(box.got):
                m = re.fullmatch(rf"<PST><{tag}>(-?\d+\.\d)</{tag}></PST>", g)
                if m and abs(float(m.group(1)) - want) < 0.5:
                    return g
            return None
        poll("the box told 120 / 30", lambda: told("AZIMUTH", 120.0) and told("ELEVATION", 30.0), 15)
        sent = (told("AZIMUTH", 120.0), told("ELEVATION", 30.0))
        poll("the box's position read back on its way",
             lambda: box.az > 20 and abs((position(state)[0] or -99) - box.az) < 8, 15)
        log = leave_and_read_log(tb, state, procs)
        check("rotator: connected to PstRotator 127.0.0.1:" in log, "connected once the box answered")
        asks = sum(1 for g in box.got if g == "<PST>AZ?</PST>")
        print(f"pstrotator_udp client: rotctld P 120 30 -> the box got {sent[0]} and {sent[1]}; "
              f"position read back ({asks} AZ? asked)")
    finally:
        box.close()
        shutil.rmtree(state, ignore_errors=True)


def main():
    procs = []
    try:
        client_aims_trakbox(procs)
        trakbox_aims_box(procs)
    finally:
        reap(procs)


if __name__ == "__main__":
    run_test(main)
