#!/usr/bin/env python3
"""Ten hand-made extreme shapes, written as Triangle .poly files (1-based), each checked exactly.

Usage: scripts/zoo/gen_extremes.py OUTDIR

Rectangles of aspect 100, 1,000 and 10,000; a 5,000-gon; a comb of 30 teeth 1:200; a star of 200
spikes; a spiral of 179 interior segments in a square; a hole 1e-3 from the outer boundary; and
two strips far narrower than the default spacing, which the size field does not resolve (README,
known weak points): a hole 1e-6 from the boundary, and two holes 1e-5 apart. Sweep them with
`scripts/sweep.py --extra '--time-limit 60' OUTDIR/*.poly`.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "stress"))
from gen_domain import check, write_poly_file  # noqa: E402


def loop(points, start=0):
    n = len(points)
    return [(start + i, start + (i + 1) % n) for i in range(n)]


def shapes():
    for aspect in (100, 1000, 10000):
        pts = [(0, 0), (aspect, 0), (aspect, 1), (0, 1)]
        yield f"rect{aspect}", pts, loop(pts), []
    for gap in (1e-3, 1e-6):
        outer = [(0, 0), (10, 0), (10, 10), (0, 10)]
        hole = [(2, gap), (8, gap), (8, 5), (2, 5)]
        yield f"nearhole{gap:g}", outer + hole, loop(outer) + loop(hole, 4), [(5, 2.5)]
    outer = [(0, 0), (10, 0), (10, 10), (0, 10)]
    h1 = [(2, 2), (5, 2), (5, 8), (2, 8)]
    h2 = [(5 + 1e-5, 2), (8, 2), (8, 8), (5 + 1e-5, 8)]
    yield "twoholes", outer + h1 + h2, loop(outer) + loop(h1, 4) + loop(h2, 8), [(3, 5), (7, 5)]
    n, pts = 200, []
    for i in range(n):
        a = 2 * math.pi * i / n
        pts.append((10 * math.cos(a), 10 * math.sin(a)))
        b = a + math.pi / n
        pts.append((3 * math.cos(b), 3 * math.sin(b)))
    yield "star200", pts, loop(pts), []
    pts, x = [(0, 0)], 0
    for _ in range(30):
        pts += [(x + 1, 0), (x + 1, 200), (x + 2, 200), (x + 2, 0)]
        x += 2
    pts += [(x + 1, 0), (x + 1, -5), (0, -5)]
    yield "longcomb", pts, loop(pts), []
    n = 5000
    pts = [(math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n)) for i in range(n)]
    yield "circle5000", pts, loop(pts), []
    outer = [(-20, -20), (20, -20), (20, 20), (-20, 20)]
    spiral = [(0.5 * t * math.cos(t), 0.5 * t * math.sin(t)) for t in (0.5 + 0.2 * k for k in range(180))]
    yield "spiral_constraint", outer + spiral, loop(outer) + [(4 + i, 5 + i) for i in range(len(spiral) - 1)], []


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.strip().splitlines()[2])
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for name, pts, segs, holes in shapes():
        problem = check(pts, segs, holes, [], range(len(pts)))
        if problem:
            sys.exit(f"gen_extremes: {name}: {problem}")
        write_poly_file(os.path.join(out, name + ".poly"), [f"{name} (scripts/zoo/gen_extremes.py)"], pts, segs, holes)


if __name__ == "__main__":
    main()
