#!/usr/bin/python3
"""Prints the Sun directions written into tests/unit/orbit/test_observe.cpp ("Sun against ERFA").

ERFA (Debian python3-pyerfa, the IAU SOFA library) gives the Earth's heliocentric position
(epv00, VSOP87-based, about 5e-8 AU); minus that is the geocentric Sun, in the ICRS (GCRS-aligned).
pnm06a rotates it to the true equator and equinox of date, which differs from TEME only by the
equation of the equinoxes (about 1 arcsecond) -- far below the 0.01 deg of the low-precision model.
UTC stands in for TT (69 s: 0.003 deg of solar motion); the test allows 0.02 deg.
"""
import erfa
import numpy as np

for when in [(2006, 4, 2, 0, 0, 0.0), (2018, 1, 21, 12, 0, 0.0), (2018, 6, 21, 10, 7, 0.0),
             (2026, 11, 21, 15, 16, 24.0)]:
    d1, d2 = erfa.dtf2d("UTC", *when)
    pvh, _ = erfa.epv00(d1, d2)
    sun_gcrs = -pvh[0]
    sun_tod = erfa.pnm06a(d1, d2) @ sun_gcrs
    u = sun_tod / np.linalg.norm(sun_tod)
    print(f"{{{when[:5]}, {{{u[0]:.9f}, {u[1]:.9f}, {u[2]:.9f}}}, {np.linalg.norm(sun_tod):.9f}}},")
