#!/usr/bin/python3
"""Writes the OMM test files of tests/data/omm/ from real TLEs, independently of trakbox.

Run with Debian's interpreter (python3-sgp4 2.15): /usr/bin/python3 scripts/make-omm-fixtures.py

The element values come from python-sgp4: Satrec.twoline2rv reads each TLE and
sgp4.exporter.export_omm turns the satellite into the OMM keywords. python-sgp4 2.15 writes no
encoding itself (export_omm returns a dict), so this script writes each encoding from that dict
as CelesTrak and Space-Track publish them: CelesTrak JSON (numbers as numbers), Space-Track JSON
(every value a string, plus the extra keys Space-Track adds), CSV, XML (CCSDS NDM) and KVN. The
XML and CSV files are read back with sgp4.omm (its parse_xml / parse_csv and initialize) and
checked against the TLE's satellite, so the files are what python-sgp4 itself understands.

Sources: ISS (ZARYA) 25544 and QO-100 43700 (deep space, geostationary) from data/amateur.tle,
MOLNIYA 2-14 08195 (deep space, 12-hour resonance) from Vallado's SGP4-VER.TLE (Debian
python3-sgp4). Three groups of files, the same three objects each time:
  sources.*    the original catalog numbers                      (sources.tle is the TLE source)
  n100123.*    renumbered 100123, 100124, 100125 (Alpha-5 A0123...: n100123.tle exists)
  n800123456.* renumbered 800123456, 800123457, 800123458 (no TLE can hold them: no .tle)
"""
import csv
import io
import json
import os
import sys
import xml.etree.ElementTree as ET

from sgp4.api import Satrec
from sgp4.exporter import export_omm
from sgp4 import omm

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, 'tests', 'data', 'omm')
VALLADO = '/usr/lib/python3/dist-packages/sgp4/SGP4-VER.TLE'

META = ['CENTER_NAME', 'REF_FRAME', 'TIME_SYSTEM', 'MEAN_ELEMENT_THEORY']
CELESTRAK_KEYS = ['OBJECT_NAME', 'OBJECT_ID', 'EPOCH', 'MEAN_MOTION', 'ECCENTRICITY', 'INCLINATION',
                  'RA_OF_ASC_NODE', 'ARG_OF_PERICENTER', 'MEAN_ANOMALY', 'EPHEMERIS_TYPE',
                  'CLASSIFICATION_TYPE', 'NORAD_CAT_ID', 'ELEMENT_SET_NO', 'REV_AT_EPOCH', 'BSTAR',
                  'MEAN_MOTION_DOT', 'MEAN_MOTION_DDOT']
MEAN_ELEMENTS = CELESTRAK_KEYS[2:9]
TLE_PARAMETERS = CELESTRAK_KEYS[9:]
ALPHA5 = 'ABCDEFGHJKLMNPQRSTUVWXYZ'


def tle_lines(path, catalog):
    """The two element lines of `catalog` (5 columns as written) in a TLE file."""
    lines = [l.rstrip('\r\n') for l in open(path)]
    for i, l in enumerate(lines):
        if l.startswith('1 ' + catalog) and lines[i + 1].startswith('2 ' + catalog):
            return l[:69], lines[i + 1][:69]
    sys.exit('%s: no set %s' % (path, catalog))


def checksum(line):
    return str(sum(int(c) if c.isdigit() else c == '-' for c in line[:68]) % 10)


def renumber_tle(line, number):
    text = '%05d' % number if number < 100000 else ALPHA5[number // 10000 - 10] + '%04d' % (number % 10000)
    line = line[:2] + text + line[7:68]
    return line + checksum(line)


def sources():
    amateur = os.path.join(ROOT, 'data', 'amateur.tle')
    return [('ISS (ZARYA)',) + tle_lines(amateur, '25544'),
            ('QO-100',) + tle_lines(amateur, '43700'),
            ('MOLNIYA 2-14',) + tle_lines(VALLADO, '08195')]


def write(name, text):
    with open(os.path.join(OUT, name), 'w', newline='') as f:
        f.write(text)


def celestrak_json(objects):
    return '[' + ',\n'.join(json.dumps({k: o[k] for k in CELESTRAK_KEYS}) for o in objects) + ']\n'


def spacetrack_json(objects):
    rows = []
    for o in objects:
        row = {'CCSDS_OMM_VERS': '2.0', 'COMMENT': 'GENERATED VIA SPACE-TRACK.ORG API',
               'ORIGINATOR': '18 SPCS'}
        row.update({k: str(o[k]) for k in ['OBJECT_NAME', 'OBJECT_ID'] + META + CELESTRAK_KEYS[2:]})
        row['DECAY_DATE'] = None  # Space-Track's null: a keyword with no value
        rows.append(row)
    return json.dumps(rows, indent=1) + '\n'


def csv_text(objects):
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=CELESTRAK_KEYS)  # lines end in \r\n, as CelesTrak's
    w.writeheader()
    for o in objects:
        w.writerow({k: o[k] for k in CELESTRAK_KEYS})
    return buf.getvalue()


