#!/usr/bin/env python3
"""Independent E57 inspector used to obtain the expected values of test_e57.

Written from E57_FACTS.md only (no code shared with core/io/e57): checks the file length,
every page CRC-32C (bit-by-bit, no table), the header; extracts the XML and, for every
data3D, prints recordCount, prototype fields, pose, cartesianBounds; then decodes the points
(bit-pack codec, pure Python) and prints the number of points that are valid
(cartesianInvalidState/sphericalInvalidState != 1 and != 2, i.e. kept by default) and the bounds of
those points in the scan frame (spherical converted as x=r cos(el) cos(az) ...).

Usage: e57_inspect.py FILE...   (prints one block per file; errors are printed, not raised)
"""
import math
import struct
import sys
import xml.etree.ElementTree as ET

PAGE = 1024
PAYLOAD = 1020


def crc32c(data):
    crc = 0xFFFFFFFF
    for b in data:
        crc ^= b
        for _ in range(8):
            crc = (crc >> 1) ^ (0x82F63B78 if crc & 1 else 0)
    return crc ^ 0xFFFFFFFF


class Logical:
    def __init__(self, raw):
        self.raw = raw
        pages = len(raw) // PAGE
        self.data = b"".join(raw[i * PAGE:i * PAGE + PAYLOAD] for i in range(pages))

    @staticmethod
    def log(phys):
        return (phys // PAGE) * PAYLOAD + min(phys % PAGE, PAYLOAD)

    def read(self, phys, n):
        off = self.log(phys)
        if off + n > len(self.data):
            raise ValueError("read past end: physical %d + %d" % (phys, n))
        return self.data[off:off + n]


def strip_ns(tag):
    return tag.split('}', 1)[1] if '}' in tag else tag


def local_name(tag, nsmap_rev):
    if '}' in tag:
        ns, name = tag[1:].split('}', 1)
        prefix = nsmap_rev.get(ns, '')
        return (prefix + ':' + name) if prefix else name
    return tag


def fields_of(proto, nsrev):
    out = []
    for child in proto:
        t = child.get('type')
        name = local_name(child.tag, nsrev)
        if t == 'Structure':
            for sub in fields_of(child, nsrev):
                out.append((name + '/' + sub[0],) + sub[1:])
            continue
        f = {'type': t}
        if t in ('Integer', 'ScaledInteger'):
            f['min'] = int(child.get('minimum', str(-2**63)))
            f['max'] = int(child.get('maximum', str(2**63 - 1)))
            f['scale'] = float(child.get('scale', '1'))
            f['offset'] = float(child.get('offset', '0'))
        elif t == 'Float':
            f['precision'] = child.get('precision', 'double')
        out.append((name, f))
    return out


class BitReader:
    def __init__(self, data):
        self.data = data
        self.pos = 0  # bit position

    def take(self, bits):
        v = 0
        for k in range(bits):
            p = self.pos + k
            v |= ((self.data[p >> 3] >> (p & 7)) & 1) << k
        self.pos += bits
        return v


def decode_points(lg, cv, fields, count, file_size):
    hdr = lg.read(int(cv.get('fileOffset')), 32)
    sid, sect_len, data_off, index_off = hdr[0], *struct.unpack('<QQQ', hdr[8:32])
    if sid != 1:
        raise ValueError('compressed vector section id %d' % sid)
    streams = [bytearray() for _ in fields]
    if count == 0:
        return {}
    pos = lg.log(data_off)
    end = lg.log(int(cv.get('fileOffset'))) + sect_len
    while pos < end:
        h = lg.data[pos:pos + 4]
        ptype, length = h[0], struct.unpack('<H', h[2:4])[0] + 1
        if ptype == 1:
            n = struct.unpack('<H', lg.data[pos + 4:pos + 6])[0]
            lens = struct.unpack('<%dH' % n, lg.data[pos + 6:pos + 6 + 2 * n])
            q = pos + 6 + 2 * n
            for i, L in enumerate(lens):
                streams[i] += lg.data[q:q + L]
                q += L
        elif ptype not in (0, 2):
            raise ValueError('packet type %d at logical %d' % (ptype, pos))
        pos += length
    values = {}
    for (name, f), s in zip(fields, streams):
        vals = []
        if f['type'] == 'Float':
            fmt, size = ('<f', 4) if f['precision'] == 'single' else ('<d', 8)
            for i in range(count):
                vals.append(struct.unpack(fmt, s[i * size:(i + 1) * size])[0])
        else:
            rng = f['max'] - f['min']
            bits = 0 if rng == 0 else rng.bit_length()
            br = BitReader(s)
            for i in range(count):
                raw = br.take(bits) + f['min'] if bits else f['min']
                vals.append(raw * f['scale'] + f['offset'] if f['type'] == 'ScaledInteger' else raw)
        values[name] = vals
    return values


def inspect(path):
    raw = open(path, 'rb').read()
    print('== %s (%d bytes)' % (path, len(raw)))
    if len(raw) % PAGE:
        print('ERROR: size not a multiple of 1024')
        return
    for i in range(len(raw) // PAGE):
        page = raw[i * PAGE:(i + 1) * PAGE]
        if crc32c(page[:PAYLOAD]) != struct.unpack('>I', page[PAYLOAD:])[0]:
            print('ERROR: bad CRC on page %d (byte %d)' % (i, i * PAGE))
            return
    sig = raw[:8]
    major, minor, plen, xoff, xlen, psize = struct.unpack('<IIQQQQ', raw[8:48])
    print('header: sig=%r version=%d.%d length=%d xml@%d len %d page %d' %
          (sig, major, minor, plen, xoff, xlen, psize))
    lg = Logical(raw)
    xml = lg.read(xoff, xlen)
    nsrev = {}
    for ev, (prefix, uri) in ET.iterparse(__import__('io').BytesIO(xml), events=['start-ns']):
        if prefix:
            nsrev[uri] = prefix
    root = ET.fromstring(xml)
    d3 = [c for c in root if strip_ns(c.tag) == 'data3D']
    scans = list(d3[0]) if d3 else []
    print('scans: %d' % len(scans))
    for k, scan in enumerate(scans):
        get = {strip_ns(c.tag): c for c in scan}
        name = get['name'].text if 'name' in get else ''
        print('scan %d name=%r guid=%r' % (k, name, get['guid'].text if 'guid' in get else ''))
        pose = get.get('pose')
        if pose is not None:
            pd = {}
            for part in pose:
                for c in part:
                    pd[strip_ns(part.tag) + '.' + strip_ns(c.tag)] = float(c.text or 0)
            print('  pose', pd)
        cb = get.get('cartesianBounds')
        if cb is not None:
            print('  cartesianBounds', {strip_ns(c.tag): float(c.text or 0) for c in cb})
        pts = get['points']
        count = int(pts.get('recordCount'))
        proto = [c for c in pts if strip_ns(c.tag) == 'prototype'][0]
        fields = fields_of(proto, nsrev)
        print('  recordCount=%d fileOffset=%s' % (count, pts.get('fileOffset')))
        print('  prototype:', ' '.join('%s:%s%s%s' % (n, f['type'], ('[%d,%d]' % (f['min'], f['max'])
                                        if 'min' in f else ''), ('/' + f['precision'] if 'precision' in f else ''))
                                       for n, f in fields))
        try:
            v = decode_points(lg, pts, fields, count, len(raw))
        except Exception as e:  # noqa
            print('  DECODE ERROR:', e)
            continue
        if not v:
            print('  valid=0')
            continue
        keep = []
        for i in range(count):
            ok = True
            for st in ('cartesianInvalidState', 'sphericalInvalidState'):
                if st in v and v[st][i] != 0:
                    ok = False
            keep.append(ok)
        if 'cartesianX' in v:
            xyz = [(v['cartesianX'][i], v['cartesianY'][i], v['cartesianZ'][i]) for i in range(count)]
        else:
            xyz = []
            for i in range(count):
                r, az, el = v['sphericalRange'][i], v['sphericalAzimuth'][i], v['sphericalElevation'][i]
                xyz.append((r * math.cos(el) * math.cos(az), r * math.cos(el) * math.sin(az), r * math.sin(el)))
        sel = [p for p, ok in zip(xyz, keep) if ok]
        print('  valid=%d (of %d)' % (len(sel), count))
        if sel:
            lo = [min(p[a] for p in sel) for a in range(3)]
            hi = [max(p[a] for p in sel) for a in range(3)]
            print('  bounds min=(%.6f, %.6f, %.6f) max=(%.6f, %.6f, %.6f)' % (*lo, *hi))
            if cb is not None:
                c = {strip_ns(e.tag): float(e.text or 0) for e in cb}
                inside = all(c[a + 'Minimum'] <= lo[k] and hi[k] <= c[a + 'Maximum']
                             for k, a in enumerate('xyz'))
                print('  points inside cartesianBounds: %s' % ('yes' if inside else 'no'))
        if 'isColorInvalid' in v:
            print('  isColorInvalid set=%d' % sum(1 for x, ok in zip(v['isColorInvalid'], keep)
                                                 if ok and x != 0))
        extensions = sorted(n for n in v if ':' in n)
        for name in ('intensity', 'colorRed', 'rowIndex', 'columnIndex', 'returnIndex', 'timeStamp',
                     *extensions):
            if name in v:
                vals = [x for x, ok in zip(v[name], keep) if ok]
                if vals:
                    print('  %s range [%s, %s]' % (name, min(vals), max(vals)))


if __name__ == '__main__':
    for p in sys.argv[1:]:
        try:
            inspect(p)
        except Exception as e:  # noqa
            print('ERROR:', type(e).__name__, e)
