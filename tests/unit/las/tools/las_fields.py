#!/usr/bin/env python3
"""Independent LAS reader/writer for the lossless-conversion tests (standard library only,
written from docs/LAS_FORMAT.md; no code shared with core/io/las).

  las_fields.py make OUT.las     writes LAS 1.4 PDRF 6 with every non-coordinate field varied
                                 (5 points, listed in the docstring of make())
  las_fields.py dump FILE.las    prints the header facts, then one line per point with every
                                 field but X/Y/Z, in a form that does not depend on the format
                                 (so a PDRF 6 file and its conversion compare line by line)
  las_fields.py extra FILE.las   prints the Extra Bytes VLR (LASF_Spec 4) descriptors, one line
                                 'field NAME type T at OFFSET', then one line per point,
                                 'point I NAME=VALUE ...' (float/double fields, raw values)
"""
import struct
import sys

SIZE = {0: 20, 1: 28, 2: 26, 3: 34, 6: 30, 7: 36, 8: 38}
GPS = {1: 20, 3: 20, 6: 22, 7: 22, 8: 22}
RGB = {2: 20, 3: 28, 7: 30, 8: 30}


def make(path):
    """Points i = 0..4: intensity 1000 i, return (i % 3) + 1 of 3, class 2 + i,
    flags (synthetic, key-point, withheld, overlap) = i + 3 (low 4 bits), scanner channel i % 4,
    scan direction i % 2, edge of flight line (i // 2) % 2, user data 10 + i,
    scan angle -1000 + 500 i (x 0.006 deg), point source id 4000 + i, GPS time 5.25 + i."""
    n = 5
    recs = bytearray()
    for i in range(n):
        r = bytearray(30)
        struct.pack_into('<iiiH', r, 0, 100 * i, -50 * i, 7 * i, 1000 * i)
        r[14] = ((i % 3) + 1) | (3 << 4)
        r[15] = ((i + 3) & 0x0F) | ((i % 4) << 4) | ((i % 2) << 6) | (((i // 2) % 2) << 7)
        r[16] = 2 + i
        r[17] = 10 + i
        struct.pack_into('<hHd', r, 18, -1000 + 500 * i, 4000 + i, 5.25 + i)
        recs += r
    h = bytearray(375)
    h[0:4] = b'LASF'
    struct.pack_into('<H', h, 6, 0x10)  # WKT bit (required for PDRF 6)
    h[24], h[25] = 1, 4
    h[26:31] = b'pytest'[:5]
    struct.pack_into('<HIIBH', h, 94, 375, 375, 0, 6, 30)
    struct.pack_into('<3d', h, 131, 0.01, 0.01, 0.01)
    struct.pack_into('<3d', h, 155, 1000.0, 2000.0, 10.0)
    struct.pack_into('<6d', h, 179, 1004.0, 1000.0, 2000.0, 1998.0, 10.28, 10.0)
    struct.pack_into('<Q', h, 247, n)
    by_return = [sum(1 for i in range(n) if (i % 3) + 1 == k) for k in range(1, 16)]
    struct.pack_into('<15Q', h, 255, *by_return)
    with open(path, 'wb') as f:
        f.write(h + recs)


def dump(path):
    b = open(path, 'rb').read()
    assert b[0:4] == b'LASF', 'not a LAS file'
    minor = b[25]
    header_size, offset, _nvlr, fmt, reclen = struct.unpack_from('<HIIBH', b, 94)
    fmt &= 0x3F
    legacy = struct.unpack_from('<I', b, 107)[0]
    legacy_by = struct.unpack_from('<5I', b, 111)
    count = struct.unpack_from('<Q', b, 247)[0] if minor >= 4 else legacy
    by = struct.unpack_from('<15Q', b, 255) if minor >= 4 else legacy_by
    print('version 1.%d format %d record %d count %d' % (minor, fmt, reclen, count))
    print('by_return %s' % ' '.join(str(v) for v in by[:5]))
    print('legacy %d %s' % (legacy, ' '.join(str(v) for v in legacy_by)))
    ext = fmt >= 6
    for i in range(count):
        r = b[offset + i * reclen: offset + (i + 1) * reclen]
        intensity = struct.unpack_from('<H', r, 12)[0]
        if ext:
            ret, cnt = r[14] & 0x0F, r[14] >> 4
            flags, channel = r[15] & 0x0F, (r[15] >> 4) & 3
            direction, edge = (r[15] >> 6) & 1, r[15] >> 7
            cls, user = r[16], r[17]
            angle_deg = struct.unpack_from('<h', r, 18)[0] * 0.006
            source = struct.unpack_from('<H', r, 20)[0]
        else:
            ret, cnt = r[14] & 7, (r[14] >> 3) & 7
            direction, edge = (r[14] >> 6) & 1, r[14] >> 7
            cls, flags, channel = r[15] & 0x1F, r[15] >> 5, 0
            angle_deg = struct.unpack_from('<b', r, 16)[0]
            user = r[17]
            source = struct.unpack_from('<H', r, 18)[0]
        gps = struct.unpack_from('<d', r, GPS[fmt])[0] if fmt in GPS else None
        rgb = struct.unpack_from('<3H', r, RGB[fmt]) if fmt in RGB else None
        print('point %d intensity %d return %d/%d class %d flags %d channel %d direction %d '
              'edge %d user %d angle %.3f source %d gps %s rgb %s' %
              (i, intensity, ret, cnt, cls, flags, channel, direction, edge, user, angle_deg,
               source, gps, rgb))


def extra(path):
    """The Extra Bytes VLR: 54-byte VLR headers walked from the header size; each 192-byte
    descriptor has data_type @2 (9 float, 10 double) and a 32-byte name @4; described fields
    follow one another from the end of the format's core record."""
    b = open(path, 'rb').read()
    assert b[0:4] == b'LASF', 'not a LAS file'
    header_size, offset, nvlr, fmt, reclen = struct.unpack_from('<HIIBH', b, 94)
    fmt &= 0x3F
    minor = b[25]
    count = struct.unpack_from('<Q', b, 247)[0] if minor >= 4 else struct.unpack_from('<I', b, 107)[0]
    fields, pos, at = [], header_size, SIZE[fmt]
    for _ in range(nvlr):
        user = b[pos + 2:pos + 18].rstrip(b'\0').decode()
        rid, length = struct.unpack_from('<HH', b, pos + 18)
        if user == 'LASF_Spec' and rid == 4:
            for d in range(length // 192):
                desc = b[pos + 54 + 192 * d: pos + 54 + 192 * (d + 1)]
                kind = desc[2]
                name = desc[4:36].rstrip(b'\0').decode()
                size = {9: 4, 10: 8}[kind]
                fields.append((name, kind, at))
                print('field %s type %d at %d' % (name, kind, at))
                at += size
        pos += 54 + length
    for i in range(count):
        r = b[offset + i * reclen: offset + (i + 1) * reclen]
        vals = ['%s=%r' % (n, struct.unpack_from('<f' if k == 9 else '<d', r, o)[0]) for n, k, o in fields]
        print('point %d %s' % (i, ' '.join(vals)))


if __name__ == '__main__':
    {'make': make, 'dump': dump, 'extra': extra}[sys.argv[1]](sys.argv[2])
