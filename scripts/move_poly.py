#!/usr/bin/env python3
"""Writes a .poly domain moved (and scaled) to where real data sits, e.g. UTM-like coordinates.

Usage: scripts/move_poly.py IN.poly OUT.poly [--shift DX DY] [--scale S]   (e.g. --shift 1000000 -3000000)

Each point (and hole seed) p becomes S p + (DX, DY), rounded to doubles; the segments are kept.
The result is checked exactly (scripts/stress/gen_domain.py's check): rounding may join or cross
what was apart, and such a file is refused (exit 1). Far from the origin a segment's Steiner
points can be placed only to within a few ulps, so this is how the segment snap is timed:
`acute mesh OUT.poly` against `acute mesh IN.poly`.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "stress"))
from gen_domain import check, read_poly, write_poly_file  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("--shift", nargs=2, type=float, default=(0.0, 0.0), metavar=("DX", "DY"))
    ap.add_argument("--scale", type=float, default=1.0)
    a = ap.parse_args()
    if os.path.abspath(a.input) == os.path.abspath(a.output):
        sys.exit("move_poly: the output would overwrite the input")
    pts, segs, holes, _ = read_poly(a.input)
    move = lambda p: (a.scale * p[0] + a.shift[0], a.scale * p[1] + a.shift[1])
    pts, holes = [move(p) for p in pts], [move(h) for h in holes]
    problem = check(pts, segs, [], [], allowed_on_segment=range(len(pts)))
    if problem:
        sys.exit(f"move_poly: {a.input} moved: {problem}")
    write_poly_file(a.output, [f"{os.path.basename(a.input)} scaled by {a.scale!r} and shifted by ({a.shift[0]!r}, {a.shift[1]!r})"],
                    pts, segs, holes)


if __name__ == "__main__":
    main()
