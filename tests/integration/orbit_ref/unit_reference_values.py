#!/usr/bin/python3
"""Prints the Skyfield/python-sgp4 reference values written into tests/unit/orbit/test_observe.cpp.

Run once with Debian's interpreter (python3-sgp4, python3-skyfield), offline:
    /usr/bin/python3 tests/integration/orbit_ref/unit_reference_values.py
For each case: the TEME state from python-sgp4 (Satrec.twoline2rv, WGS-72, improved mode) at a UTC
time, Skyfield's DUT1 for that time (builtin IERS table), and what Skyfield says a WGS-84 station
sees: (sat - station).at(t).altaz(), the range rate from frame_latlon_and_rates(station), and the
sub-satellite point from wgs84.geographic_position_of(). The unit test feeds the TEME state and DUT1
to teme_to_ecef/look_angles/ecef_to_geodetic, so it checks the geometry alone, not SGP4.
"""
from skyfield.api import EarthSatellite, load, wgs84

CASES = [
    # name, line1, line2, (Y, M, D, h, m, s) UTC, (lat, lon, height_m)
    ("ISS over Tucson", "1 25544U 98067A   18020.89808844  .00002078  00000-0  38550-4 0  9992",
     "2 25544  51.6424  32.9776 0003646  28.7227  39.5332 15.54190080 95614",
     (2018, 1, 21, 3, 37, 10), (32.259, -110.778, 842.0)),
    ("Molniya 1-91 from McMurdo", "1 25485U 98054A   18020.59692113  .00001350  00000-0  30675-3 0  9990",
     "2 25485  61.9914  82.2968 7500781 275.3765 275.9103  2.00669830141494",
     (2018, 1, 22, 3, 30, 15), (-77.85, 166.67, 10.0)),
    ("GOES 16 from Quito", "1 41866U 16071A   18019.87773469 -.00000245  00000-0  00000-0 0  9992",
     "2 41866   0.0069 115.0916 0001074 269.6956 335.2025  1.00271237  4322",
     (2018, 1, 20, 6, 0, 0), (-0.1807, -78.4678, 2850.0)),
]

ts = load.timescale(builtin=True)
for name, l1, l2, when, (lat, lon, h) in CASES:
    sat = EarthSatellite(l1, l2, name, ts)
    t = ts.utc(*when)
    err, r, v = sat.model.sgp4(t.whole, t.tai_fraction - t._leap_seconds() / 86400.0)
    station = wgs84.latlon(lat, lon, elevation_m=h)
    topo = (sat - station).at(t)
    alt, az, dist = topo.altaz()
    _, _, _, _, _, range_rate = topo.frame_latlon_and_rates(station)
    sub = wgs84.geographic_position_of(sat.at(t))
    print(f"// {name}: {when} UTC, station {lat}, {lon}, {h} m, DUT1 {float(t.dut1)!r} s")
    print(f"//   TEME r = {{{r[0]!r}, {r[1]!r}, {r[2]!r}}}")
    print(f"//   TEME v = {{{v[0]!r}, {v[1]!r}, {v[2]!r}}}")
    print(f"//   az {az.degrees!r} el {alt.degrees!r} range {dist.km!r} range rate {range_rate.km_per_s!r}")
    print(f"//   sub-point lat {sub.latitude.degrees!r} lon {sub.longitude.degrees!r} alt {sub.elevation.km!r}")
