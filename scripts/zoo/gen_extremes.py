#!/usr/bin/env python3
"""Ten hand-made extreme shapes, written as Triangle .poly files (1-based), each checked exactly.

Usage: scripts/zoo/gen_extremes.py OUTDIR

Rectangles of aspect 100, 1,000 and 10,000; a 5,000-gon; a comb of 30 teeth 1:200; a star of 200
spikes; a spiral of 179 interior segments in a square; a hole 1e-3 from the outer boundary; and
two strips far narrower than the default spacing, which the size field does not resolve (README,
known weak points): a hole 1e-6 from the boundary, and two holes 1e-5 apart. Built and checked
with gen_zoo.py's Domain (kept apart from the zoo: the two strips are known misses). Sweep them
with `scripts/sweep.py --extra '--time-limit 60' OUTDIR/*.poly`.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gen_zoo import Domain, circle, write_poly  # noqa: E402


def domains():
    out = []
    for aspect in (100, 1000, 10000):
        d = Domain(f"rect{aspect}", f"rectangle {aspect} x 1")
        d.loop([(0, 0), (aspect, 0), (aspect, 1), (0, 1)])
        out.append(d)
    square = [(0, 0), (10, 0), (10, 10), (0, 10)]
    for gap in (1e-3, 1e-6):
        d = Domain(f"nearhole{gap:g}", f"square 10 with a 6 x 5 hole {gap:g} from its lower side")
        d.loop(square)
        d.hole([(2, gap), (8, gap), (8, 5), (2, 5)], (5, 2.5))
        out.append(d)
    d = Domain("twoholes", "square 10 with two 3 x 6 holes 1e-5 apart")
    d.loop(square)
    d.hole([(2, 2), (5, 2), (5, 8), (2, 8)], (3, 5))
    d.hole([(5 + 1e-5, 2), (8, 2), (8, 8), (5 + 1e-5, 8)], (7, 5))
    out.append(d)
    d = Domain("star200", "star of 200 spikes, radii 10 and 3")
    d.loop([p for k in range(200) for p in (circle(0, 0, 10, 200)[k], circle(0, 0, 3, 200, math.pi / 200)[k])])
    out.append(d)
    d = Domain("longcomb", "comb of 30 teeth 1 wide and 200 long, 1 apart")
    pts, x = [(0, 0)], 0
    for _ in range(30):
        pts += [(x + 1, 0), (x + 1, 200), (x + 2, 200), (x + 2, 0)]
        x += 2
    d.loop(pts + [(x + 1, 0), (x + 1, -5), (0, -5)])
    out.append(d)
    d = Domain("circle5000", "5,000-gon of radius 1")
    d.loop(circle(0, 0, 1, 5000))
    out.append(d)
    d = Domain("spiral_constraint", "square 40 with a spiral chain of 179 interior segments")
    d.loop([(-20, -20), (20, -20), (20, 20), (-20, 20)])
    d.chain([(0.5 * t * math.cos(t), 0.5 * t * math.sin(t)) for t in (0.5 + 0.2 * k for k in range(180))])
    out.append(d)
    return out


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.strip().splitlines()[2])
    os.makedirs(sys.argv[1], exist_ok=True)
    for d in domains():
        problem = d.problem()
        if problem:
            sys.exit(f"gen_extremes: {d.name}: {problem}")
        write_poly(os.path.join(sys.argv[1], d.name + ".poly"), d)


if __name__ == "__main__":
    main()
