"""`passes --plot` names its files (issue 39): one pass is drawn to exactly the file named; several are
drawn one file each, every name listed on standard output after the table (and the named file
itself not written, which is said); a name that is not .png or .svg is refused before anything is
computed or printed."""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, SOURCE, check, in_temp_dir, run_test, sh  # noqa: E402

TLE = os.path.join(SOURCE, "data", "amateur.tle")
COMMON = ["--sat", "ISS", "--station", "27.391,128.657,50", "--start", "2026-05-21T13:30:00Z"]


def walk(tmp):
    one = os.path.join(tmp, "one.png")
    code, out, err = sh(BIN, "passes", TLE, *COMMON, "--hours", "1", "--min-el", "10", "--plot", one)
    check(code == 0, f"one pass: {code} {err}")
    check(os.listdir(tmp) == ["one.png"], f"exactly the file named: {os.listdir(tmp)}")
    check(f"plot: {one}  ISS 2026-05-21T" in out, f"and its name on stdout: {out}")

    several = os.path.join(tmp, "day.svg")
    code, out, err = sh(BIN, "passes", TLE, *COMMON, "--hours", "24", "--plot", several)
    check(code == 0, f"several passes: {code} {err}")
    made = sorted(f for f in os.listdir(tmp) if f.startswith("day"))
    check(len(made) >= 3 and "day.svg" not in made, f"one file each, numbered: {made}")
    check(f"plot: {len(made)} passes, one file each ({several} is not written):" in out, f"said: {out}")
    for f in made:
        check(f"plot: {os.path.join(tmp, f)}  ISS " in out, f"{f} is listed on stdout: {out}")
        check(f.startswith("day-") and f.endswith(".svg"), f"named FILE-N.svg: {f}")

    # With a horizon mask (issue 57): the SVG shades it and says so; LOS is marked on it.
    roof = os.path.join(tmp, "roof.hrz")
    with open(roof, "w") as f:
        f.write("0 0\n190 25\n230 25\n240 0\n360 0\n")
    masked = os.path.join(tmp, "masked.svg")
    code, out, err = sh(BIN, "passes", TLE, *COMMON, "--hours", "1", "--min-el", "10", "--horizon-mask", roof,
                        "--plot", masked)
    check(code == 0, f"a pass with the mask: {code} {err}")
    svg = open(masked).read()
    check("brown: horizon mask" in svg, "the legend names the mask")
    check("fill-rule:evenodd" in svg or 'fill-rule="evenodd"' in svg, "the mask is drawn as a ring from the horizon up")
    os.remove(roof)
    os.remove(masked)

    code, out, err = sh(BIN, "passes", TLE, *COMMON, "--hours", "24", "--plot", os.path.join(tmp, "p.jpg"))
    check(code == 2, f"a .jpg is refused as a usage error: {code}")
    check(out == "", f"before any table is printed: {out!r}")
    check("--plot" in err and "expected a name ending .png or .svg" in err, f"saying why: {err}")
    check(not os.path.exists(os.path.join(tmp, "p.jpg")), "and nothing is written")


def main():
    in_temp_dir("trakbox-plot-files-", walk)


if __name__ == "__main__":
    run_test(main)
