"""`trakbox passes --ics FILE` and GET /api/v1/passes.ics (issue 47) read back by a real iCalendar
reader (python3-icalendar): one event a pass with its UID, DTSTAMP, DTSTART = AOS and DTEND = LOS
in UTC, the same passes `passes --json` lists; `passes` lists only passes that rise (no maximum
under 0 deg); `passes --with JN58td` gives only the times both stations see the satellite (checked
with Skyfield, independent of trakbox, at both ends of each shared time)."""
import datetime
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import BIN, SOURCE, check, run_test, sh, skip  # noqa: E402
from _web import WebStation  # noqa: E402

TLE = os.path.join(SOURCE, "data", "amateur.tle")
HOME = "JO40ba"                 # Frankfurt
PARTNER = "JN58td"              # Munich, 300 km away
START = "2026-05-21T00:00:00Z"


def iso(s):
    return datetime.datetime.fromisoformat(s.replace("Z", "+00:00"))


def centre(loc):
    """A 6-character Maidenhead locator's centre (latitude, longitude)."""
    a = "ABCDEFGHIJKLMNOPQRSTUVWX"
    lon = -180 + a.index(loc[0].upper()) * 20 + int(loc[2]) * 2 + a.index(loc[4].upper()) * 5 / 60 + 2.5 / 60
    lat = -90 + a.index(loc[1].upper()) * 10 + int(loc[3]) + a.index(loc[5].upper()) * 2.5 / 60 + 1.25 / 60
    return lat, lon


def calendar_events(data):
    try:
        import icalendar
    except ImportError:
        skip("python3-icalendar is not installed")
    cal = icalendar.Calendar.from_ical(data)
    return [e for e in cal.walk("VEVENT")]


def cli():
    base = [BIN, "passes", TLE, "--sat", "ISS", "--sat", "SO-50", "--station", HOME, "--start", START, "--hours", "24"]
    code, out, err = sh(*base, "--json")
    check(code == 0, f"passes --json: {err}")
    passes = json.loads(out)
    check(passes and all(p["max_el_deg"] > 0 for p in passes), f"only passes that rise: {[p['max_el_deg'] for p in passes]}")
    ics = os.path.join(tempfile.mkdtemp(prefix="trakbox-ics-"), "passes.ics")
    code, out, err = sh(*base, "--ics", ics)
    check(code == 0 and f"ics: {ics}  {len(passes)} passes" in out, f"passes --ics: {out} {err}")
    raw = open(ics, "rb").read()
    check(b"\r\n" in raw and b"\n" not in raw.replace(b"\r\n", b""), "CRLF line ends only")
    check(all(len(line) <= 75 for line in raw.split(b"\r\n")), "lines folded at 75 octets")
    events = calendar_events(raw)
    check(len(events) == len(passes), f"{len(events)} events for {len(passes)} passes")
    uids = set()
    for e, p in zip(sorted(events, key=lambda e: e.decoded("DTSTART")), passes):
        # To the second (iCalendar has no fractions).
        check(abs((e.decoded("DTSTART") - iso(p["aos_utc"])).total_seconds()) <= 1, f"DTSTART {e.decoded('DTSTART')} vs {p}")
        check(abs((e.decoded("DTEND") - iso(p["los_utc"])).total_seconds()) <= 1, f"DTEND {e.decoded('DTEND')} vs {p}")
        check(str(e["SUMMARY"]).startswith(p["sat"] + " pass, max "), f"SUMMARY {e['SUMMARY']}")
        check("DTSTAMP" in e, "DTSTAMP")
        uids.add(str(e["UID"]))
    check(len(uids) == len(events), "a UID each")
    print(f"passes --ics: {len(events)} events read back by icalendar")


def both_see():
    from skyfield.api import EarthSatellite, load, wgs84
    lines = open(TLE).read().splitlines()
    i = lines.index("ISS")
    sat = EarthSatellite(lines[i + 1], lines[i + 2], "ISS")
    ts = load.timescale()
    where = {loc: centre(loc) for loc in (HOME, PARTNER)}
    code, out, err = sh(BIN, "passes", TLE, "--sat", "ISS", "--station", HOME, "--with", PARTNER, "--start", START,
                        "--hours", "24", "--json")
    check(code == 0, f"passes --with: {err}")
    shared = json.loads(out)
    code, out, _ = sh(BIN, "passes", TLE, "--sat", "ISS", "--station", HOME, "--start", START, "--hours", "24", "--json")
    alone = json.loads(out)
    check(shared and len(shared) <= len(alone), f"{len(shared)} shared of {len(alone)}")
    # 300 km apart, the stations' horizons differ: the shared times are shorter than Frankfurt's own.
    own = sum((iso(p["los_utc"]) - iso(p["aos_utc"])).total_seconds() for p in alone)
    both = sum((iso(p["los_utc"]) - iso(p["aos_utc"])).total_seconds() for p in shared)
    check(both < own, f"shared {both:.0f} s of Frankfurt's {own:.0f} s in view")
    for p in shared:
        for t, inward in ((iso(p["aos_utc"]), 1), (iso(p["los_utc"]), -1)):
            t = t + datetime.timedelta(seconds=inward)
            for loc, (lat, lon) in where.items():
                alt, _, _ = (sat - wgs84.latlon(lat, lon)).at(ts.from_datetime(t)).altaz()
                check(alt.degrees > -2.0 - 0.05, f"{loc} sees ISS at {t}: {alt.degrees:.2f} deg")
        # The partner's maximum over the shared time (issue 60: --with named neither), by Skyfield each second.
        lat, lon = where[PARTNER]
        a, b = iso(p["aos_utc"]), iso(p["los_utc"])
        n = int((b - a).total_seconds())
        times = ts.from_datetimes([a + datetime.timedelta(seconds=k) for k in range(n + 1)])
        there = max((sat - wgs84.latlon(lat, lon)).at(times).altaz()[0].degrees)
        check(abs(p["there_max_el_deg"] - there) < 0.05, f"the partner's maximum {p['there_max_el_deg']} vs Skyfield {there:.3f}")
    code, out, err = sh(BIN, "passes", TLE, "--sat", "ISS", "--station", HOME, "--with", PARTNER, "--start", START,
                        "--hours", "24")
    check(code == 0 and "with " in out and f"({PARTNER[:4]}" in out and "THERE" in out, f"the table names the partner:\n{out}")
    print(f"passes --with {PARTNER}: {len(shared)} of {len(alone)} ISS passes shared ({both:.0f} of {own:.0f} s), "
          "both ends and the partner's maximum checked with Skyfield")


def web():
    w = WebStation(clock="2026-05-21T12:00:00Z")
    try:
        status, headers, body = w.request("GET", "/api/v1/passes.ics?sat=ISS,SO-50&min_el=10&hours=24")
        check(status == 200 and headers["content-type"].startswith("text/calendar"), f"{status} {headers}")
        events = calendar_events(body)
        status, j = w.get_json("/api/v1/passes?sat=ISS,SO-50&min_el=10&hours=24")
        check(len(events) == len(j["passes"]) > 0, f"{len(events)} events, {len(j['passes'])} passes")
        print(f"passes.ics: {len(events)} events")
    finally:
        w.stop()


def main():
    cli()
    both_see()
    web()


run_test(main)
