#!/usr/bin/env python3
"""Independent check of the values test_io asserts for ../shared/data/{pcd,ifc}.

PCD: parses the header itself, decompresses binary_compressed data with its own LZF decoder
(PCD stores the fields column by column after decompression), and prints point counts, the
number of finite points and the bounds of the finite points.
IFC: counts entity instances per type with a regular expression over the STEP text.
Run: python3 tests/unit/io/verify_shared_data.py ../shared/data
"""
import math
import re
import struct
import sys
from collections import Counter
from pathlib import Path


def lzf_decompress(src, out_len):
    out = bytearray()
    i = 0
    while i < len(src):
        ctrl = src[i]
        i += 1
        if ctrl < 32:  # literal run of ctrl+1 bytes
            out += src[i:i + ctrl + 1]
            i += ctrl + 1
        else:  # back reference
            length = ctrl >> 5
            if length == 7:
                length += src[i]
                i += 1
            ref = len(out) - ((ctrl & 0x1F) << 8) - src[i] - 1
            i += 1
            for _ in range(length + 2):
                out.append(out[ref])
                ref += 1
    assert len(out) == out_len, (len(out), out_len)
    return bytes(out)


def pcd(path):
    data = path.read_bytes()
    header = {}
    pos = 0
    while True:
        end = data.index(b"\n", pos)
        line = data[pos:end].decode().strip()
        pos = end + 1
        if not line or line.startswith("#"):
            continue
        key, *vals = line.split()
        header[key] = vals
        if key == "DATA":
            break
    fields = header["FIELDS"]
    sizes = [int(s) for s in header["SIZE"]]
    n = int(header["POINTS"][0])
    assert all(s == 4 for s in sizes) and header["TYPE"] == ["F"] * len(fields)
    kind = header["DATA"][0]
    cols = {}
    if kind == "binary_compressed":
        comp, raw = struct.unpack_from("<II", data, pos)
        buf = lzf_decompress(data[pos + 8:pos + 8 + comp], raw)
        off = 0
        for f in fields:  # column-major after decompression
            cols[f] = struct.unpack_from("<%df" % n, buf, off)
            off += 4 * n
    else:
        raise SystemExit("unexpected DATA " + kind)
    finite = [i for i in range(n) if all(math.isfinite(cols[a][i]) for a in "xyz")]
    lo = [min(cols[a][i] for i in finite) for a in "xyz"]
    hi = [max(cols[a][i] for i in finite) for a in "xyz"]
    print(f"{path.name}: WIDTH {header['WIDTH'][0]} HEIGHT {header['HEIGHT'][0]} POINTS {n} "
          f"finite {len(finite)} min {['%.4f' % v for v in lo]} max {['%.4f' % v for v in hi]}")


def ifc(path):
    c = Counter(m.group(1) for m in re.finditer(r"^#\d+\s*=\s*(IFC[A-Z0-9]+)\s*\(",
                                                path.read_text(errors="replace"), re.M))
    keys = ["IFCWALL", "IFCWALLSTANDARDCASE", "IFCWINDOW", "IFCDOOR", "IFCSLAB", "IFCBEAM",
            "IFCCOVERING", "IFCFOOTING", "IFCMEMBER", "IFCRAILING", "IFCPLATE", "IFCSTAIRFLIGHT",
            "IFCFURNISHINGELEMENT", "IFCCURTAINWALL", "IFCSPACE", "IFCOPENINGELEMENT"]
    schema = re.search(r"FILE_SCHEMA\s*\(\s*\(\s*'([^']+)'", path.read_text(errors="replace")).group(1)
    print(f"{path.name}: {schema} " + " ".join(f"{k}={c[k]}" for k in keys if c[k]))


if __name__ == "__main__":
    root = Path(sys.argv[1] if len(sys.argv) > 1 else "../shared/data")
    for p in sorted((root / "pcd").glob("*.pcd")):
        pcd(p)
    for p in sorted((root / "ifc").glob("*.ifc")):
        ifc(p)
