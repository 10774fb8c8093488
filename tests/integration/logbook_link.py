"""Issue 56 item 12 on the real binary: STATE/logbook.sqlite a symbolic link to a file outside the
state directory was followed (the QSO written there, -wal and -shm beside it). Now the link is
refused: `status --json` has the reason as the problem of `log`, trakbox.log says it, a QSO from the
page is refused, and nothing is written where the link points."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import check, read_log, run_test  # noqa: E402
from _web import WebStation  # noqa: E402


def main():
    state = tempfile.mkdtemp(prefix="trakbox-logbook-link-")
    outside = tempfile.mkdtemp(prefix="trakbox-outside-")
    target = os.path.join(outside, "stolen.sqlite")
    os.symlink(target, os.path.join(state, "logbook.sqlite"))
    web = WebStation(state=state)
    try:
        s = web.status()
        problem = s["log"].get("problem") or ""
        check("logbook.sqlite: is a symbolic link: trakbox does not follow links in its state directory" in problem,
              f"the problem of log in status: {s['log']}")
        check(any("is a symbolic link" in p for p in s["problems"]), f"among the problems: {s['problems']}")
        status, r = web.post("/api/v1/log", {"call": "W1AW", "sat": "ISS"})
        check(status != 200, f"a QSO without a logbook is refused: {status} {r}")
    finally:
        web.stop()
    check("is a symbolic link" in read_log(state), "the refusal is logged")
    left = sorted(os.listdir(outside))
    check(left == [], f"nothing written where the link points: {left}")
    check(os.path.islink(os.path.join(state, "logbook.sqlite")), "the link left as it was")
    print(f"refused: {problem}")


if __name__ == "__main__":
    run_test(main)
