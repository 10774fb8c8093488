"""The battery-backed RAM: state survives restarts; a damaged state file gives the manual's message,
the defaults, and is kept aside (never overwritten). Runs trakbox on pipes (plain-line mode).
"""
import glob
import json
import os
import shutil
import subprocess
import sys
import tempfile
import zlib

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, check, run_test  # noqa: E402

LOST = "Data in RAM was lost !! Set default parameter !"


def run(state, keys, extra=()):
    p = subprocess.run([BIN, "--state", state, "--clock", CLOCK, "--satrak-port", "0", *extra], input=keys.encode(),
                       capture_output=True, timeout=60)
    return p.returncode, p.stdout.decode("latin-1"), p.stderr.decode("latin-1")


def crc(data):
    """trakbox's checksum: CRC-32 of the data as compact JSON with sorted keys (nlohmann's dump())."""
    text = json.dumps(data, separators=(",", ":"), sort_keys=True, ensure_ascii=False)
    return "%08x" % (zlib.crc32(text.encode()) & 0xFFFFFFFF)


def state_path(state):
    return os.path.join(state, "trakbox-state.json")


def main():
    state = tempfile.mkdtemp(prefix="trakbox-state-")
    try:
        # Fresh start, set a callsign; input ends -> trakbox saves and exits 0.
        code, out, _ = run(state, "4\rK7ABC\r\r\r\r\r\r\r")
        check(code == 0, f"exit status {code}")
        check(LOST not in out, "a fresh start is not a RAM loss")
        doc = json.load(open(state_path(state)))
        check(doc["data"]["station"]["callsign"] == "K7ABC", "callsign saved")
        check(doc["checksum"] == crc(doc["data"]), "the checksum is CRC-32 of the compact data")
        check(not glob.glob(os.path.join(state, ".trakbox-state.json.tmp*")), "no temporary file left behind")

        # Restart keeps it.
        code, out, _ = run(state, "4\r\r\r\r\r\r\r")
        check("Callsign           : K7ABC" in out, "restart shows the stored callsign")

        # One byte changed: the checksum fails.
        text = open(state_path(state)).read()
        damaged = text.replace("K7ABC", "K7ABD")
        open(state_path(state), "w").write(damaged)
        code, out, _ = run(state, "4\r\r\r\r\r\r\r")
        check(code == 0, f"exit status {code}")
        check(LOST in out, "the manual's message after a checksum failure")
        check("Callsign           : NOCALL" in out, "defaults after the loss")
        kept = glob.glob(state_path(state) + ".corrupt-*")
        check(len(kept) == 1, f"one kept-aside copy: {kept}")
        check(open(kept[0]).read() == damaged, "the damaged file is kept exactly")
        check(kept[0] in out, "the operator is told where the damaged copy is")
        check("checksum" in out, "the reason is given")

        # The checksum is right but the content is impossible (latitude 95): refused as a whole.
        doc = json.load(open(state_path(state)))
        doc["data"]["station"]["lat_deg"] = 95.0
        doc["checksum"] = crc(doc["data"])
        open(state_path(state), "w").write(json.dumps(doc, indent=2))
        code, out, _ = run(state, "")
        check(LOST in out, "impossible content is a loss too")
        check("station.lat_deg" in out, f"the bad field is named: {out[:400]}")
        check(len(glob.glob(state_path(state) + ".corrupt-*")) == 2, "second copy kept, first untouched")
        check(open(kept[0]).read() == damaged, "the first kept copy is never overwritten")

        # Not JSON at all.
        open(state_path(state), "w").write("\x00\x01garbage")
        code, out, _ = run(state, "")
        check(LOST in out and code == 0, "garbage is a loss, and trakbox still runs")
        check(len(glob.glob(state_path(state) + ".corrupt-*")) == 3, "third copy kept")

        # Bad command-line values: one line naming the argument, exit status 2.
        for args, word in ((["--baud", "300"], "--baud"), (["--standalone", "16"], "--standalone"),
                           (["--clock", "yesterday"], "--clock"), (["--rotator", "gs232"], "--rotator"),
                           (["--bogus"], "--bogus")):
            p = subprocess.run([BIN, "--state", state, "--satrak-port", "0", *args], input=b"", capture_output=True,
                               timeout=30)
            err = p.stderr.decode()
            check(p.returncode == 2, f"{args}: exit status {p.returncode}")
            check(word in err and err.count("\n") == 1, f"{args}: one line naming {word}: {err!r}")
    finally:
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
