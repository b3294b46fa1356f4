#!/usr/bin/env python3
"""Decodes a fuzz_cdt input (see fuzz_cdt.cpp) into a Triangle .poly file, for reading and for
regression tests.   Usage: tests/fuzz/cdt_input_to_poly.py INPUT [OUT.poly]   (stdout by default)
The flags (convex hull, split crossings) are written in the comment line."""
import sys

SCALES = [1, 1, 2.0**-30, 2.0**30, 2.0**-60, 2.0**60, 1, 2.0**-20]
OFFSETS = [0, -8, 0, 0, 0, 0, 2.0**40, 2.0**-10]


def main():
    data = open(sys.argv[1], "rb").read()
    pos = 0

    def nxt():
        nonlocal pos
        b = data[pos] if pos < len(data) else 0
        pos += 1
        return b

    flags = nxt()
    grid = 4 << (2 * ((flags >> 2) & 3))
    mode = (flags >> 4) & 7
    scale, offset = SCALES[mode], OFFSETS[mode]
    n = 3 + nxt() % 18
    pts = [(offset + scale * (nxt() % grid), offset + scale * (nxt() % grid)) for _ in range(n)]
    m = nxt() % 24
    segs = []
    for _ in range(m):
        a, b = nxt() % n, nxt() % n
        if a != b:
            segs.append((a, b))
    holes = []
    for _ in range(nxt() % 3):
        x, y = nxt(), nxt()
        holes.append((offset + scale * (x % grid + 0.5), offset + scale * (y % grid + 0.5)))
    out = open(sys.argv[2], "w") if len(sys.argv) > 2 else sys.stdout
    out.write(f"# fuzz_cdt input: convex_hull={flags & 1} split_crossings={(flags >> 1) & 1}\n")
    out.write(f"{n} 2 0 0\n")
    for i, (x, y) in enumerate(pts):
        out.write(f"{i} {x!r} {y!r}\n")
    out.write(f"{len(segs)} 0\n")
    for i, (a, b) in enumerate(segs):
        out.write(f"{i} {a} {b}\n")
    out.write(f"{len(holes)}\n")
    for i, (x, y) in enumerate(holes):
        out.write(f"{i} {x!r} {y!r}\n")


if __name__ == "__main__":
    main()
