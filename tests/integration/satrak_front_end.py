"""Satrak and host mode as front ends of the controller of record (issues 55 and 56), on the real
binary: in standby a Satrak GOTO, STEP, MOVE and TRACK are refused with ERR and the antenna stays,
host mode's FU is refused; under another client's `--exclusive rotctld` hold a Satrak GOTO is
refused; a Satrak client that holds the antenna is named in status by its connection, and its
disconnect hands the antenna back at once, as a rotctld client's does. A PstRotator datagram refused
in standby switches nothing on (rotor control stays off, and stored off)."""
import json
import os
import socket
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, Satrak, check, free_port, poll, run_test, wait_listening  # noqa: E402

START = "2026-05-21T12:09:40Z"


def cli(state, *args):
    r = subprocess.run([BIN, *args, "--state", state], capture_output=True, text=True, timeout=20)
    return r.returncode, r.stdout + r.stderr


def status(state):
    r = subprocess.run([BIN, "status", "--state", state, "--json"], capture_output=True, text=True, timeout=20)
    return json.loads(r.stdout)


def holder(state):
    return status(state)["control"]["antenna"]


def antenna(state):
    a = status(state)["antenna"]
    return a.get("az_deg"), a.get("el_deg")


def host_line(port, line):
    with socket.create_connection(("127.0.0.1", port), timeout=10) as c:
        c.settimeout(10)
        got = b""
        while b">" not in got:  # the greeting's prompt
            got += c.recv(4096)
        c.sendall(line.encode() + b"\r\n")
        reply = b""
        deadline = time.time() + 10
        while b">" not in reply and time.time() < deadline:
            reply += c.recv(4096)
        return reply.decode(errors="replace")


def main():
    state = tempfile.mkdtemp(prefix="trakbox-satrak-door-")
    sat, rot, host, pst = free_port(), free_port(), free_port(), free_port()
    p = subprocess.Popen([BIN, "--service", "--state", state, "--satrak-port", str(sat), "--rotctld-port", str(rot),
                          "--host-port", str(host), "--pst-port", str(pst), "--clock", START, "--clock-rate", "10",
                          "--rotor-control", "off"],
                         stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    try:
        wait_listening(sat, "Satrak", proc=p)
        wait_listening(host, "host mode", proc=p)
        code, out = cli(state, "standby", "on")
        check(code == 0, f"standby on: {out}")
        poll("standby holds the antenna", lambda: holder(state)["kind"] == "standby", 10)
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as u:
            u.sendto(b"<PST><AZIMUTH>173.0</AZIMUTH></PST>", ("127.0.0.1", pst))
        time.sleep(1.0)
        check(status(state)["antenna"]["rotor_control"] is False, "a PstRotator move refused in standby leaves rotor control off")
        code, out = cli(state, "settings", "set", "rotor_control", "on")
        check(code == 0, f"rotor control on through the one door: {out}")
        before = antenna(state)
        s = Satrak(sat)
        for cmd in ("GOTO=,120,35", "STEP=,5,5", "MOVE=,2,1", "TRACK=,1"):
            got = s.ask(cmd)
            check(",ERR," in got, f"{cmd} refused in standby: {got!r}")
        time.sleep(1.0)
        check(antenna(state) == before, f"the antenna stays: {before} -> {antenna(state)}")
        check(holder(state)["kind"] == "standby", f"standby still holds: {holder(state)}")
        check(status(state)["control"]["radio"]["kind"] == "standby", "and the radio")
        reply = host_line(host, "FU14595000")
        check("standby" in reply.lower(), f"host FU refused in standby: {reply!r}")
        code, out = cli(state, "standby", "off")
        check(code == 0, f"standby off: {out}")

        # --exclusive rotctld, set on the running station through the one door.
        code, out = cli(state, "settings", "set", "sharing.exclusive", "rotctld")
        check(code == 0, f"exclusive rotctld: {out}")
        r = socket.create_connection(("127.0.0.1", rot), timeout=10)
        r.sendall(b"P 200 30\n")
        check(r.recv(100).startswith(b"RPRT 0"), "rotctld takes the antenna")
        poll("rotctld holds", lambda: holder(state)["kind"] == "rotctld", 10)
        got = s.ask("GOTO=,120,35")
        check(",ERR," in got, f"a Satrak GOTO under rotctld's exclusive hold is refused: {got!r}")
        check(holder(state)["kind"] == "rotctld", f"rotctld still holds: {holder(state)}")
        r.close()
        poll("rotctld's hold ended with its connection", lambda: holder(state)["kind"] != "rotctld", 10)

        # The Satrak client takes it, is named by its connection, and hands it back when it leaves.
        got = s.ask("GOTO=,120,35")
        check(got.endswith(",OK"), f"GOTO taken now: {got!r}")
        h = holder(state)
        check(h["kind"] == "satrak" and h["label"].startswith("satrak 127.0.0.1:"), f"status names it: {h}")
        s.close()
        poll("the Satrak client's hold ended with its connection",
             lambda: holder(state)["kind"] == "tracking", 10)
        print("Satrak refused in standby and under --exclusive; its disconnect hands back")
    finally:
        p.terminate()
        try:
            p.wait(60)
        except subprocess.TimeoutExpired:
            p.kill()


if __name__ == "__main__":
    run_test(main)
