#!/usr/bin/env python3
"""A day of tracking in minutes (issue 21; not in CI): trakbox on the simulated station at an
accelerated clock, priority multi-tracking of five satellites with rotation limits and parking on,
the antenna polled through rotctld ~4 times a second and the radio through rigctld once a second,
for a number of SIMULATED hours. It reports:

  * RSS and open descriptors of trakbox over time (every 30 s of wall time);
  * antenna readings outside the limits (with --cross, those in the excluded azimuth sector are
    counted apart: the antenna crosses it between passes);
  * the pointing error against `trakbox schedule` while the satellite the tracker follows is above
    10 deg (median, 95th percentile, worst with its pass), split by why an error can be large:
    the satellite outside the limits (azimuth in the excluded sector, elevation above the maximum),
    in the other piece of a split travel, just after a switch to another satellite (slew lag), or
    none of these;
  * parking events (the antenna coming to rest at the parking position), radio tuning (the
    downlink frequency changes seen by rigctld), and the log's warnings and errors.

The satellite followed is the first of the tracking list above -2 deg (the priority rule of
tracker::choose_multi); its position comes from `trakbox schedule` every 2 s, interpolated. Each
reading's simulated time comes from the clock: trakbox's clock is start + rate * (wall - origin),
and the offset is measured with Satrak TIME? before polling starts.

  nice scripts/soak_rotator.py --hours 24 --rate 100 --start south     # about 15 minutes
  TRAKBOX_BIN=build/trakbox (default), --keep to keep the state directory and the sample CSV.

Standard library only. Exit status 1 when trakbox died, a reading was outside the limits, RSS grew
more than 10 % after the first wall minute, or descriptors grew.
"""
import argparse
import csv
import datetime
import io
import json
import math
import os
import re
import shutil
import socket
import statistics
import subprocess
import sys
import tempfile
import time
import zlib

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN = os.environ.get("TRAKBOX_BIN", os.path.join(SOURCE, "build", "trakbox"))
HOST = "127.0.0.1"
STEP_S = 2.0  # reference track step


def free_port():
    with socket.socket() as s:
        s.bind((HOST, 0))
        return s.getsockname()[1]


def parse_iso(text):
    return datetime.datetime.strptime(text, "%Y-%m-%dT%H:%M:%SZ").replace(tzinfo=datetime.timezone.utc)


# --------------------------------------------------------------------------------------------
# The state: fresh defaults from trakbox itself, then the soak's configuration, checksummed the
# way store::StateFile does (CRC-32 of the compact, key-sorted data).

