#!/usr/bin/env python3
# npy.py -- reads a .npy file with the standard library alone (struct, ast)
# and checks it against the text table the program wrote for the same run.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Usage: npy.py elements|surfaces FILE.npy TABLE.tsv N
# The format: NumPy Enhancement Proposal 1 and numpy/lib/format.py (magic
# "\x93NUMPY", version, little-endian header length, a dict literal padded
# so the data starts at a multiple of 64 bytes).  The values must equal the
# table's bit for bit (%.17g round-trips a double, C11 7.21.6.1 and
# DBL_DECIMAL_DIG = 17), and the table's text must be what Python's own
# correctly rounded formatter (David Gay's dtoa) prints for them: an
# independent check of the program's %.17g writer.
import ast
import struct
import sys

checks = []


def ok(cond, what):
    checks.append(bool(cond))
    print("%s %d - %s" % ("ok" if cond else "not ok", len(checks), what))


def bits(x):
    return struct.pack("<d", x)


def read_npy(path):
    with open(path, "rb") as f:
        raw = f.read()
    ok(raw[:6] == b"\x93NUMPY", "magic string \\x93NUMPY")
    ok(raw[6:8] == b"\x01\x00", "format version 1.0")
    (hlen,) = struct.unpack("<H", raw[8:10])
    header = raw[10:10 + hlen]
    ok((10 + hlen) % 64 == 0, "data starts at a multiple of 64 bytes (%d)" % (10 + hlen))
    ok(header.endswith(b"\n") and all(c < 128 for c in header), "header is ASCII ending in a newline")
    d = ast.literal_eval(header.decode("ascii"))
    ok(isinstance(d, dict) and sorted(d) == ["descr", "fortran_order", "shape"],
       "header is a dict of descr, fortran_order, shape")
    ok(d.get("descr") == "<f8", "descr '<f8' (little-endian float64)")
    shape = d.get("shape")
    ok(isinstance(shape, tuple) and len(shape) == 2, "shape %r is two-dimensional" % (shape,))
    rows, cols = shape
    data = raw[10 + hlen:]
    ok(len(data) == 8 * rows * cols, "data is rows x cols float64 (%d bytes)" % len(data))
    flat = struct.unpack("<%dd" % (rows * cols), data)
    if d.get("fortran_order"):
        a = [[flat[i + j * rows] for j in range(cols)] for i in range(rows)]
    else:
        a = [[flat[i * cols + j] for j in range(cols)] for i in range(rows)]
    return shape, a


def read_table(path):
    with open(path) as f:
        lines = f.read().splitlines()
    return lines[0].split("\t"), [l.split("\t") for l in lines[1:]]


def main():
    kind, npy, tsv, n = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
    shape, a = read_npy(npy)
    ok(shape == (n, n), "shape (%d, %d): %r" % (n, n, shape))
    head, rows = read_table(tsv)
    want_head = ["i", "j", "F"] if kind == "elements" else ["S", "K", "F"]
    ok(head[:3] == want_head, "table header starts %s" % " ".join(want_head))
    seen = set()
    same = text = 0
    for r in rows:
        i, j = int(r[0]), int(r[1])
        seen.add((i, j))
        same += bits(a[i][j]) == bits(float(r[2]))
        text += "%.17g" % a[i][j] == r[2]
    pairs = n * (n - 1) if kind == "elements" else n * n
    ok(len(rows) == pairs and len(seen) == pairs, "the table has every pair once (%d rows)" % len(rows))
    ok(same == len(rows), ".npy equals the table bit for bit in %d of %d entries" % (same, len(rows)))
    ok(text == len(rows), "the table's text is Python's '%%.17g' of the value in %d of %d" % (text, len(rows)))
    ok(all(a[i][i] == 0.0 for i in range(n)), "zero diagonal")
    # closure (Goral et al. 1984): what leaves i arrives somewhere in the
    # closed cube, so each row sums to 1; default accuracy's error is far
    # below 1e-6, and the columns of unequal elements miss 1 by 0.1 or more
    rows_ok = all(abs(sum(a[i]) - 1) < 1e-6 for i in range(n))
    ok(rows_ok, "row i (from element i) sums to 1 within 1e-6")
    cols_off = any(abs(sum(a[i][j] for i in range(n)) - 1) > 1e-3 for j in range(n))
    ok(kind == "surfaces" or cols_off, "columns do not all sum to 1 (the matrix is not its transpose)")
    try:
        import numpy
    except ImportError:
        print("# numpy not importable: numpy.load not tried")
    else:
        m = numpy.load(npy)
        ok(m.dtype == numpy.float64 and m.shape == (n, n), "numpy.load: float64, shape (%d, %d)" % (n, n))
        ok(all(m[i, j] == a[i][j] for i in range(n) for j in range(n)), "numpy.load: the same values")
    print("1..%d" % len(checks))
    return 0 if all(checks) else 1


if __name__ == "__main__":
    sys.exit(main())
