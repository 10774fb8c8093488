"""docs/connect.md, run (issue 39, item 14): every command of its ```sh blocks, against the
responders the other tests use, each `#>` line under a command found in what trakbox printed.

* `trakbox --radio list` and `trakbox --rotator list`: run as they are; the `#>` lines are looked
  for in their output.
* `rigctld ... &` and `rotctld ... &`: Hamlib's daemons, started on a free loopback port (`-T
  127.0.0.1 -t PORT`; the 4532/4533 of the next trakbox command become that port).
* Any other `trakbox ...`: the station, with `--state` a fresh directory, `--line`, no Satrak port
  and the clock at 2026-05-21 10:57 UTC (RS-44 a minute before its culmination, as the radio tests).
  /dev/ttyUSB0-2 become socat pseudo-terminals with a responder on the far end, chosen by the spec
  that names the device (ic9700/hamlib:3081/rigctld -m 3081: _ic9700.py; ic9100: the same at 7Ch;
  ts2000: _ts2000.py; ft847, ft817, ft818: _ft847.py; hamlib:603 / rotctld -m 603: a GS-232B, 901:
  a Rot2Prog, _rotators.py). Any other device name is left missing. The test types menu 6-0, then
  S 12 (RS-44); every radio must be tuned to RS-44's spots (both links, or the pair's one each),
  every rotator given `--rotor-control on` commanded a position; then input ends (trakbox leaves).
  The `#>` lines are looked for in its output (6-0) and trakbox.log, the pseudo-terminals' names
  put back to the document's device names.
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(__file__))
import _ic9700  # noqa: E402
from _ft847 import FT847  # noqa: E402
from _ic9700 import IC9700, from_bcd_le  # noqa: E402
from _ptyradio import RS44_PASS, SPOTS, poll, tuned  # noqa: E402
from _rotators import GS232B, Rot2Prog  # noqa: E402
from _tbharness import BIN, SOURCE, Failure, SerialPair, check, free_port, reap, run_test, skip, wait_listening  # noqa: E402
from _ts2000 import TS2000  # noqa: E402

DOC = os.path.join(SOURCE, "docs", "connect.md")
DEVICES = ("/dev/ttyUSB0", "/dev/ttyUSB1", "/dev/ttyUSB2")


class IC9100(IC9700):
    """The IC-9700 responder at the IC-9100's address; Main is its uplink in satellite mode."""

    def feed(self, chunk):
        saved, _ic9700.ADDR = _ic9700.ADDR, 0x7C
        try:
            super().feed(chunk)
        finally:
            _ic9700.ADDR = saved


# spec prefix -> (responder, downlink getter, uplink getter): the links as the model puts them.
RADIOS = {
    "ic9700": (IC9700, lambda r: r.get("main"), lambda r: r.get("sub")),
    "hamlib:3081": (IC9700, lambda r: r.get("main"), lambda r: r.get("sub")),
    "ic9100": (IC9100, lambda r: r.get("sub"), lambda r: r.get("main")),
    "ts2000": (TS2000, lambda r: r.get("A"), lambda r: r.get("B")),
    "ft847": (FT847, lambda r: r.get("rx"), lambda r: r.get("tx")),
    "ft817": (lambda p: FT847(p, ft817=True), lambda r: r.get("main"), None),
    "ft818": (lambda p: FT847(p, ft817=True), lambda r: r.get("main"), None),
}
ROTATORS = {"hamlib:603": GS232B, "hamlib:901": Rot2Prog}


def commands(text):
    """The commands of the ```sh blocks, in order: (command line, [expected texts])."""
    out = []
    for block in re.findall(r"```sh\n(.*?)```", text, re.S):
        for line in block.splitlines():
            if line.startswith("#>"):
                check(out, f"an expectation before any command: {line}")
                out[-1][1].append(line[2:].strip())
            elif line.strip() and not line.startswith("#"):
                out.append((line.strip(), []))
    return out


