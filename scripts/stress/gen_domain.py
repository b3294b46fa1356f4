#!/usr/bin/env python3
"""Random domains for stress runs, written as Triangle .poly files (1-based).

Usage: scripts/stress/gen_domain.py SEED OUT.poly      (deterministic in SEED)
       scripts/stress/gen_domain.py --check FILE.poly   (exact validity check, exit 1 if bad)

Each domain is an outer polygon (star-shaped, or a rectangle with many vertices on one line)
with some of: holes, interior segments (chords, chains of collinear points, a tree), nearly
collinear vertices (edges subdivided with offsets of 1e-15..1e-9 of their length), tiny features
beside large ones (holes, notches and segments at 1e-7..1e-4 of the domain size), isolated
interior points and points lying inside segments; then scaled by 1, 1e-8 or 1e8 (plus an
optional offset). The result is checked exactly (fractions): no duplicate points, no zero-length,
repeated, crossing or overlapping segments, every hole seed strictly inside its hole. A candidate
that fails is redrawn (the generator stays deterministic).
"""
import math
import random
import sys
from fractions import Fraction


# ---------------------------------------------------------------- exact checks

def orient(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def sgn(x):
    return (x > 0) - (x < 0)


def on_closed(p, a, b):
    """p on the closed segment ab, given collinear."""
    return min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def segments_conflict(a, b, c, d):
    """True when ab and cd cross, overlap, or one passes through an endpoint of the other that is
    not a shared endpoint. Touching at a shared endpoint is fine."""
    shared = {a, b} & {c, d}
    o1, o2, o3, o4 = sgn(orient(a, b, c)), sgn(orient(a, b, d)), sgn(orient(c, d, a)), sgn(orient(c, d, b))
    if o1 == o2 == 0:  # collinear
        if len(shared) == 2:
            return True  # repeated
        pts = sorted([a, b]) , sorted([c, d])
        lo = max(pts[0][0], pts[1][0])
        hi = min(pts[0][1], pts[1][1])
        if lo < hi:
            return True  # overlap of positive length
        return lo == hi and not shared  # touching end to end without a shared point index
    if shared:
        return False
    if o1 * o2 < 0 and o3 * o4 < 0:
        return True
    # an endpoint on the other segment's interior
    for p, (s, t), o in ((c, (a, b), o1), (d, (a, b), o2), (a, (c, d), o3), (b, (c, d), o4)):
        if o == 0 and on_closed(p, s, t):
            return True
    return False


def check(points, segments, holes, hole_loops, allowed_on_segment=()):
    """Returns '' when valid, else the first problem. hole_loops: point index loops per hole."""
    P = [(Fraction(x), Fraction(y)) for x, y in points]
    if any(not math.isfinite(c) for p in points for c in p):
        return "non-finite coordinate"
    if len(set(P)) != len(P):
        return "duplicate points"
    segs = []
    for i, (u, v) in enumerate(segments):
        if u == v or P[u] == P[v]:
            return f"segment {i}: zero length"
        segs.append((P[u], P[v]))
    # Sweep on x to prune pairs.
    order = sorted(range(len(segs)), key=lambda i: min(segs[i][0][0], segs[i][1][0]))
    active = []
    for i in order:
        a, b = segs[i]
        xlo = min(a[0], b[0])
        active = [j for j in active if max(segs[j][0][0], segs[j][1][0]) >= xlo]
        for j in active:
            c, d = segs[j]
            ylo1, yhi1 = min(a[1], b[1]), max(a[1], b[1])
            if max(c[1], d[1]) < ylo1 or min(c[1], d[1]) > yhi1:
                continue
            if segments_conflict(a, b, c, d):
                return f"segments {j} and {i} conflict"
        active.append(i)
    # Points strictly inside a segment are allowed only where we put them on purpose.
    allowed = set(allowed_on_segment)
    boxes = [(min(a[0], b[0]), min(a[1], b[1]), max(a[0], b[0]), max(a[1], b[1])) for a, b in segs]
    for k, p in enumerate(P):
        if k in allowed:
            continue
        for i, (a, b) in enumerate(segs):
            bx = boxes[i]
            if p[0] < bx[0] or p[0] > bx[2] or p[1] < bx[1] or p[1] > bx[3]:
                continue
            if p != a and p != b and orient(a, b, p) == 0:
                return f"point {k} inside segment {i}"
    for h, loop in zip(holes, hole_loops):
        q = (Fraction(h[0]), Fraction(h[1]))
        if not strictly_inside(q, [P[i] for i in loop]):
            return "hole seed not strictly inside its hole"
    return ""


def strictly_inside(q, poly):
    n = len(poly)
    inside = False
    for i in range(n):
        a, b = poly[i], poly[(i + 1) % n]
        if orient(a, b, q) == 0 and on_closed(q, a, b):
            return False
        if (a[1] > q[1]) != (b[1] > q[1]):
            x = a[0] + (q[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            if x > q[0]:
                inside = not inside
    return inside


# ---------------------------------------------------------------- building blocks

class Builder:
    def __init__(self):
        self.points, self.segments, self.holes, self.hole_loops = [], [], [], []
        self.on_segment = []  # indices of points deliberately inside a segment
        self.features = []

    def point(self, p):
        self.points.append((float(p[0]), float(p[1])))
        return len(self.points) - 1

    def loop(self, pts):
        idx = [self.point(p) for p in pts]
        for i in range(len(idx)):
            self.segments.append((idx[i], idx[(i + 1) % len(idx)]))
        return idx

    def chain(self, pts):
        idx = [self.point(p) for p in pts]
        for i in range(len(idx) - 1):
            self.segments.append((idx[i], idx[i + 1]))
        return idx


def star(rng, cx, cy, r, n, rmin=0.45):
    angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
    return [(cx + r * rng.uniform(rmin, 1) * math.cos(t), cy + r * rng.uniform(rmin, 1) * math.sin(t)) for t in angles]


def subdivide_nearly_collinear(rng, pts, prob, eps):
    """Insert points along edges, offset perpendicular by eps * length (nearly collinear)."""
    out = []
    for i, a in enumerate(pts):
        b = pts[(i + 1) % len(pts)]
        out.append(a)
        if rng.random() < prob:
            k = rng.randint(1, 4)
            dx, dy = b[0] - a[0], b[1] - a[1]
            for j in range(1, k + 1):
                t = j / (k + 1)
                off = eps * rng.choice((-1, 0, 1))
                out.append((a[0] + t * dx - off * dy, a[1] + t * dy + off * dx))
    return out


def seg_dist(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    L = dx * dx + dy * dy
    t = 0 if L == 0 else max(0, min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)


def clearance(b, p):
    d = min((seg_dist(p, b.points[u], b.points[v]) for u, v in b.segments), default=1e9)
    return min([d] + [math.hypot(p[0] - q[0], p[1] - q[1]) for q in b.points])


def inside_float(p, poly):
    return strictly_inside((Fraction(p[0]), Fraction(p[1])), [(Fraction(x), Fraction(y)) for x, y in poly])


def random_inside(rng, b, outer, box, min_clear, tries=200):
    for _ in range(tries):
        p = (rng.uniform(box[0], box[2]), rng.uniform(box[1], box[3]))
        if inside_float(p, outer) and clearance(b, p) > min_clear and not any(inside_float(p, b.points_of(l)) for l in b.hole_loops):
            return p
    return None


Builder.points_of = lambda self, loop: [self.points[i] for i in loop]


def build(rng):
    b = Builder()
    R = 1.0
    # Outer boundary.
    if rng.random() < 0.35:
        n_line = rng.choice((20, 100, 400))
        w, h = 2.0, rng.choice((0.5, 1.0, 2.0))
        # Bottom edge with many exactly collinear vertices (x multiples of a power of two on y=0).
        step = w / n_line
        outer = [(i * step, 0.0) for i in range(n_line)] + [(w, 0.0), (w, h), (0.0, h)]
        b.features.append(f"{n_line + 1} vertices on one line")
    else:
        outer = star(rng, 0, 0, R, rng.randint(5, 40))
        b.features.append("star outer")
    if rng.random() < 0.4:
        eps = rng.choice((1e-15, 1e-12, 1e-9))
        outer = subdivide_nearly_collinear(rng, outer, 0.5, eps)
        b.features.append(f"nearly collinear {eps:g}")
    if rng.random() < 0.25:
        # A tiny notch on the longest edge: a feature 1e-7..1e-4 of the domain size.
        tiny = rng.choice((1e-7, 1e-6, 1e-5, 1e-4))
        i = max(range(len(outer)), key=lambda k: math.dist(outer[k], outer[(k + 1) % len(outer)]))
        a, c = outer[i], outer[(i + 1) % len(outer)]
        L = math.dist(a, c)
        ux, uy = (c[0] - a[0]) / L, (c[1] - a[1]) / L
        m = (a[0] + 0.5 * (c[0] - a[0]), a[1] + 0.5 * (c[1] - a[1]))
        notch = [(m[0] - tiny * ux, m[1] - tiny * uy), (m[0] - uy * tiny * 0.5, m[1] + ux * tiny * 0.5),  # inward (ccw)
                 (m[0] + tiny * ux, m[1] + tiny * uy)]
        outer = outer[:i + 1] + notch + outer[i + 1:]
        b.features.append(f"tiny notch {tiny:g}")
    b.loop(outer)
    xs, ys = [p[0] for p in outer], [p[1] for p in outer]
    box = (min(xs), min(ys), max(xs), max(ys))
    size = max(box[2] - box[0], box[3] - box[1])

    # Holes.
    for _ in range(rng.choice((0, 0, 1, 2, 3))):
        tiny_hole = rng.random() < 0.3
        c = random_inside(rng, b, outer, box, size * (1e-4 if tiny_hole else 0.08))
        if c is None:
            continue
        r = clearance(b, c) * (rng.uniform(1e-3, 1e-2) if tiny_hole else rng.uniform(0.3, 0.6))
        pts = star(rng, c[0], c[1], r, rng.randint(3, 12), rmin=0.7)
        # The hole's centre is inside (star-shaped with rmin 0.7 around it).
        loop = b.loop(pts)
        b.holes.append(c)
        b.hole_loops.append(loop)
        b.features.append("tiny hole" if tiny_hole else "hole")

    # Interior segments: chords between free points, a collinear chain, a small tree.
    for _ in range(rng.choice((0, 1, 2, 4))):
        p = random_inside(rng, b, outer, box, size * 0.02)
        if p is None:
            continue
        L = clearance(b, p) * rng.choice((0.9, 0.5, 1e-3, 1e-6))
        t = rng.uniform(0, 2 * math.pi)
        q = (p[0] + L * math.cos(t), p[1] + L * math.sin(t))
        b.chain([p, q])
        b.features.append("interior segment" if L > size * 1e-4 else "tiny interior segment")
    if rng.random() < 0.3:
        p = random_inside(rng, b, outer, box, size * 0.05)
        if p is not None:
            L = clearance(b, p) * 0.9
            k = rng.choice((5, 30, 150))
            # Exactly collinear horizontal chain: y constant.
            b.chain([(p[0] - L + 2 * L * j / k, p[1]) for j in range(k + 1)])
            b.features.append(f"collinear chain of {k + 1}")
    if rng.random() < 0.2:
        p = random_inside(rng, b, outer, box, size * 0.05)
        if p is not None:
            L = clearance(b, p) * 0.45
            centre = b.point(p)
            for j in range(rng.randint(2, 5)):
                t = 2 * math.pi * j / 5 + rng.uniform(0, 0.5)
                leaf = b.point((p[0] + L * math.cos(t), p[1] + L * math.sin(t)))
                b.segments.append((centre, leaf))
            b.features.append("segment tree")
    for _ in range(rng.choice((0, 0, 3, 20))):
        p = random_inside(rng, b, outer, box, size * 1e-6)
        if p is not None:
            b.point(p)
    if rng.random() < 0.2:
        # A point exactly at the middle of a horizontal (or vertical) segment, if there is one.
        hv = [s for s in b.segments if b.points[s[0]][1] == b.points[s[1]][1] or b.points[s[0]][0] == b.points[s[1]][0]]
        if hv:
            u, v = rng.choice(hv)
            m = (0.5 * (b.points[u][0] + b.points[v][0]), 0.5 * (b.points[u][1] + b.points[v][1]))
            if m not in b.points:
                b.on_segment.append(b.point(m))
                b.features.append("point inside a segment")

    # Scale (and offset): tiny or huge coordinates.
    scale = rng.choice((1.0, 1.0, 1e-8, 1e8))
    offset = rng.choice((0.0, 0.0, 3.0 * scale, -1e3 * scale))
    if scale != 1.0 or offset != 0.0:
        b.points = [(x * scale + offset, y * scale + offset) for x, y in b.points]
        b.holes = [(x * scale + offset, y * scale + offset) for x, y in b.holes]
        b.features.append(f"scale {scale:g} offset {offset:g}")
    return b


def write_poly_file(path, comments, points, segments, holes, vertex_markers=False):
    """Writes a 1-based .poly: `comments` as leading `# ` lines, then the points (with a 0 marker
    each when vertex_markers), the segments (marker 1) and the hole seeds. Shared with
    scripts/zoo/gen_zoo.py."""
    with open(path, "w") as f:
        for c in comments:
            f.write(f"# {c}\n")
        f.write(f"{len(points)} 2 0 {1 if vertex_markers else 0}\n")
        for i, (x, y) in enumerate(points, 1):
            f.write(f"{i} {x!r} {y!r}{' 0' if vertex_markers else ''}\n")
        f.write(f"{len(segments)} 1\n")
        for i, (u, v) in enumerate(segments, 1):
            f.write(f"{i} {u + 1} {v + 1} 1\n")
        f.write(f"{len(holes)}\n")
        for i, (x, y) in enumerate(holes, 1):
            f.write(f"{i} {x!r} {y!r}\n")


def write_poly(path, b, seed):
    write_poly_file(path, [f"stress domain, seed {seed}: {', '.join(b.features)}"], b.points, b.segments, b.holes, vertex_markers=True)


def generate(seed):
    for attempt in range(50):
        rng = random.Random(seed * 1000003 + attempt)
        b = build(rng)
        problem = check(b.points, b.segments, b.holes, b.hole_loops, b.on_segment)
        if not problem:
            return b
    raise SystemExit(f"seed {seed}: no valid domain in 50 attempts (last: {problem})")


def read_poly(path):
    """Minimal .poly reader (1-based or 0-based indices, no .node): points, segments and hole seeds
    (0-based), and the hole loops given as `# hole K loop: i j ...` comments (gen_zoo.py writes
    them; empty when there are none). Shared with scripts/zoo/gen_zoo.py."""
    rows, loops = [], {}
    for line in open(path):
        if line.startswith("# hole ") and " loop:" in line:
            head, body = line[1:].split(":", 1)
            loops[int(head.split()[1])] = [int(t) for t in body.split()]
        line = line.split("#")[0].split()
        if line:
            rows.append(line)
    it = iter(rows)
    n = int(next(it)[0])
    pts, first = [], None
    for _ in range(n):
        r = next(it)
        first = int(r[0]) if first is None else first
        pts.append((float(r[1]), float(r[2])))
    m = int(next(it)[0])
    segs = [(int(r[1]) - first, int(r[2]) - first) for r in (next(it) for _ in range(m))]
    nh = int(next(it)[0])
    holes = [(float(r[1]), float(r[2])) for r in (next(it) for _ in range(nh))]
    hole_loops = [[i - first for i in loops[k]] for k in sorted(loops)]
    return pts, segs, holes, hole_loops


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--check":
        pts, segs, holes, _ = read_poly(sys.argv[2])
        problem = check(pts, segs, [], [], allowed_on_segment=range(len(pts)))
        print(problem or "ok")
        sys.exit(1 if problem else 0)
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    seed = int(sys.argv[1])
    write_poly(sys.argv[2], generate(seed), seed)


if __name__ == "__main__":
    main()