def xml_text(objects):
    ndm = ET.Element('ndm')
    for o in objects:
        e = ET.SubElement(ndm, 'omm', id='CCSDS_OMM_VERS', version='2.0')
        header = ET.SubElement(e, 'header')
        ET.SubElement(header, 'ORIGINATOR').text = 'make-omm-fixtures.py'
        segment = ET.SubElement(ET.SubElement(e, 'body'), 'segment')
        groups = [(ET.SubElement(segment, 'metadata'), ['OBJECT_NAME', 'OBJECT_ID'] + META)]
        data = ET.SubElement(segment, 'data')
        groups += [(ET.SubElement(data, 'meanElements'), MEAN_ELEMENTS),
                   (ET.SubElement(data, 'tleParameters'), TLE_PARAMETERS)]
        for parent, keys in groups:
            for k in keys:
                ET.SubElement(parent, k).text = str(o[k])
    ET.indent(ndm)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(ndm, encoding='unicode') + '\n'


def kvn_text(objects):
    out = []
    for o in objects:
        out.append('CCSDS_OMM_VERS = 2.0')
        out.append('COMMENT written by scripts/make-omm-fixtures.py from python-sgp4 export_omm')
        for k in ['OBJECT_NAME', 'OBJECT_ID'] + META + CELESTRAK_KEYS[2:]:
            out.append('%-19s = %s' % (k, o[k]))
        out.append('')
    return '\n'.join(out)


def check_same(a, b, what, renumbered):
    if not renumbered and a.satnum != b.satnum:
        sys.exit('%s: satnum differs: %r vs %r' % (what, a.satnum, b.satnum))
    for attr in ['epochyr', 'jdsatepoch', 'jdsatepochF', 'no_kozai', 'ecco', 'inclo', 'nodeo',
                 'argpo', 'mo', 'bstar']:
        x, y = getattr(a, attr), getattr(b, attr)
        # The epoch is written to the microsecond (1.16e-11 day); the rest to every digit.
        tolerance = 1.2e-11 if attr == 'jdsatepochF' else 1e-12 * max(1.0, abs(x))
        if abs(x - y) > tolerance:
            sys.exit('%s: %s differs: %r vs %r' % (what, attr, x, y))


def main():
    os.makedirs(OUT, exist_ok=True)
    base = sources()
    for group, first in [('sources', None), ('n100123', 100123), ('n800123456', 800123456)]:
        objects, tle, sats = [], [], []
        for i, (name, l1, l2) in enumerate(base):
            sat = Satrec.twoline2rv(l1, l2)
            o = export_omm(sat, name)
            if first is not None:
                o['NORAD_CAT_ID'] = first + i
                if first + i <= 339999:
                    l1, l2 = renumber_tle(l1, first + i), renumber_tle(l2, first + i)
            objects.append(o)
            sats.append(sat)
            tle += [name, l1, l2]
        if first is None or first <= 339999:
            write(group + '.tle', '\n'.join(tle) + '\n')
        write(group + '.json', celestrak_json(objects))
        write(group + '-spacetrack.json', spacetrack_json(objects))
        write(group + '.csv', csv_text(objects))
        write(group + '.xml', xml_text(objects))
        write(group + '.kvn', kvn_text(objects))
        # What python-sgp4 reads back from its own files must be the TLE's satellite.
        for suffix, parse in [('.xml', omm.parse_xml), ('.csv', omm.parse_csv)]:
            with open(os.path.join(OUT, group + suffix), newline='') as f:
                read = list(parse(f))
            if len(read) != len(sats):
                sys.exit('%s%s: %d objects read back' % (group, suffix, len(read)))
            for fields, sat in zip(read, sats):
                again = Satrec()
                omm.initialize(again, fields)
                check_same(sat, again, group + suffix, first is not None)
    print('wrote', OUT)


if __name__ == '__main__':
    main()