def make_state(state_dir, args):
    p = subprocess.Popen([BIN, "--service", "--state", state_dir, "--data", os.path.join(SOURCE, "data"),
                          "--satrak-port", "0"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    path = os.path.join(state_dir, "trakbox-state.json")
    time.sleep(1.0)
    p.terminate()
    p.wait(20)
    with open(path) as f:
        doc = json.load(f)

    def dump(d):
        return json.dumps(d, sort_keys=True, separators=(",", ":"), ensure_ascii=False).encode()

    if "%08x" % zlib.crc32(dump(doc["data"])) != doc["checksum"].lower():
        raise SystemExit("soak: cannot reproduce the state checksum; the state format changed")
    d = doc["data"]
    d["station"]["rotor_start"] = args.start
    names = [s["elements"]["name"] for s in d["db"]["satellites"]]
    sel = []
    for n in args.sats.split(","):
        if n not in names:
            raise SystemExit(f"soak: {n} is not in the shipped database ({', '.join(names)})")
        sel.append(names.index(n))
    d["db"]["selected"] = sel
    d["db"]["marked"] = sel[0]
    d["db"]["multi_count"] = len(sel)
    d["priority_mode"] = True
    d["rotor_control"] = True
    r = d["rotator"]
    r["limits_enabled"] = True
    r["az_limit_min"], r["az_limit_max"] = args.az_limits
    r["el_limit_min"], r["el_limit_max"] = args.el_limits
    r["parking_enabled"] = True
    r["parking"] = list(args.park)
    if args.cross:
        r["cross_limit_sector"] = True
    doc["checksum"] = "%08x" % zlib.crc32(dump(d))
    with open(path, "w") as f:
        json.dump(doc, f, indent=2)
    os.remove(os.path.join(state_dir, "trakbox.log"))  # the soak's log starts with the soak
    return d, [names[i] for i in sel]


# --------------------------------------------------------------------------------------------
# Reference tracks.

class Track:
    def __init__(self, name, t0, rows):
        self.name = name
        self.t0 = t0
        self.az = [float(r["az_deg"]) for r in rows]
        self.el = [float(r["el_deg"]) for r in rows]

    def at(self, t):
        """(az, el) at simulated time t (a datetime), interpolated."""
        x = (t - self.t0).total_seconds() / STEP_S
        i = max(0, min(int(x), len(self.az) - 2))
        f = x - i
        a0, a1 = self.az[i], self.az[i + 1]
        da = (a1 - a0 + 180.0) % 360.0 - 180.0
        return (a0 + f * da) % 360.0, self.el[i] + f * (self.el[i + 1] - self.el[i])


def reference(name, station, t0, seconds):
    count = int(seconds / STEP_S) + 10
    out = subprocess.run([BIN, "schedule", os.path.join(SOURCE, "data", "amateur.tle"), "--sat", name, "--station",
                          station, "--start", t0.strftime("%Y-%m-%dT%H:%M:%SZ"), "--step", str(STEP_S), "--count",
                          str(count), "--csv"], capture_output=True, text=True, timeout=300, check=True).stdout
    return Track(name, t0, list(csv.DictReader(io.StringIO(out))))


def pointing_error(az1, el1, az2, el2):
    a1, e1, a2, e2 = map(math.radians, (az1, el1, az2, el2))
    c = math.sin(e1) * math.sin(e2) + math.cos(e1) * math.cos(e2) * math.cos(a1 - a2)
    return math.degrees(math.acos(max(-1.0, min(1.0, c))))


# --------------------------------------------------------------------------------------------
# Endpoints.

class LineClient:
    def __init__(self, port):
        self.port = port
        self.sock = None
        self.buf = b""

    def ask(self, line, lines):
        if self.sock is None:
            self.sock = socket.create_connection((HOST, self.port), timeout=5)
            self.sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            self.buf = b""
        self.sock.sendall(line.encode() + b"\n")
        out = []
        while len(out) < lines:
            while b"\n" not in self.buf:
                chunk = self.sock.recv(4096)
                if not chunk:
                    self.sock = None
                    raise OSError("connection closed")
                self.buf += chunk
            one, self.buf = self.buf.split(b"\n", 1)
            out.append(one.decode().strip())
            if out[-1].startswith("RPRT"):
                break
        return out


def satrak_time(port):
    def frame(payload):
        x = 0
        for b in payload.encode():
            x ^= b
        return ("$%s*%02X\r\n" % (payload, x)).encode()
    with socket.create_connection((HOST, port), timeout=5) as s:
        s.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        w0 = time.time()
        s.sendall(frame("TIME?"))
        buf = b""
        while b"\n" not in buf:
            buf += s.recv(4096)
        w1 = time.time()
    f = re.match(r"\$TIME\?,(.*)\*", buf.decode()).group(1).split(",")
    h, mi, se, d, mo, y, ms = map(int, f)
    sim = datetime.datetime(y, mo, d, h, mi, se, ms * 1000, tzinfo=datetime.timezone.utc)
    return sim, 0.5 * (w0 + w1), w1 - w0


def proc_sample(pid):
    with open(f"/proc/{pid}/status") as f:
        rss = int(re.search(r"VmRSS:\s+(\d+)", f.read()).group(1))
    return rss, len(os.listdir(f"/proc/{pid}/fd"))


# --------------------------------------------------------------------------------------------

def in_sector(az, lo, hi):
    """az inside the clockwise sector lo -> hi (compass degrees)."""
    if hi - lo >= 360.0:
        return True
    return (az - lo) % 360.0 <= (hi - lo) % 360.0


def pieces_of(start, lo, hi):
    """The reachable pieces of travel (compass sectors lo -> hi) for a rotor start and azimuth
    limits: two when the stop lies inside the allowed sector."""
    stop = 0.0 if start == "north" else 180.0
    if hi - lo >= 360.0 or not in_sector(stop, lo, hi) or stop in (lo % 360.0, hi % 360.0):
        return [(lo, hi)]
    return [(lo, stop), (stop, hi)]


def piece_index(pieces, az):
    for i, (lo, hi) in enumerate(pieces):
        if in_sector(az, lo, hi):
            return i
    return None


def pct(values, q):
    if not values:
        return float("nan")
    v = sorted(values)
    return v[min(len(v) - 1, int(round(q / 100.0 * (len(v) - 1))))]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--hours", type=float, default=24.0, help="simulated hours (default 24)")
    ap.add_argument("--rate", type=float, default=100.0, help="clock rate (default 100, at most 200)")
    ap.add_argument("--start", choices=("north", "south"), default="north", help="rotor start")
    ap.add_argument("--clock", default="2026-05-21T00:00:00Z", help="simulated start, UTC")
    ap.add_argument("--sats", default="ISS,SO-50,AO-91,FO-29,PO-101", help="the tracking list, in priority order")
    ap.add_argument("--az-limits", type=float, nargs=2, default=(10.0, 350.0))
    ap.add_argument("--el-limits", type=float, nargs=2, default=(0.0, 80.0))
    ap.add_argument("--park", type=float, nargs=2, default=(200.0, 4.9))
    ap.add_argument("--cross", action="store_true", help="limits are pointing limits: cross between passes")
    ap.add_argument("--keep", action="store_true", help="keep the state directory and samples.csv")
    args = ap.parse_args()

    work = tempfile.mkdtemp(prefix="trakbox-soak-rotator-")
    state = os.path.join(work, "state")
    os.makedirs(os.path.join(state, "tle"), mode=0o700)
    os.chmod(state, 0o700)
    model, sats = make_state(state, args)
    st = model["station"]
    station = f"{st['lat_deg']},{st['lon_deg']},{st['height_m']}"
    t0 = parse_iso(args.clock)
    sim_seconds = args.hours * 3600.0
    print(f"soak_rotator: {args.hours:g} simulated h at {args.rate:g}x, rotor start {args.start}, limits az "
          f"{args.az_limits[0]:g}..{args.az_limits[1]:g} el {args.el_limits[0]:g}..{args.el_limits[1]:g}, park "
          f"{args.park[0]:g}/{args.park[1]:g}{', crossing between passes' if args.cross else ''}; priority "
          f"tracking of {', '.join(sats)}; station {station}; work {work}", flush=True)
    tracks = [reference(n, station, t0, sim_seconds + 600) for n in sats]

    ports = {k: free_port() for k in ("satrak", "rotctld", "rigctld")}
    cmd = [BIN, "--service", "--state", state, "--data", os.path.join(SOURCE, "data"), "--clock", args.clock,
           "--clock-rate", str(args.rate), "--satrak-port", str(ports["satrak"]),
           "--rotctld-port", str(ports["rotctld"]), "--rigctld-port", str(ports["rigctld"])]
    err = open(os.path.join(work, "stderr.log"), "w")
    proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=err)
    failed = []
    try:
        deadline = time.time() + 15
        offsets = []
        while len(offsets) < 5:
            try:
                sim, wall, rtt = satrak_time(ports["satrak"])
                if rtt < 0.01:
                    offsets.append(sim.timestamp() - args.rate * wall)
            except OSError:
                if time.time() > deadline:
                    raise SystemExit("soak: the Satrak server never answered")
                time.sleep(0.2)
        offset = statistics.median(offsets)

        def sim_at(wall):
            return datetime.datetime.fromtimestamp(offset + args.rate * wall, datetime.timezone.utc)

        rot, rig = LineClient(ports["rotctld"]), LineClient(ports["rigctld"])
        samples = []      # (sim, az, el)
        radio = []        # (sim, hz)
        mem = []          # (wall s, rss kB, fds)
        wall_start = time.time()
        end_sim = t0 + datetime.timedelta(seconds=sim_seconds)
        next_rig, next_mem, next_report = 0.0, 0.0, 0.0
        poll_failures = 0
        while True:
            now = time.time()
            if proc.poll() is not None:
                failed.append(f"trakbox exited with status {proc.returncode}")
                break
            if sim_at(now) >= end_sim:
                break
            try:
                w0 = time.time()
                r = rot.ask("p", 2)
                w1 = time.time()
                if len(r) == 2 and not r[0].startswith("RPRT"):
                    samples.append((sim_at(0.5 * (w0 + w1)), float(r[0]), float(r[1])))
                if now >= next_rig:
                    next_rig = now + 1.0
                    w0 = time.time()
                    f = rig.ask("f", 1)
                    w1 = time.time()
                    if f and not f[0].startswith("RPRT"):
                        radio.append((sim_at(0.5 * (w0 + w1)), int(float(f[0]))))
            except OSError:
                poll_failures += 1
            if now >= next_mem:
                next_mem = now + 30.0
                mem.append((now - wall_start,) + proc_sample(proc.pid))
            if now >= next_report:
                next_report = now + 60.0
                done = (sim_at(now) - t0).total_seconds() / 3600.0
                print(f"  {now - wall_start:6.0f} s wall, {done:5.1f} simulated h, {len(samples)} antenna readings, "
                      f"RSS {mem[-1][1] / 1024:.1f} MB, {mem[-1][2]} fds", flush=True)
            time.sleep(max(0.0, 0.25 - (time.time() - now)))
        wall_total = time.time() - wall_start
    finally:
        if proc.poll() is None:
            proc.terminate()
            try:
                proc.wait(30)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
        err.close()

    # ---- analysis
    lo, hi = args.az_limits
    elo, ehi = args.el_limits
    pieces = pieces_of(args.start, lo, hi)
    outside = [(t, a, e) for t, a, e in samples
               if not (in_sector(a, lo - 0.5, hi + 0.5) and elo - 0.2 <= e <= ehi + 0.2)]
    # With --cross the limits are pointing limits only: the antenna passes through the excluded
    # azimuth sector when it moves to the other piece between passes (elevation is still a limit).
    transit = []
    if args.cross and len(pieces) > 1:
        transit = [x for x in outside if elo - 0.2 <= x[2] <= ehi + 0.2]
        outside = [x for x in outside if x not in transit]
    cats = {"inside limits, same piece": [], "satellite outside the limits": [], "other piece of a split travel": [],
            "within 60 s after a switch of satellite": []}
    passes = {}  # (sat, pass start) -> [worst error, time, sat az/el, antenna az/el, samples, max el]
    prev_followed, switch_at, pass_start = None, None, {}
    ant_piece = None  # the antenna's piece: at the rotor stop (a piece boundary) the one it was in

    rows = []
    beyond = []  # inside the limits and the piece, yet beyond the dead band plus the slew lag
    stop = 0.0 if args.start == "north" else 180.0
    for t, a, e in samples:
        if len(pieces) > 1 and min(abs(a - stop), 360.0 - abs(a - stop)) > 0.5:
            ant_piece = piece_index(pieces, a)
        followed = None
        for k, tr in enumerate(tracks):
            saz, sel = tr.at(t)
            if sel >= -2.0:
                followed = (k, saz, sel)
                break
        if followed is None:
            prev_followed = None
            continue
        k, saz, sel = followed
        if prev_followed is not None and prev_followed != k:
            switch_at = t
        if prev_followed != k:
            pass_start[k] = t
        prev_followed = k
        if sel < 10.0:
            continue
        err_deg = pointing_error(a, e, saz, sel)
        # What the dead band and the slew lag allow: the factory dead band plus the ADC's flooring
        # (4 counts of azimuth at 0.352 deg, 2 of elevation at 0.176 deg), and the satellite's
        # motion in 2.2 s: the tracker re-targets every second of clock time while the antenna is on
        # target, rotctld's `p` reports the position of the controller's last tick (up to 1 s old),
        # and 0.2 s for the motor's spin-up and the reading's time.
        saz2, sel2 = tracks[k].at(t + datetime.timedelta(seconds=1))
        rate = pointing_error(saz, sel, saz2, sel2)
        allowed = math.hypot(4 * 360.0 / 1023 * math.cos(math.radians(sel)), 2 * 90.0 / 511) + 2.2 * rate
        if not (in_sector(saz, lo, hi) and sel <= ehi):
            cat = "satellite outside the limits"
        elif len(pieces) > 1 and piece_index(pieces, saz) != ant_piece:
            cat = "other piece of a split travel"
        elif switch_at is not None and (t - switch_at).total_seconds() <= 60.0:
            cat = "within 60 s after a switch of satellite"
        else:
            cat = "inside limits, same piece"
        cats[cat].append(err_deg)
        if cat == "inside limits, same piece" and err_deg > allowed:
            beyond.append((t, tracks[k].name, saz, sel, a, e, err_deg, allowed))
        key = (tracks[k].name, pass_start[k])
        p = passes.setdefault(key, [0.0, None, None, None, 0, 0.0, cat])
        p[4] += 1
        p[5] = max(p[5], sel)
        if err_deg > p[0]:
            p[0], p[1], p[2], p[3], p[6] = err_deg, t, (saz, sel), (a, e), cat
        rows.append((t.isoformat(), tracks[k].name, f"{saz:.2f}", f"{sel:.2f}", f"{a:.2f}", f"{e:.2f}",
                     f"{err_deg:.3f}", f"{allowed:.3f}", cat))

    # parking: the antenna at rest within 1 deg of the parking position, counted once per arrival
    parks, at_park = 0, False
    for t, a, e in samples:
        here = pointing_error(a, e, args.park[0], args.park[1]) <= 1.0
        if here and not at_park:
            parks += 1
        at_park = here
    tunes = sum(1 for i in range(1, len(radio)) if radio[i][1] != radio[i - 1][1])
    with open(os.path.join(state, "trakbox.log")) as f:
        log = f.read().splitlines()
    warnings = [ln for ln in log if re.search(r"\[(warning|error|critical)\]", ln)]

    print(f"\nsoak_rotator: {wall_total:.0f} s of wall time, {len(samples)} antenna readings "
          f"({len(samples) / max(wall_total, 1):.1f}/s), {len(radio)} radio readings, {poll_failures} failed polls")
    if mem:
        print(f"  RSS {mem[0][1] / 1024:.1f} MB at start, {min(m[1] for m in mem) / 1024:.1f}..."
              f"{max(m[1] for m in mem) / 1024:.1f} MB, {mem[-1][1] / 1024:.1f} MB at the end; descriptors "
              f"{mem[0][2]} at start, {min(m[2] for m in mem)}..{max(m[2] for m in mem)}, {mem[-1][2]} at the end")
        print("  over time (wall s: RSS MB / fds): " +
              ", ".join(f"{m[0]:.0f}: {m[1] / 1024:.1f}/{m[2]}" for m in mem[::max(1, len(mem) // 10)]))
        later = [m for m in mem if m[0] >= 60.0]
        if later and max(m[1] for m in later) > 1.10 * later[0][1]:
            failed.append("RSS grew more than 10 % after the first minute")
        if mem[-1][2] > mem[0][2] + 2:
            failed.append("descriptors grew")
    print(f"  antenna readings outside the limits: {len(outside)} of {len(samples)}"
          + (f" (first {outside[0]})" if outside else ""))
    if outside:
        failed.append(f"{len(outside)} readings outside the limits")
    if args.cross and len(pieces) > 1:
        print(f"  readings in the excluded azimuth sector while crossing between pieces: {len(transit)}"
              + "".join(f"\n    {t:%H:%M:%S} {a:.1f}/{e:.1f}" for t, a, e in transit[:10]))
    print(f"  pieces of travel: {', '.join(f'{a:g}-{b:g}' for a, b in pieces)}")
    print("  pointing error while the followed satellite is above 10 deg (deg):")
    allv = [v for vs in cats.values() for v in vs]
    for name, vs in [("all samples", allv)] + list(cats.items()):
        if vs:
            print(f"    {name:42s} n={len(vs):6d}  median {statistics.median(vs):6.2f}  95th {pct(vs, 95):6.2f}  "
                  f"worst {max(vs):6.2f}  >10 deg {100.0 * sum(v > 10 for v in vs) / len(vs):5.1f} %")
    print(f"  passes followed above 10 deg: {len(passes)}; the worst per pass, largest first:")
    for (name, start), p in sorted(passes.items(), key=lambda kv: -kv[1][0])[:12]:
        print(f"    {name:7s} pass from {start:%H:%M:%S} (max el {p[5]:4.1f}, {p[4]} samples): worst {p[0]:6.2f} at "
              f"{p[1]:%H:%M:%S} satellite {p[2][0]:.1f}/{p[2][1]:.1f} antenna {p[3][0]:.1f}/{p[3][1]:.1f} ({p[6]})")
    n_inside = len(cats["inside limits, same piece"])
    print(f"  inside the limits and the piece: {n_inside - len(beyond)} of {n_inside} samples within the dead band "
          f"plus the slew lag (dead band and ADC flooring, 4 az / 2 el counts, + 2.2 s of the satellite's motion)")
    for b in beyond[:10]:
        print(f"    beyond: {b[0]:%H:%M:%S} {b[1]} satellite {b[2]:.1f}/{b[3]:.1f} antenna {b[4]:.1f}/{b[5]:.1f}: "
              f"{b[6]:.2f} > {b[7]:.2f} deg")
    inside = [p for p in passes.values() if p[6] == "inside limits, same piece"]
    print(f"  passes whose worst sample is inside the limits and the same piece: {len(inside)}, their worst "
          f"{max((p[0] for p in inside), default=0):.2f} deg")
    print(f"  parking events: {parks}; radio: {tunes} downlink changes seen, "
          f"{len(set(h for _, h in radio))} distinct frequencies")
    print(f"  log: {len(log)} lines, {len(warnings)} warnings/errors" +
          ("".join(f"\n    {w}" for w in warnings[:10])))
    if args.keep:
        with open(os.path.join(work, "samples.csv"), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["utc", "sat", "sat_az", "sat_el", "ant_az", "ant_el", "error_deg", "allowed_deg", "category"])
            w.writerows(rows)
        print(f"  kept {work} (state/, samples.csv)")
    else:
        shutil.rmtree(work, ignore_errors=True)
    for f in failed:
        print(f"soak_rotator: FAILED: {f}")
    print("soak_rotator: " + ("FAILED" if failed else "passed"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
