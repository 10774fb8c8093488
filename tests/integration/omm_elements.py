"""OMM through the real binary (issue 12): `trakbox passes` on every OMM encoding of
tests/data/omm (written by python-sgp4, scripts/make-omm-fixtures.py) prints exactly what it prints
on the TLE the OMM was made from, for catalog numbers 25544.., 100123.. (Alpha-5 TLE) and
800123456.. (no TLE); `trakbox elements --to` round-trips; a TLE that cannot hold 800123456 is an
error; `--no-checksum` on Vallado's SGP4-VER.TLE accepts the sets with wrong checksums, which are
refused without it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, SOURCE, check, run_test, sh  # noqa: E402

DATA = os.path.join(SOURCE, "tests", "data", "omm")
VALLADO = os.path.join(os.environ.get("TRAKBOX_SGP4_DATA_DIR", "/usr/lib/python3/dist-packages/sgp4"),
                       "SGP4-VER.TLE")
ENCODINGS = [".json", "-spacetrack.json", ".csv", ".xml", ".kvn"]
STATION = ["--station", "52.0,5.0,10"]
# ISS and QO-100 (always up from here) near their 2026 epochs; MOLNIYA 2-14 near its 2006 epoch.
WINDOWS = [["--sat", "ISS (ZARYA)", "--sat", "QO-100", "--start", "2026-05-21T06:00:00Z", "--hours", "48"],
           ["--sat", "MOLNIYA 2-14", "--start", "2006-06-25T08:00:00Z", "--hours", "48"]]


def run_ok(*args):
    code, out, err = sh(BIN, *args, timeout=120)
    check(code == 0, f"trakbox {' '.join(args)}: exit {code}: {err}")
    return out


def check_passes():
    compared = 0
    for window in WINDOWS:
        want = run_ok("passes", os.path.join(DATA, "sources.tle"), *STATION, *window, "--csv")
        check(want.count("\n") > 2, f"passes from the TLE: {want}")
        for group in ["sources", "n100123", "n800123456"]:
            files = [group + e for e in ENCODINGS] + ([group + ".tle"] if group != "n800123456" else [])
            for name in files:
                got = run_ok("passes", os.path.join(DATA, name), *STATION, *window, "--csv")
                check(got == want, f"passes from {name} differ from the TLE's:\n{got}\nvs\n{want}")
                compared += 1
    return compared


def check_listing():
    # The 9-digit numbers in the listing: the TLE's listing with the numbers and format replaced.
    tle = run_ok("elements", os.path.join(DATA, "sources.tle"), "--time", "2026-06-01")
    for source, encoding, fmt in [("n800123456.kvn", "n800123456", "OMM KVN"), ("n100123.xml", "n100123", "OMM XML")]:
        first = int(encoding[1:])
        want = tle.replace(os.path.join(DATA, "sources.tle"), os.path.join(DATA, source)).replace("NASA TLE", f"{fmt:<8}")
        for i, old in enumerate(["25544", "43700", " 8195"]):
            want = want.replace(f"{old:>9}", f"{first + i:>9}")
        got = run_ok("elements", os.path.join(DATA, source), "--time", "2026-06-01")
        check(got == want, f"elements {source}:\n{got}\nexpected\n{want}")


def check_conversions(tmp):
    with open(os.path.join(DATA, "sources.tle")) as f:
        original = f.read()
    for group, tle_ok in [("sources", True), ("n100123", True), ("n800123456", False)]:
        json_direct = run_ok("elements", os.path.join(DATA, group + ".json"), "--to", "omm-json")
        for target in ["omm-json", "omm-xml", "omm-csv", "omm-kvn"]:
            path = os.path.join(tmp, f"{group}.{target}")
            with open(path, "w") as f:
                f.write(run_ok("elements", os.path.join(DATA, group + ".kvn"), "--to", target))
            again = run_ok("elements", path, "--to", "omm-json")
            check(again == json_direct, f"{group} through {target} and back:\n{again}\nvs\n{json_direct}")
            code, out, err = sh(BIN, "elements", path, "--to", "tle")
            if tle_ok:
                with open(os.path.join(DATA, group + ".tle")) as f:
                    want = f.read()
                check(code == 0 and out == want, f"{group} {target} -> tle: exit {code} {err}\n{out}\nvs\n{want}")
            else:
                check(code == 1 and out == "", f"{group} {target} -> tle: exit {code}, stdout {out!r}")
                check("ISS (ZARYA) (800123456): no TLE: catalog number 800123456 does not fit a TLE" in err, err)
    back = run_ok("elements", os.path.join(tmp, "sources.omm-xml"), "--to", "tle")
    check(back == original, f"TLE -> OMM -> TLE:\n{back}\nvs\n{original}")


def check_no_checksum(tmp):
    code, out, err = sh(BIN, "elements", VALLADO, "--time", "2026-01-01")
    refused = [l for l in err.splitlines() if "checksum" in l and "(set refused; --no-checksum accepts it)" in l]
    check(code == 1 and "30 element sets" in out and len(refused) == 3, f"without --no-checksum: {code}\n{out}\n{err}")
    code, out, err = sh(BIN, "elements", VALLADO, "--time", "2026-01-01", "--no-checksum")
    accepted = [l for l in err.splitlines() if "checksum" in l and "(warning: set accepted)" in l]
    check("33 element sets" in out and len(accepted) == 3, f"with --no-checksum: {out}\n{err}")
    # Every one of the 33 sets, each in a file of its own, propagates at its epoch; 33334 is
    # Vallado's set whose perturbed eccentricity leaves 0..1 at once: trakbox's SGP4 reports the
    # error at initialisation (Vallado's testcpp prints the t=0 line, then stops).
    code, tles, err = sh(BIN, "elements", VALLADO, "--no-checksum", "--to", "tle")
    lines = tles.splitlines()
    check(code == 0 and len(lines) == 66, f"--to tle: {code} {len(lines)} lines {err}")
    propagated = 0
    for i in range(0, 66, 2):
        path = os.path.join(tmp, f"set{i // 2}.tle")
        with open(path, "w") as f:
            f.write(lines[i] + "\n" + lines[i + 1] + "\n")
        code, out, err = sh(BIN, "propagate", path, "--start", "0", "--stop", "0", "--step", "1")
        if lines[i][2:7] == "33334":
            check(code == 1 and "# sgp4 error" in out, f"33334: exit {code} {out} {err}")
        else:
            check(code == 0 and len(out.splitlines()) == 1, f"set {lines[i][2:7]}: exit {code} {out} {err}")
        propagated += 1
    check(propagated == 33, f"{propagated} sets")
    code, out, err = sh(BIN, "propagate", VALLADO, "--sat", "33333", "--start", "0", "--stop", "0", "--step", "1")
    check(code == 2 and "checksum" in err and "no element set named or numbered '33333'" in err, f"{code} {err}")
    code, out, err = sh(BIN, "propagate", VALLADO, "--sat", "33333", "--start", "0", "--stop", "0", "--step", "1",
                        "--no-checksum")
    check(code == 0 and "(warning: set accepted)" in err and len(out.splitlines()) == 1, f"{code} {out} {err}")


def check_bad_files(tmp):
    for name, content, says in [("empty.json", "", "the file is empty"),
                                ("binary.tle", "\x00\x01\x02ELF", "not a text file")]:
        path = os.path.join(tmp, name)
        with open(path, "w") as f:
            f.write(content)
        code, out, err = sh(BIN, "elements", path)
        check(code == 1 and says in err and path in err, f"{name}: exit {code} {err}")
    path = os.path.join(tmp, "xp.kvn")
    with open(os.path.join(DATA, "sources.kvn")) as f:
        text = f.read().replace("MEAN_ELEMENT_THEORY = SGP4", "MEAN_ELEMENT_THEORY = SGP4-XP", 1)
    with open(path, "w") as f:
        f.write(text)
    code, out, err = sh(BIN, "elements", path, "--time", "2026-06-01")
    check(code == 1 and "2 element sets" in out, f"SGP4-XP: exit {code} {out}")
    check(f"{path}:8:0: object 1 (ISS (ZARYA) 25544): MEAN_ELEMENT_THEORY: found 'SGP4-XP'" in err, err)


def main():
    with tempfile.TemporaryDirectory() as tmp:
        compared = check_passes()
        check_listing()
        check_conversions(tmp)
        check_no_checksum(tmp)
        check_bad_files(tmp)
    print(f"{compared} OMM/TLE files give the TLE's passes; conversions, listings, --no-checksum checked")


if __name__ == "__main__":
    run_test(main)
