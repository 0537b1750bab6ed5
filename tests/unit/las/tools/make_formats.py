#!/usr/bin/env python3
"""Writes tests/unit/las/data/format_<N>.las for every point format 0..10 (shared/data/las has
only 1, 3, 4, 6, 7), from the record tables of docs/LAS_FORMAT.md, with the standard
library only. test_las_formats.cpp checks the reader against the values below.

Each file holds 3 points, i = 0, 1, 2:
  X, Y, Z records = 1000*i + 1, -2000*i - 2, 3*i + 3 with scale 0.001 and offset
  (500000, 6000000, 100)  -> world (500000.001 + i, 5999999.998 - 2i, 100.003 + 0.003i)
  intensity 100 + i; return number i + 1 of 3; class 2 + i (PDRF 6-10: 40 + i, > 31)
  user data 7, point source id 300 + i; scan angle rank -5 (0-5) / -500 * 0.006 deg (6-10)
  GPS time 1000.5 + i; RGB = (256 * (10 + i), 256 * 20, 256 * 30); NIR 777
Versions: 1.0 for PDRF 0, 1.1 for 1, 1.2 for 2-3, 1.3 for 4-5, 1.4 for 6-10 (64-bit
counts, WKT bit set), so every version 1.0-1.4 is read too.
"""
import os
import struct

SIZE = {0: 20, 1: 28, 2: 26, 3: 34, 4: 57, 5: 63, 6: 30, 7: 36, 8: 38, 9: 59, 10: 67}
GPS = {1: 20, 3: 20, 4: 20, 5: 20, 6: 22, 7: 22, 8: 22, 9: 22, 10: 22}
RGB = {2: 20, 3: 28, 5: 28, 7: 30, 8: 30, 10: 30}
NIR = {8: 36, 10: 36}
N = 3


def record(fmt, i):
    r = bytearray(SIZE[fmt])
    struct.pack_into("<iiiH", r, 0, 1000 * i + 1, -2000 * i - 2, 3 * i + 3, 100 + i)
    if fmt < 6:
        r[14] = (i + 1) | (3 << 3)
        r[15] = 2 + i
        struct.pack_into("<bBH", r, 16, -5, 7, 300 + i)
    else:
        r[14] = (i + 1) | (3 << 4)
        r[15] = 0
        r[16] = 40 + i
        struct.pack_into("<BhH", r, 17, 7, -500, 300 + i)
    if fmt in GPS:
        struct.pack_into("<d", r, GPS[fmt], 1000.5 + i)
    if fmt in RGB:
        struct.pack_into("<3H", r, RGB[fmt], 256 * (10 + i), 256 * 20, 256 * 30)
    if fmt in NIR:
        struct.pack_into("<H", r, NIR[fmt], 777)
    return bytes(r)


def header(fmt):
    minor = min(fmt, 2) if fmt <= 3 else (3 if fmt <= 5 else 4)
    size = {0: 227, 1: 227, 2: 227, 3: 235, 4: 375}[minor]
    h = bytearray(size)
    h[0:4] = b"LASF"
    struct.pack_into("<H", h, 6, 0x10 if fmt >= 6 else 0)
    h[24], h[25] = 1, minor
    h[26:26 + 9] = b"make_form"
    struct.pack_into("<HIIBHI", h, 94, size, size, 0, fmt, SIZE[fmt], N if fmt < 6 else 0)
    if fmt < 6:
        struct.pack_into("<5I", h, 111, 1, 1, 1, 0, 0)
    struct.pack_into("<3d", h, 131, 0.001, 0.001, 0.001)
    struct.pack_into("<3d", h, 155, 500000.0, 6000000.0, 100.0)
    struct.pack_into("<6d", h, 179, 500002.001, 500000.001, 5999999.998, 5999995.998,
                     100.009, 100.003)
    if minor == 4:
        struct.pack_into("<QIQ", h, 235, 0, 0, N)
        struct.pack_into("<3Q", h, 255, 1, 1, 1)
    return bytes(h)


def main():
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data")
    os.makedirs(out, exist_ok=True)
    for fmt in range(11):
        with open(os.path.join(out, "format_%d.las" % fmt), "wb") as f:
            f.write(header(fmt) + b"".join(record(fmt, i) for i in range(N)))


if __name__ == "__main__":
    main()
