#!/usr/bin/env python3
"""Writes the NMEA 0183 logs of tests/integration/gps_gpsd.py (run it here to regenerate them).

Each second of a log is one receiver cycle: GGA (time, position, fix quality, satellites, HDOP,
altitude above mean sea level, geoid separation), GSA (fix mode 1/2/3, satellites used, DOPs) and
RMC (time, status A/V, position, speed, course, date), in that order, each with its checksum: the XOR
of every byte between '$' and '*', two upper-case hex digits. Positions are ddmm.mmmm / dddmm.mmmm.
gpsd gives the height above the ellipsoid as altitude + separation (here 83.0 + 37.0 = 120.0 m).
"""
import datetime
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
SATS = ["04", "05", "09", "12", "17", "24"]


def sentence(body):
    c = 0
    for ch in body.encode("ascii"):
        c ^= ch
    return "$%s*%02X" % (body, c)


def angle(value, deg_digits, pos, neg):
    hemi = pos if value >= 0 else neg
    v = abs(value)
    d = int(v)
    m = (v - d) * 60.0
    return ("%0*d%07.4f" % (deg_digits, d, m), hemi)


def cycle(t, lat, lon, mode=3, alt=83.0, sep=37.0, speed_kn=0.0, course=0.0):
    """One second of a receiver: mode 1 no fix, 2 a 2D fix (no altitude), 3 a 3D fix."""
    hms = t.strftime("%H%M%S") + ".00"
    dmy = t.strftime("%d%m%y")
    la, ns = angle(lat, 2, "N", "S")
    lo, ew = angle(lon, 3, "E", "W")
    if mode == 1:
        gga = "GPGGA,%s,,,,,0,00,99.9,,M,,M,," % hms
        gsa = "GPGSA,A,1,,,,,,,,,,,,,99.9,99.9,99.9"
        rmc = "GPRMC,%s,V,,,,,,,%s,,,N" % (hms, dmy)
    else:
        altitude = ("%.1f" % alt) if mode == 3 else ""
        gga = "GPGGA,%s,%s,%s,%s,%s,1,%02d,1.2,%s,M,%.1f,M,," % (hms, la, ns, lo, ew, len(SATS), altitude, sep)
        used = SATS + [""] * (12 - len(SATS))
        gsa = "GPGSA,A,%d,%s,2.1,1.2,1.7" % (mode, ",".join(used))
        rmc = "GPRMC,%s,A,%s,%s,%s,%s,%.1f,%.1f,%s,,,A" % (hms, la, ns, lo, ew, speed_kn, course, dmy)
    return [sentence(gga), sentence(gsa), sentence(rmc)]


def write(name, comment, cycles):
    # gpsd identifies the receiver from the first sentences and learns which one ends a cycle: the
    # first cycles of a log are a lead-in (the same as its first), as a receiver powered on earlier.
    lead = []
    for k in range(LEAD, 0, -1):
        first = [s[1:s.index("*")] for s in cycles[0]]
        t0 = first[0].split(",")[1][:6]
        t = (datetime.datetime.strptime(t0, "%H%M%S") - datetime.timedelta(seconds=k)).strftime("%H%M%S")
        lead.append([sentence(s.replace(t0 + ".00", t + ".00", 1)) for s in first])
    # And a tail the tests never feed: gpsfake -1 ends (and takes its gpsd down) after the last
    # sentence, so the last cycle a test feeds is never the log's last.
    last = [s[1:s.index("*")] for s in cycles[-1]]
    t1 = last[0].split(",")[1][:6]
    t = (datetime.datetime.strptime(t1, "%H%M%S") + datetime.timedelta(seconds=1)).strftime("%H%M%S")
    tail = [sentence(s.replace(t1 + ".00", t + ".00", 1)) for s in last]
    cycles = lead + cycles + [tail]
    with open(os.path.join(HERE, name), "w", newline="") as f:
        f.write("# %s\n# written by make_logs.py from the NMEA 0183 GGA, GSA and RMC formats\n" % comment)
        for c in cycles:
            for s in c:
                f.write(s + "\r\n")


LEAD = 8
START = datetime.datetime(2017, 10, 19, 6, 0, 0)  # the Satrak document's GPS_DATA? example time
LAT, LON = 41.01, 29.17                            # and position


def at(i):
    return START + datetime.timedelta(seconds=i)


def offset(lat, lon, north_m, east_m):
    r = 6371008.8
    return (lat + math.degrees(north_m / r), lon + math.degrees(east_m / (r * math.cos(math.radians(lat)))))


def main():
    # A fixed station: the receiver wanders by a metre or two (jitter under any threshold).
    jitter = [(0.0, 0.0), (1.2, -0.8), (-0.9, 1.1), (0.4, 0.6), (-1.5, -0.3), (0.8, -1.4)]
    fixed = []
    for i in range(12):
        n, e = jitter[i % len(jitter)]
        fixed.append(cycle(at(i), *offset(LAT, LON, n, e)))
    write("fixed.nmea", "a fixed station at 41.01N 29.17E, 120 m above the ellipsoid, jitter within 2 m", fixed)

    # A rover driving 10 km due east at 250 m per report (900 km/h would be a jump: this is the
    # log played fast; reachability is judged on the log's own times: 250 m in 1 s is under 300 m/s).
    rover = [cycle(at(i), LAT, LON, speed_kn=486.0, course=90.0) for i in range(3)]
    for k in range(1, 41):
        rover.append(cycle(at(2 + k), *offset(LAT, LON, 0.0, 250.0 * k), speed_kn=486.0, course=90.0))
    for i in range(3):
        rover.append(cycle(at(43 + i), *offset(LAT, LON, 0.0, 10000.0), speed_kn=0.0, course=90.0))
    write("rover.nmea", "a rover from 41.01N 29.17E driving 10 km east, 250 m a report, then stopping", rover)

    # A fix, lost for 5 s, regained 2 km north (reachable: 2 km in 8 s).
    lost = [cycle(at(i), LAT, LON) for i in range(5)]
    lost += [cycle(at(5 + i), LAT, LON, mode=1) for i in range(5)]
    lost += [cycle(at(10 + i), *offset(LAT, LON, 2000.0, 0.0)) for i in range(5)]
    write("fix_lost.nmea", "a 3D fix, no fix for 5 s, the fix again 2 km north", lost)

    # A 2D fix: no altitude (the station keeps its stored height).
    write("fix_2d.nmea", "a 2D fix at 41.01N 29.17E", [cycle(at(i), LAT, LON, mode=2) for i in range(6)])

    # One report 100 km away between good ones, then a latitude of 95 degrees (nonsense), then good.
    bad = [cycle(at(i), LAT, LON) for i in range(4)]
    bad.append(cycle(at(4), *offset(LAT, LON, 100000.0, 0.0)))
    bad += [cycle(at(5 + i), LAT, LON) for i in range(3)]
    nonsense = cycle(at(8), LAT, LON)
    nonsense = [sentence(s[1:s.index("*")].replace("4100.6000,N", "9500.0000,N")) for s in nonsense]
    bad.append(nonsense)
    bad.append([sentence(s[1:s.index("*")].replace("4100.6000,N", "9500.0000,N")) for s in cycle(at(9), LAT, LON)])
    bad += [cycle(at(10 + i), LAT, LON) for i in range(4)]
    write("jump_nonsense.nmea", "a fixed station, one report 100 km north, then two of latitude 95N", bad)

    # No fix ever: a receiver indoors.
    write("no_fix.nmea", "a receiver without a fix", [cycle(at(i), LAT, LON, mode=1) for i in range(6)])


if __name__ == "__main__":
    main()
