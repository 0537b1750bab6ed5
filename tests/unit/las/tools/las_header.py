#!/usr/bin/env python3
"""Independent LAS header parser used to verify what tests/unit/las expects.

Written straight from the ASPRS LAS 1.4 R16 tables in docs/LAS_FORMAT.md with the
standard library only (struct), sharing no code with core/io/las. Usage:

    python3 las_header.py FILE [FILE...]          # header, VLRs, EVLRs, point summary
    python3 las_header.py --point N FILE          # also dump point N's decoded fields

For each file it prints the header fields, the (E)VLR list, and a scan of all points:
min/max of the scaled X/Y/Z, count per return number and class, min/max of intensity/RGB/GPS.
"""
import struct
import sys

CORE_SIZE = {0: 20, 1: 28, 2: 26, 3: 34, 4: 57, 5: 63, 6: 30, 7: 36, 8: 38, 9: 59, 10: 67}
GPS_AT = {1: 20, 3: 20, 4: 20, 5: 20, 6: 22, 7: 22, 8: 22, 9: 22, 10: 22}
RGB_AT = {2: 20, 3: 28, 5: 28, 7: 30, 8: 30, 10: 30}


def header(data):
    h = {}
    h["signature"] = data[0:4]
    h["major"], h["minor"] = data[24], data[25]
    h["system"] = data[26:58].split(b"\0")[0].decode("latin-1")
    h["software"] = data[58:90].split(b"\0")[0].decode("latin-1")
    h["global_encoding"] = struct.unpack_from("<H", data, 6)[0]
    (h["header_size"], h["offset_to_points"], h["n_vlrs"], h["pdrf"], h["record_length"],
     h["legacy_count"]) = struct.unpack_from("<HIIBHI", data, 94)
    h["legacy_by_return"] = struct.unpack_from("<5I", data, 111)
    h["scale"] = struct.unpack_from("<3d", data, 131)
    h["offset"] = struct.unpack_from("<3d", data, 155)
    mx, mnx, my, mny, mz, mnz = struct.unpack_from("<6d", data, 179)
    h["min"], h["max"] = (mnx, mny, mnz), (mx, my, mz)
    h["count"] = h["legacy_count"]
    h["evlr_start"], h["n_evlrs"] = 0, 0
    if h["minor"] >= 4 and h["header_size"] >= 375:
        h["evlr_start"], h["n_evlrs"], count64 = struct.unpack_from("<QIQ", data, 235)
        h["by_return"] = struct.unpack_from("<15Q", data, 255)
        h["count"] = h["legacy_count"] if h["legacy_count"] else count64
    return h


def vlrs(data, h):
    out, pos = [], h["header_size"]
    for _ in range(h["n_vlrs"]):
        user = data[pos + 2:pos + 18].split(b"\0")[0].decode("latin-1")
        rid, length = struct.unpack_from("<HH", data, pos + 18)
        out.append(("VLR", pos, user, rid, length))
        pos += 54 + length
    pos = h["evlr_start"]
    for _ in range(h["n_evlrs"]):
        user = data[pos + 2:pos + 18].split(b"\0")[0].decode("latin-1")
        rid, length = struct.unpack_from("<HQ", data, pos + 18)
        out.append(("EVLR", pos, user, rid, length))
        pos += 60 + length
    return out


EXTRA_FMT = {1: "B", 2: "b", 3: "H", 4: "h", 5: "I", 6: "i", 7: "Q", 8: "q", 9: "f", 10: "d"}


def extra_descriptors(data, h):
    """(name, struct code, element count, byte size) of each Extra Bytes descriptor."""
    out = []
    for kind, pos, user, rid, length in vlrs(data, h):
        if user != "LASF_Spec" or rid != 4:
            continue
        start = pos + (54 if kind == "VLR" else 60)
        for k in range(length // 192):
            d = data[start + 192 * k:start + 192 * (k + 1)]
            dtype, options = d[2], d[3]
            name = d[4:36].split(b"\0")[0].decode("latin-1")
            if dtype == 0:
                out.append((name, None, 0, options))
            else:
                n, base = (dtype - 1) // 10 + 1, (dtype - 1) % 10 + 1
                out.append((name, EXTRA_FMT[base], n, n * struct.calcsize(EXTRA_FMT[base])))
    return out


def point(data, h, i):
    f = h["pdrf"] & 0x3F
    base = h["offset_to_points"] + i * h["record_length"]
    x, y, z, inten = struct.unpack_from("<iiiH", data, base)
    p = {"raw": (x, y, z), "intensity": inten}
    p["xyz"] = tuple(r * s + o for r, s, o in zip((x, y, z), h["scale"], h["offset"]))
    b = data[base + 14]
    if f < 6:
        p["return"], p["returns"], p["class"] = b & 7, (b >> 3) & 7, data[base + 15] & 31
    else:
        p["return"], p["returns"], p["class"] = b & 15, b >> 4, data[base + 16]
    if f in GPS_AT:
        p["gps"] = struct.unpack_from("<d", data, base + GPS_AT[f])[0]
    if f in RGB_AT:
        p["rgb"] = struct.unpack_from("<3H", data, base + RGB_AT[f])
    at = base + CORE_SIZE[f]
    for name, code, n, size in extra_descriptors(data, h):
        if code:
            p["extra " + name] = struct.unpack_from("<%d%s" % (n, code), data, at)
        at += size
    return p


def summary(data, h):
    n = h["count"]
    lo, hi = [float("inf")] * 3, [-float("inf")] * 3
    by_ret, by_class, stats = {}, {}, {}
    for i in range(n):
        p = point(data, h, i)
        for a in range(3):
            lo[a], hi[a] = min(lo[a], p["xyz"][a]), max(hi[a], p["xyz"][a])
        by_ret[p["return"]] = by_ret.get(p["return"], 0) + 1
        by_class[p["class"]] = by_class.get(p["class"], 0) + 1
        for k in ("intensity", "gps"):
            if k in p:
                s = stats.setdefault(k, [p[k], p[k]])
                s[0], s[1] = min(s[0], p[k]), max(s[1], p[k])
        if "rgb" in p:
            s = stats.setdefault("rgb", [min(p["rgb"]), max(p["rgb"])])
            s[0], s[1] = min(s[0], min(p["rgb"])), max(s[1], max(p["rgb"]))
    return lo, hi, by_ret, by_class, stats


def main(argv):
    want = None
    if len(argv) > 2 and argv[0] == "--point":
        want, argv = int(argv[1]), argv[2:]
    for path in argv:
        data = open(path, "rb").read()
        h = header(data)
        print(f"== {path} ({len(data)} bytes)")
        for k, v in h.items():
            print(f"  {k}: {v}")
        for v in vlrs(data, h):
            print("  %s @%d user=%r id=%d length=%d" % v)
        lo, hi, by_ret, by_class, stats = summary(data, h)
        print(f"  points min: {lo}\n  points max: {hi}")
        print(f"  by return: {sorted(by_ret.items())}\n  by class: {sorted(by_class.items())}")
        for k, v in stats.items():
            print(f"  {k}: {v[0]} .. {v[1]}")
        if want is not None:
            print(f"  point {want}: {point(data, h, want)}")


if __name__ == "__main__":
    main(sys.argv[1:])
