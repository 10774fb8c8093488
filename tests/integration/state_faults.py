"""Faults of the battery-backed RAM, on the real binary (issue 14, defects 1, 3 and 4; issue 20's file
modes):

- a state document of the wrong shape (wrong JSON types anywhere) takes the manual's "Data in RAM
  was lost" path, is kept aside, and trakbox comes up on its defaults — it used to abort (exit 134);
- a save that fails (the state file's name is taken by a directory: an injected write failure that
  needs no privileges) is answered ERR,12 on Satrak, not OK, and the log says memory and disk differ;
- kill -9 in the middle of saves, many rounds: every restart loads the state, nothing that was
  acknowledged is lost, and the temporary files the kills leave are removed at the next start;
- the state directory is 0700 and the document 0600, and looser ones are tightened with a log line.
Satrak frames are built and checked here with their own checksum code, not trakbox's.
"""
import glob
import json
import os
import random
import select
import shutil
import stat
import subprocess
import sys
import tempfile
import time
import zlib

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, Satrak, check, frame, free_port, read_log, run_test  # noqa: E402

LOST = "Data in RAM was lost !! Set default parameter !"


def crc(data):
    text = json.dumps(data, separators=(",", ":"), sort_keys=True, ensure_ascii=False)
    return "%08x" % (zlib.crc32(text.encode()) & 0xFFFFFFFF)


def state_path(state):
    return os.path.join(state, "trakbox-state.json")


def run_once(state, keys=b""):
    p = subprocess.run([BIN, "--state", state, "--clock", CLOCK, "--satrak-port", "0"], input=keys,
                       capture_output=True, timeout=60)
    return p.returncode, p.stdout.decode("latin-1"), p.stderr.decode("latin-1")


