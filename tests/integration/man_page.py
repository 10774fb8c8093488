"""trakbox(1) and --help cannot drift (issue 13): every option that `trakbox --help` lists, and every
option of each command's --help, is described in packaging/trakbox.1, and the manual page names no
option the program does not have. Every command of --help has its entry under COMMANDS. The page
renders without a warning when groff is there (man-db's groff-base)."""
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, SOURCE, check, in_ci, run_test, sh  # noqa: E402

PAGE = os.path.join(SOURCE, "packaging", "trakbox.1")
COMMANDS = ["host", "propagate", "schedule", "passes", "next", "elements", "satrak", "attach", "status", "events", "log", "calibrate", "radio"]


def options_of(text):
    return set(re.findall(r"(?<![\w-])--[a-z][a-z0-9-]*", text))


def main():
    with open(PAGE) as f:
        page = f.read()
    described = options_of(re.sub(r"\\f[BIRP]", "", page).replace("\\-", "-"))
    code, top, _ = sh(BIN, "--help")
    check(code == 0, "trakbox --help")
    program = options_of(top)
    for c in COMMANDS:
        check(re.search(r"^\.B " + c + r"$", page, re.M) is not None, f"command {c} has an entry in the page")
        if c == "host":
            continue
        code, out, err = sh(BIN, c, "--help")
        check(code == 0, f"trakbox {c} --help: {err}")
        program |= options_of(out)
    missing = sorted(program - described)
    check(not missing, f"options of --help that trakbox(1) does not describe: {missing}")
    extra = sorted(described - program)
    check(not extra, f"options in trakbox(1) that trakbox does not have: {extra}")
    if shutil.which("groff"):
        p = subprocess.run(["groff", "-man", "-ww", "-z", PAGE], capture_output=True, text=True)
        check(p.returncode == 0 and not p.stderr.strip(), f"groff warnings: {p.stderr}")
    else:
        check(not in_ci(), "groff is not installed (package groff-base): in CI every tool must be")
        print("groff not installed: the page's syntax was not checked")
    print(f"{len(program)} options, {len(COMMANDS)} commands, described in trakbox(1)")


if __name__ == "__main__":
    run_test(main)