class Bench:
    """The pseudo-terminals, responders and daemons of one document section's commands."""

    def __init__(self):
        self.pairs, self.rigs, self.daemons, self.ports = {}, [], [], {}
        self.names = {}     # pty path -> the document's device name
        self.missing = tempfile.mkdtemp(prefix="connect-doc-missing-")

    def device(self, name, make):
        """The pty for the document's device `name`, with make(path) on its far end."""
        if name not in self.pairs:
            pair = SerialPair()
            self.pairs[name] = pair
            self.names[pair.trakbox_side] = name
            self.rigs.append((name, make(pair.terminal_side)))
        return self.pairs[name].trakbox_side

    def responder(self, name):
        return next(r for n, r in self.rigs if n == name)

    def substitute(self, spec, make):
        """spec with its /dev/ name replaced: a pty with make() behind it, or a missing path."""
        m = re.search(r"/dev/[A-Za-z0-9_]+", spec)
        if not m:
            return spec
        dev = m.group(0)
        if dev in DEVICES and make:
            return spec.replace(dev, self.device(dev, make))
        path = os.path.join(self.missing, os.path.basename(dev))
        self.names[path] = dev
        return spec.replace(dev, path)

    def daemon(self, argv):
        argv = [a for a in argv if a != "&"]
        model = argv[argv.index("-m") + 1]
        port = free_port()
        self.ports["4532" if argv[0] == "rigctld" else "4533"] = str(port)
        dev = argv[argv.index("-r") + 1]
        make = IC9700 if model == "3081" else ROTATORS.get(f"hamlib:{model}")
        argv[argv.index("-r") + 1] = self.substitute(dev, make)
        proc = subprocess.Popen(argv + ["-T", "127.0.0.1", "-t", str(port)],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        self.daemons.append(proc)
        wait_listening(port, argv[0], 15, proc)
        return dev, model

    def as_document(self, text):
        for path, name in self.names.items():
            text = text.replace(path, name)
        for doc_port, port in self.ports.items():
            text = text.replace(f":{port}", f":{doc_port}")
        return text

    def close(self):
        reap(self.daemons)
        for _, r in self.rigs:
            r.close()
        for p in self.pairs.values():
            p.close()
        shutil.rmtree(self.missing, ignore_errors=True)


def find(expected, seen, command):
    for e in expected:
        check(e in seen, f"`{command}`: the document's\n  {e}\nis not in what trakbox printed:\n{seen[-4000:]}")


def one_shot(argv, expected, command):
    p = subprocess.run([BIN, *argv[1:]], capture_output=True, text=True, timeout=30)
    check(p.returncode == 0, f"`{command}` exited {p.returncode}: {p.stderr}")
    find(expected, p.stdout + p.stderr, command)


def station(argv, expected, command, bench, daemons):
    """One station start of the document (see the module's comment)."""
    args, radios, rotators = [], [], []
    daemon_radio, daemon_rotator = daemons.get("rigctld"), daemons.get("rotctld")
    it = iter(argv[1:])
    for a in it:
        if a in ("--radio", "--uplink-radio", "--rotator"):
            spec = next(it)
            for port_doc, port in bench.ports.items():
                spec = spec.replace(f":{port_doc}", f":{port}")
            key = ":".join(spec.split(":")[:2]) if spec.startswith("hamlib:") else spec.split(":")[0]
            kind = RADIOS.get(key) if a != "--rotator" else ROTATORS.get(key)
            make = kind[0] if a != "--rotator" and kind else kind
            spec = bench.substitute(spec, make)
            dev = next((d for d in DEVICES if d in argv[argv.index(a) + 1]), None)
            if kind and dev and os.path.exists(bench.pairs[dev].trakbox_side):
                (radios if a != "--rotator" else rotators).append((dev, kind))
            if a == "--radio" and spec.startswith("rigctld") and daemon_radio:
                radios.append((daemon_radio[0], "rigctld"))
            if a == "--rotator" and spec.startswith("rotctld") and daemon_rotator:
                rotators.append(daemon_rotator)
            args += [a, spec]
        else:
            args.append(a)
    state = tempfile.mkdtemp(prefix="connect-doc-")
    out_path = os.path.join(state, "stdout.txt")
    procs = []
    try:
        with open(out_path, "wb") as out:
            tb = subprocess.Popen([BIN, "--state", state, "--data", os.path.join(SOURCE, "data"), "--line", "--satrak-port", "0",
                                   "--clock", RS44_PASS[0].strftime("%Y-%m-%dT%H:%M:%SZ"), *args],
                                  stdin=subprocess.PIPE, stdout=out, stderr=subprocess.STDOUT)
        procs.append(tb)
        printed = lambda: open(out_path, errors="replace").read()  # noqa: E731
        # The main menu, 6, 0 (the display), a key, Q back to the main menu: each key once its prompt is there.
        for prompt, times, keys in (("Select [", 1, b"6"), ("Select:", 1, b"0"), ("Press any key", 1, b" "),
                                    ("Select:", 2, b"Q"), ("Select [", 2, b"")):
            try:
                poll(f"`{command}`: {prompt!r} before {keys!r}", lambda: printed().count(prompt) >= times, 20)
            except Failure as e:
                raise Failure(f"{e}; trakbox {'running' if tb.poll() is None else 'exited ' + str(tb.returncode)}; it printed:\n{printed()[-3000:]}")
            time.sleep(0.2)
            tb.stdin.write(keys)
            tb.stdin.flush()
        tb.stdin.write(b"S\r" + RS44_PASS[1] + b"\r")
        tb.stdin.flush()
        tune(radios, bench, command)
        for dev, _ in rotators:
            rot = bench.responder(dev)
            poll(f"`{command}`: a position sent to the rotator on {dev}",
                 lambda: any(c == 0x2F or (isinstance(c, str) and c.startswith("W")) for c in rot.commands), 30)
        tb.stdin.close()
        check(tb.wait(30) == 0, f"`{command}`: trakbox leaves cleanly when input ends")
        with open(os.path.join(state, "trakbox.log")) as f:
            seen = bench.as_document(printed() + f.read())
        find(expected, seen, command)
        return seen
    finally:
        reap(procs)
        shutil.rmtree(state, ignore_errors=True)


def tune(radios, bench, command):
    """Every radio responder on RS-44's spots: both links, or one each for a pair."""
    for dev, kind in radios:
        if kind == "rigctld":
            # Hamlib's IC-9700 sets a frequency with 25 00 (the targetable VFO), which the responder,
            # answering only trakbox's own commands, refuses: the downlink must reach it all the same.
            rig = bench.responder(dev)
            poll(f"`{command}`: RS-44's downlink through rigctld (25 00 ...)",
                 lambda: any(f[4:6] == b"\x25\x00" and abs(from_bcd_le(f[6:11]) - SPOTS["RS-44"][0]) < 12_000
                             for _, f in rig.frames), 30)
    radios = [(dev, kind) for dev, kind in radios if kind != "rigctld"]
    singles = [(dev, kind) for dev, kind in radios if kind[2] is None]
    for dev, (_, down, up) in radios:
        if up is not None:
            rig = bench.responder(dev)
            tuned("RS-44", lambda: down(rig), lambda: up(rig), (f"{command}: downlink", "uplink"))
    if singles:
        check(len(singles) == 2, f"`{command}`: a one-link radio without its pair")
        d, u = bench.responder(singles[0][0]), bench.responder(singles[1][0])
        tuned("RS-44", lambda: singles[0][1][1](d), lambda: singles[1][1][1](u), (f"{command}: downlink radio", "uplink radio"))


def main():
    for tool in ("socat", "rigctld", "rotctld"):
        if not shutil.which(tool):
            skip(f"{tool} not installed")
    with open(DOC) as f:
        cmds = commands(f.read())
    check(len(cmds) >= 12, f"docs/connect.md has {len(cmds)} commands")
    bench, daemons, ran = Bench(), {}, 0
    try:
        for command, expected in cmds:
            argv = shlex.split(command)
            if argv[0] in ("rigctld", "rotctld"):
                dev, model = bench.daemon(argv)
                daemons[argv[0]] = (dev, RADIOS["hamlib:" + model] if argv[0] == "rigctld" else ROTATORS["hamlib:" + model])
                continue
            check(argv[0] == "trakbox", f"a command the test does not know: {command}")
            check(expected, f"`{command}`: the document says nothing it prints")
            if argv[1:] in (["--radio", "list"], ["--rotator", "list"]):
                one_shot(argv, expected, command)
            else:
                station(argv, expected, command, bench, daemons)
                bench.close()
                bench, daemons = Bench(), {}
            ran += 1
            print(f"ran: {command}")
    finally:
        bench.close()
    print(f"connect_doc: {ran} commands of docs/connect.md run, {len(cmds) - ran} daemons started")


if __name__ == "__main__":
    run_test(main)
