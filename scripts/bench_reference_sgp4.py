#!/usr/bin/python3
"""Same-machine baseline for bench/bench_sgp4.cpp (BM_Sgp4Gpredict979x1440).

Runs python-sgp4's SatrecArray over the element sets of gpredict's satellites.dat at 1440
one-minute steps from 2018-01-21 00:00 UTC (one call for all sets and times, the workload of the
C++ benchmark) and prints nanoseconds per propagation.

With python-sgp4's compiled extension (sgp4.api.accelerated is True, as in the PyPI wheels) that is
Vallado's C++ in array mode. Debian's python3-sgp4 ships without the extension: the script then
times the pure-Python fallback instead, says so, and by default runs only the first 60 minutes
(pass --minutes 1440 for the full day; it takes a few minutes).

Usage: /usr/bin/python3 scripts/bench_reference_sgp4.py [--satdata PATH] [--minutes N] [--repeat R]
"""
import argparse
import sys
import time

SATDATA = '/usr/share/gpredict/data/satdata/satellites.dat'
JD_START = 2458139.5  # 2018-01-21 00:00 UTC


def read_gpredict_tles(path):
    """(line1, line2) pairs from gpredict's INI-like satellite file (TLE1=, TLE2= keys)."""
    pairs, line1 = [], None
    with open(path, encoding='utf-8', errors='replace') as f:
        for raw in f:
            key, _, value = raw.rstrip('\r\n').partition('=')
            if key == 'TLE1':
                line1 = value
            elif key == 'TLE2' and line1 is not None:
                pairs.append((line1, value))
                line1 = None
    return pairs


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--satdata', default=SATDATA)
    parser.add_argument('--minutes', type=int, default=None,
                        help='one-minute steps per set (default 1440; 60 for the pure-Python fallback)')
    parser.add_argument('--repeat', type=int, default=None,
                        help='runs to take the best of (default 5; 1 for the pure-Python fallback)')
    args = parser.parse_args()

    try:
        import numpy as np
        import sgp4
        from sgp4.api import Satrec, SatrecArray, WGS72, accelerated
    except ImportError as e:
        sys.exit('needs python3-sgp4 and python3-numpy (Debian), run with /usr/bin/python3: %s' % e)

    minutes = args.minutes or (1440 if accelerated else 60)
    repeat = args.repeat or (5 if accelerated else 1)
    pairs = read_gpredict_tles(args.satdata)
    sats = [Satrec.twoline2rv(l1, l2, WGS72) for l1, l2 in pairs]
    array = SatrecArray(sats)
    jd = np.full(minutes, JD_START)
    fr = np.arange(minutes) / 1440.0

    best = float('inf')
    for _ in range(repeat):
        start = time.perf_counter()
        e, r, v = array.sgp4(jd, fr)
        best = min(best, time.perf_counter() - start)
    n = len(sats) * minutes
    kind = 'C++ (vallado_cpp, array mode)' if accelerated else 'pure-Python fallback (no C++ extension installed)'
    try:
        from importlib.metadata import version as package_version
        version = package_version('sgp4')
    except Exception:  # noqa: BLE001 - the version is only informative
        version = getattr(sgp4, '__version__', '?')
    print('python-sgp4 %s, %s: %d sets x %d times, best of %d: %.3f s, %.1f ns per propagation, %d failed'
          % (version, kind, len(sats), minutes, repeat, best, best / n * 1e9, int(np.count_nonzero(e))))


if __name__ == '__main__':
    main()