def start(state, port):
    return subprocess.Popen([BIN, "--state", state, "--clock", CLOCK, "--satrak-port", str(port), "--line"],
                            stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def wrong_shapes(state):
    """Documents with every member of the wrong JSON type: none may abort trakbox."""
    good = None
    code, out, _ = run_once(state)  # a fresh state to take a valid data part from
    check(code == 0, f"fresh start: exit {code}")
    with open(state_path(state)) as f:
        good = json.load(f)["data"]
    bad_docs = [
        {"format": {}},
        {"format": "trakbox-state", "version": 1, "checksum": 7, "data": good},
        {"format": ["trakbox-state"], "checksum": crc(good), "data": good},
        {"format": "trakbox-state", "version": 1, "checksum": crc([]), "data": []},
    ]
    # Valid checksums over data whose members have the wrong type.
    for key in list(good.keys()):
        for wrong in ({}, [], "x", 1.5, None, True):
            if type(wrong) is type(good[key]):
                continue
            data = dict(good)
            data[key] = wrong
            bad_docs.append({"format": "trakbox-state", "version": 1, "checksum": crc(data), "data": data})
            break
    station = dict(good["station"])
    station["lat_deg"] = "32.2"
    data = dict(good, station=station)
    bad_docs.append({"format": "trakbox-state", "version": 1, "checksum": crc(data), "data": data})
    for n, doc in enumerate(bad_docs):
        text = json.dumps(doc)
        with open(state_path(state), "w") as f:
            f.write(text)
        before = set(glob.glob(state_path(state) + ".corrupt-*"))
        code, out, err = run_once(state)
        check(code == 0, f"document {n} ({text[:80]}...): exit status {code}, stderr {err[:200]!r}")
        check(LOST in out, f"document {n}: the manual's message")
        kept = set(glob.glob(state_path(state) + ".corrupt-*")) - before
        check(len(kept) == 1, f"document {n}: kept aside once: {kept}")
        with open(kept.pop()) as f:
            check(f.read() == text, f"document {n}: kept exactly")
        with open(state_path(state)) as f:
            check(json.load(f)["format"] == "trakbox-state", f"document {n}: defaults saved")
    return len(bad_docs)


def modes(state):
    os.chmod(state, 0o755)
    os.chmod(state_path(state), 0o644)
    code, _, _ = run_once(state)
    check(code == 0, f"exit {code}")
    check(stat.S_IMODE(os.stat(state).st_mode) == 0o700, "state directory tightened to 0700")
    check(stat.S_IMODE(os.stat(state_path(state)).st_mode) == 0o600, "state document tightened to 0600")
    log = read_log(state)
    check("mode 755" in log and "mode 644" in log, "the log says what was tightened")
    fresh = os.path.join(state, "new", "deeper")
    code, _, _ = run_once(fresh)
    check(stat.S_IMODE(os.stat(fresh).st_mode) == 0o700, "a new state directory is 0700")
    check(stat.S_IMODE(os.stat(state_path(fresh)).st_mode) == 0o600, "a new state document is 0600")


def failed_save(state):
    port = free_port()
    p = start(state, port)
    try:
        acu = Satrak(port)
        check(acu.ask("REDUCTION=,1000,1000") == "REDUCTION=,OK", "a save that works is acknowledged")
        # The disk refuses: the state file's name is a directory now, so the rename of every save fails.
        os.rename(state_path(state), state_path(state) + ".saved")
        os.mkdir(state_path(state))
        check(acu.ask("REDUCTION=,2000,2000") == "REDUCTION=,ERR,12", "a failed save is not acknowledged")
        check(acu.ask("REDUCTION?") == "REDUCTION?,2000,2000", "the change holds in memory")
        os.rmdir(state_path(state))
        os.rename(state_path(state) + ".saved", state_path(state))
        check(acu.ask("REDUCTION=,3000,3000") == "REDUCTION=,OK", "acknowledged again once saves work")
        acu.close()
    finally:
        p.terminate()
        p.wait(20)
    log = read_log(state)
    check("not on disk" in log, "the log says the change is in memory but not on disk")
    with open(state_path(state)) as f:
        check(json.load(f)["data"]["satrak"]["reduction_x"] == 3000, "the last acknowledged value is stored")


def kill_during_saves(state, rounds):
    rng = random.Random(14)
    acknowledged = 0
    value = 0
    for r in range(rounds):
        port = free_port()
        p = start(state, port)
        try:
            acu = Satrak(port)
            got = acu.ask("REDUCTION?")
            check(got.startswith("REDUCTION?,"), f"round {r}: {got}")
            stored = int(float(got.split(",")[1]))
            check(stored >= acknowledged, f"round {r}: acknowledged {acknowledged} but loaded {stored}")
            # Saves as fast as the unit answers, then kill -9 at a random moment in the stream.
            acu.s.setblocking(False)
            deadline = time.time() + rng.uniform(0.05, 0.4)
            sent = []
            # The socket does not block: when the unit falls behind (slow disk) its receive
            # buffer fills, so unsent bytes wait here and no new frame is made until they go.
            pending = b""
            while time.time() < deadline:
                if not pending:
                    value += 1
                    pending = frame(f"REDUCTION=,{value},{value}")
                    sent.append(value)
                try:
                    pending = pending[acu.s.send(pending):]
                except BlockingIOError:
                    select.select([acu.s], [acu.s], [], 0.01)
                try:
                    acu.buf += acu.s.recv(65536)
                except BlockingIOError:
                    pass
            p.kill()
            p.wait()
            try:
                while True:
                    chunk = acu.s.recv(65536)
                    if not chunk:
                        break
                    acu.buf += chunk
            except (BlockingIOError, ConnectionResetError):
                pass
            oks = acu.buf.count(b"REDUCTION=,OK")
            if oks:
                acknowledged = sent[oks - 1]
            acu.close()
        finally:
            if p.poll() is None:
                p.kill()
                p.wait()
        with open(os.path.join(state, "trakbox.log")) as f:
            check(LOST not in f.read(), f"round {r}: no RAM loss")
    # The next start loads and removes every temporary file the kills left.
    code, out, _ = run_once(state)
    check(code == 0 and LOST not in out, "the last restart loads")
    left = glob.glob(os.path.join(state, ".trakbox-state.json.tmp-*"))
    check(not left, f"temporary files removed at start: {left}")
    return acknowledged


def main():
    state = tempfile.mkdtemp(prefix="trakbox-faults-")
    try:
        n = wrong_shapes(state)
        modes(state)
        failed_save(state)
        # A temporary file of a killed save, from a process that is gone.
        stale = os.path.join(state, ".trakbox-state.json.tmp-999999999")
        with open(stale, "w") as f:
            f.write("{")
        run_once(state)
        check(not os.path.exists(stale), "a stale temporary file is removed at start")
        with open(os.path.join(state, "trakbox.log")) as f:
            check("did not finish" in f.read(), "and the log says so")
        last = kill_during_saves(state, 12)
        print(f"{n} wrong-shape documents refused; 12 kill -9 rounds, last acknowledged value {last} kept")
    finally:
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
