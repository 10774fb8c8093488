"""trakbox --service, the unattended mode of the system service (issue 13), on the real binary: no
terminal and standard input closed; it tracks the stored tracking list, serves its ports, logs to
standard error (the journal) as well as trakbox.log; SIGHUP re-reads the data directory's elements
and goes on; SIGTERM with parking on parks the antenna, saves the state and exits 0."""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import zlib

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, CLOCK, check, free_port, run_test, tcp_exchange  # noqa: E402


def crc(data):
    text = json.dumps(data, separators=(",", ":"), sort_keys=True, ensure_ascii=False)
    return "%08x" % (zlib.crc32(text.encode()) & 0xFFFFFFFF)


def main():
    state = tempfile.mkdtemp(prefix="trakbox-service-")
    try:
        subprocess.run([BIN, "--state", state, "--satrak-port", "0", "--clock", CLOCK], input=b"",
                       capture_output=True, timeout=60, check=True)
        path = os.path.join(state, "trakbox-state.json")
        with open(path) as f:
            doc = json.load(f)
        data = doc["data"]
        data["rotor_control"] = True
        data["rotator"]["parking_enabled"] = True
        data["rotator"]["parking"] = [200.0, 10.0]
        doc["checksum"] = crc(data)
        with open(path, "w") as f:
            json.dump(doc, f)

        port = free_port()
        p = subprocess.Popen([BIN, "--service", "--state", state, "--satrak-port", "0", "--clock", CLOCK,
                              "--clock-rate", "10", "--rotctld-port", str(port)],
                             stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        try:
            got = tcp_exchange(port, b"p\n", b"\n", limit=20).decode()
            check(got.count("\n") >= 1, f"rotctld served by the service: {got!r}")
            p.send_signal(1)  # SIGHUP: re-read, go on
            deadline = time.time() + 10
            log_path = os.path.join(state, "trakbox.log")
            while "SIGHUP:" not in open(log_path).read():
                check(time.time() < deadline, "SIGHUP handled")
                time.sleep(0.1)
            check(p.poll() is None, "the service goes on after SIGHUP")
            check(tcp_exchange(port, b"p\n", b"\n").count(b"\n") >= 1, "and still serves")
            p.terminate()  # SIGTERM: park, save, leave
            out, err = p.communicate(timeout=150)
        finally:
            if p.poll() is None:
                p.kill()
                p.wait()
        err = err.decode()
        check(p.returncode == 0, f"exit status {p.returncode}: {err}")
        check(out == b"", "nothing on standard output: there is no terminal")
        for line in ("service: multiple tracking", "SIGHUP: ", "SIGHUP: radio entries of", "service: parking the antenna",
                     "service: antenna parked",
                     "trakbox stopped"):
            check(line in err, f"the journal (stderr) has '{line}': {err}")
        with open(path) as f:
            check(json.load(f)["format"] == "trakbox-state", "the state is saved")
        print(err.strip().splitlines()[-4:])
    finally:
        shutil.rmtree(state, ignore_errors=True)


if __name__ == "__main__":
    run_test(main)
