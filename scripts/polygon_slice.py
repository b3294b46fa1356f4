#!/usr/bin/env python3
"""Cuts a wedge out of a star-shaped polygon: its first N+1 vertices and a centre, as a new .poly.

Usage: scripts/polygon_slice.py DOMAIN.poly N OUT.poly [--centre X Y] [--first K]

debug2 (10,000 vertices 0.036 degrees apart round the origin) is too large to experiment on: its
features ask ~4M vertices. A slice of N consecutive vertices closed at the origin keeps the same
strips and spikes at N / 10,000 of the size (N = 250: a 9-degree wedge, ~110k vertices at the
domain's own size field), so a change to the start or the repair can be judged in a minute.
Only single-polygon .poly files whose segments join consecutive vertices are meaningful input.
"""
import argparse, os, sys, tempfile


def read_poly_points(path):
    rows = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            if line: rows.append(line)
    n = int(rows[0][0])
    return [(rows[1 + i][1], rows[1 + i][2]) for i in range(n)]  # coordinates kept as text


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("domain")
    ap.add_argument("n", type=int, help="vertices of the slice's outer chain, minus one")
    ap.add_argument("out")
    ap.add_argument("--centre", nargs=2, default=["0", "0"], metavar=("X", "Y"))
    ap.add_argument("--first", type=int, default=0, help="0-based index of the slice's first vertex (default 0)")
    a = ap.parse_args()
    if os.path.exists(a.out) and os.path.samefile(a.out, a.domain):
        sys.exit(f"polygon_slice: {a.out}: the output would overwrite the input")
    try:
        points = read_poly_points(a.domain)
    except (OSError, ValueError, IndexError) as e:
        sys.exit(f"polygon_slice: {a.domain}: not a readable .poly with its vertices inline ({e})")
    if not 2 <= a.n < len(points):
        sys.exit(f"polygon_slice: {a.domain}: N must be in [2, {len(points) - 1}]")
    if not 0 <= a.first < len(points):
        sys.exit(f"polygon_slice: {a.domain}: --first must be in [0, {len(points) - 1}]")
    chain = [tuple(a.centre)] + [points[(a.first + i) % len(points)] for i in range(a.n + 1)]
    # Written beside the output, then renamed over it: never a half-written .poly.
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(os.path.abspath(a.out)), suffix=".poly.tmp")
    with os.fdopen(fd, "w") as f:
        f.write(f"# The centre ({a.centre[0]}, {a.centre[1]}) and vertices {a.first + 1}..{a.first + a.n + 1} (1-based, cyclic)"
                f" of {a.domain} (scripts/polygon_slice.py).\n")
        f.write(f"{len(chain)} 2 0 0\n")
        for i, (x, y) in enumerate(chain): f.write(f"{i + 1} {x} {y}\n")
        f.write(f"{len(chain)} 0\n")
        for i in range(len(chain)): f.write(f"{i + 1} {i + 1} {(i + 1) % len(chain) + 1}\n")
        f.write("0\n")
    os.replace(tmp, a.out)

if __name__ == "__main__":
    main()
