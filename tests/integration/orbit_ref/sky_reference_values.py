#!/usr/bin/python3
"""Prints the Sun and Moon reference values written into tests/unit/orbit/test_sky.cpp.

Independent oracle: PyEphem 4.1.4 (Debian python3-ephem, libastro from XEphem), offline. For each
station and UTC instant: the topocentric azimuth and elevation of the Sun's and the Moon's centre
as seen from the station, with refraction off (pressure = 0), i.e. geometric apparent places of
date, which is what trakbox points at; the Moon's distance from the station in km (PyEphem's
earth_distance of a body computed for an observer is topocentric); and, for the
refraction test, the Sun's elevation with PyEphem's refraction at 1010 hPa and 10 C.

Run: /usr/bin/python3 tests/integration/orbit_ref/sky_reference_values.py
"""
import math

import ephem

AU_KM = 149597870.7

STATIONS = [
    ("tucson", 32.259, -110.778, 842.0),    # the manual's station
    ("munich", 48.1458, 11.625, 520.0),     # JN58td
    ("cape", -33.9249, 18.4241, 10.0),      # southern hemisphere
    ("tromso", 69.6496, 18.9560, 100.0),    # high latitude
]
TIMES = ["2026/05/21 18:00:00", "2026/12/21 12:00:00", "2026/03/20 09:00:00",
         "2024/04/08 18:20:00", "2031/07/04 03:30:00"]


def observer(lat, lon, height):
    o = ephem.Observer()
    o.lat, o.lon, o.elevation = str(lat), str(lon), height
    o.pressure = 0
    return o


def main():
    for name, lat, lon, height in STATIONS:
        for when in TIMES:
            o = observer(lat, lon, height)
            o.date = when
            sun, moon = ephem.Sun(o), ephem.Moon(o)
            y, mo, d, h, mi, s = ephem.Date(when).tuple()
            print(f"    {{{{{lat}, {lon}, {height}}}, from_civil({y}, {mo}, {d}, {h}, {mi}), "
                  f"{math.degrees(sun.az):.4f}, {math.degrees(sun.alt):.4f}, "
                  f"{math.degrees(moon.az):.4f}, {math.degrees(moon.alt):.4f}, "
                  f"{moon.earth_distance * AU_KM:.1f}}},  // {name}")
    print("refraction (true el, lift) at 1010 hPa, 10 C:")
    o = observer(48.1458, 11.625, 520.0)
    o.pressure, o.temp = 1010, 10
    for when in ["2026/05/21 18:00:00", "2026/05/21 18:30:00", "2026/05/21 17:00:00",
                 "2026/05/21 15:00:00"]:
        o.date = when
        o.pressure = 0
        true_alt = math.degrees(ephem.Sun(o).alt)
        o.pressure = 1010
        lift = math.degrees(ephem.Sun(o).alt) - true_alt
        print(f"    {{{true_alt:.4f}, {lift:.4f}}},")


def events():
    """Rise, transit and set of the centre at a -2 deg horizon (trakbox's AOS rule), no refraction."""
    print("rise / culmination / set, centre, horizon -2 deg, pressure 0 (UTC):")
    for name, lat, lon, height in STATIONS[:2]:
        for body in (ephem.Sun(), ephem.Moon()):
            o = observer(lat, lon, height)
            o.horizon = "-2"
            o.date = "2026/03/20 00:00:00"
            rise = o.next_rising(body, use_center=True)
            o.date = rise
            transit = o.next_transit(body)
            body.compute(o)
            o.date = transit
            body.compute(o)
            max_el = math.degrees(body.alt)
            setting = o.next_setting(body, use_center=True)
            print(f"    {name} {body.name}: rise {rise} transit {transit} (el {max_el:.4f}) set {setting}")


def parallax():
    """The Moon's geocentric elevation against the station's horizon (PyEphem's apparent geocentric
    right ascension and declination of date, g_ra/g_dec, at the local apparent sidereal time), and
    the parallax: geocentric minus topocentric elevation."""
    print("moon geocentric el, topocentric el (deg):")
    for name, lat, lon, height in STATIONS[:2]:
        for when in TIMES[:3]:
            o = observer(lat, lon, height)
            o.date = when
            m = ephem.Moon(o)
            h = float(o.sidereal_time()) - float(m.g_ra)
            phi, dec = math.radians(lat), float(m.g_dec)
            geo = math.degrees(math.asin(math.sin(phi) * math.sin(dec) + math.cos(phi) * math.cos(dec) * math.cos(h)))
            print(f"    {name} {when}: {geo:.4f} {math.degrees(m.alt):.4f}")


if __name__ == "__main__":
    main()
    events()
    parallax()
