#!/usr/bin/env python3
"""A zoo of structured test domains, written as Triangle .poly files (1-based).

Usage: scripts/zoo/gen_zoo.py OUTDIR             write every domain (each is checked first)
       scripts/zoo/gen_zoo.py --check [FILE...]  check the given .poly files exactly, or, with no
                                                 file, every domain built in memory; exit 1 if bad
       scripts/zoo/gen_zoo.py --list              print the file names

The random stress generator (scripts/stress/gen_domain.py) draws star polygons; this one builds,
deterministically, the structured shapes it never makes: combs of narrow slits, spiral corridors,
Koch snowflakes, gears with a hole, perforated plates, thin annuli, rectilinear mazes (interior
walls meeting in T-junctions), corners at and near the angle bounds (30, 60, 90, 120 and 180
degrees, +-0.1), interior constraint grids, isolated points (a jittered grid and a cluster 1e-4
apart), thin rectangles and a thin L, holes 1e-3 of the size from the outer boundary, and trees
of interior segments with 10 degree forks. A few are scaled by 1e-6 or translated by 1e6.

Every domain is validated exactly (fractions, with scripts/stress/gen_domain.py's `check`): no
duplicate points, no zero-length, repeated, crossing or overlapping segments, no point inside a
segment (segments are split wherever they meet), every hole seed strictly inside its hole loop.
The hole loops are written as comments (`# hole 1 loop: 5 6 7 ...`, 1-based) so that `--check
FILE` can verify the seeds of a written file too.
"""
import math
import os
import random
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "stress"))
from gen_domain import check, read_poly, write_poly_file  # noqa: E402  (exact validity check, fractions; .poly files)


class Domain:
    def __init__(self, name, note):
        self.name, self.note = name, note
        self.points, self.index = [], {}
        self.segments, self.holes, self.hole_loops = [], [], []

    def point(self, p):
        """Index of point p, added once (exact float equality merges shared vertices)."""
        p = (float(p[0]), float(p[1]))
        if p not in self.index:
            self.index[p] = len(self.points)
            self.points.append(p)
        return self.index[p]

    def loop(self, pts):
        idx = [self.point(p) for p in pts]
        assert len(set(idx)) == len(idx), f"{self.name}: repeated point in a loop"
        for i in range(len(idx)):
            self.segments.append((idx[i], idx[(i + 1) % len(idx)]))
        return idx

    def chain(self, pts):
        idx = [self.point(p) for p in pts]
        for i in range(len(idx) - 1):
            self.segments.append((idx[i], idx[i + 1]))
        return idx

    def segment(self, p, q):
        self.segments.append((self.point(p), self.point(q)))

    def hole(self, pts, seed):
        self.hole_loops.append(self.loop(pts))
        self.holes.append((float(seed[0]), float(seed[1])))

    def transform(self, scale=1.0, offset=(0.0, 0.0)):
        """Scale then translate every point and seed (points that coincide after rounding would
        show up as duplicates in the check)."""
        f = lambda p: (p[0] * scale + offset[0], p[1] * scale + offset[1])
        self.points = [f(p) for p in self.points]
        self.holes = [f(p) for p in self.holes]
        self.index = {p: i for i, p in enumerate(self.points)}
        return self

    def problem(self):
        p = check(self.points, self.segments, self.holes, self.hole_loops)
        if p:
            return p
        return loops_problem(self.segments, self.hole_loops)


def loops_problem(segments, hole_loops):
    """Every hole loop is a closed cycle of listed segments."""
    have = {frozenset(s) for s in segments}
    for h, loop in enumerate(hole_loops):
        for i in range(len(loop)):
            if frozenset((loop[i], loop[(i + 1) % len(loop)])) not in have:
                return f"hole {h + 1}: its loop is not closed by segments"
    return ""


def circle(cx, cy, r, n, phase=0.0):
    return [(cx + r * math.cos(phase + 2 * math.pi * k / n), cy + r * math.sin(phase + 2 * math.pi * k / n)) for k in range(n)]


def fmt(x):
    """Short number for file names: 0.02, 1e-6, 1e6."""
    return f"{x:g}".replace("e-0", "e-").replace("e+0", "e").replace("e+", "e")


# ---------------------------------------------------------------- families

def comb(teeth, gap, scale=1.0, both=False):
    """A 100 x 40 rectangle with `teeth` slits of width gap*100 cut 3/4 deep from the top (and,
    with both, as many from the bottom between them: a serpentine)."""
    W, H = 100.0, 40.0
    w, depth = gap * W, 0.75 * H
    name = f"comb{'_both' if both else ''}_teeth{teeth}_gap{fmt(gap)}" + (f"_scale{fmt(scale)}" if scale != 1 else "")
    d = Domain(name, f"rectangle {W:g} x {H:g}, {teeth} slits of width {w:g} and depth {depth:g}" + (" from both sides" if both else ""))
    pitch = W / (teeth + 1)
    bottom = [(0.0, 0.0)]
    if both:
        for k in range(teeth + 1):
            if k == 0 or k == teeth:
                continue
            x = pitch * (k + 0.5)
            xl, xr = x - w / 2, x + w / 2
            bottom += [(xl, 0.0), (xl, depth), (xr, depth), (xr, 0.0)]
    bottom.append((W, 0.0))
    top = [(W, H)]
    for k in range(teeth, 0, -1):
        x = pitch * k
        xl, xr = x - w / 2, x + w / 2
        top += [(xr, H), (xr, H - depth), (xl, H - depth), (xl, H)]
    top.append((0.0, H))
    d.loop(bottom + top)
    return d.transform(scale)


def spiral_rect(turns, width, scale):
    """A corridor of constant width along a square spiral (arms 1 apart), times `scale`."""
    d = Domain(f"spiral_rect_turns{turns}_w{fmt(width)}", f"square spiral corridor, {turns} turns, arms 1 apart, width {width:g}, scale {scale:g}")
    dirs = [(1, 0), (0, 1), (-1, 0), (0, -1)]
    pts, x, y = [(0, 0)], 0, 0
    for k in range(4 * turns):
        L = k // 2 + 1
        x, y = x + dirs[k % 4][0] * L, y + dirs[k % 4][1] * L
        pts.append((x, y))
    d.loop(corridor(pts, width))
    return d.transform(scale)


def spiral_angular(turns, width, sides, scale):
    """A corridor along a polygonal spiral r = 1 + theta / 2pi, `sides` vertices a turn."""
    d = Domain(f"spiral_{sides}gon_turns{turns}_w{fmt(width)}", f"{sides}-gon spiral corridor, {turns} turns, pitch 1, width {width:g}, scale {scale:g}")
    pts = []
    for k in range(sides * turns + 1):
        t = 2 * math.pi * k / sides
        r = 1 + t / (2 * math.pi)
        pts.append((r * math.cos(t), r * math.sin(t)))
    d.loop(corridor(pts, width))
    return d.transform(scale)


def corridor(center, width):
    """The polygon of the band of the given width around an open polyline (mitred corners)."""
    h = width / 2
    left, right = [], []
    n = len(center)
    for i, p in enumerate(center):
        dirs = []
        if i > 0:
            dirs.append(unit(center[i - 1], p))
        if i < n - 1:
            dirs.append(unit(p, center[i + 1]))
        normals = [(-dy, dx) for dx, dy in dirs]
        if len(normals) == 1:
            mx, my = normals[0]
        else:
            (ax, ay), (bx, by) = normals
            c = 1 + ax * bx + ay * by
            mx, my = (ax + bx) / c, (ay + by) / c
        left.append((p[0] + h * mx, p[1] + h * my))
        right.append((p[0] - h * mx, p[1] - h * my))
    return right + left[::-1]


def unit(a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    L = math.hypot(dx, dy)
    return dx / L, dy / L


def koch(level, scale=1.0):
    """Koch snowflake from an equilateral triangle of side 100 (corners of 60 and 240 degrees)."""
    s = 100.0
    pts = [(0.0, 0.0), (s, 0.0), (s / 2, s * math.sqrt(3) / 2)]
    pts = pts[::-1]  # clockwise, so the bumps (to the left of each edge... see below) point outward
    for _ in range(level):
        out = []
        for i, a in enumerate(pts):
            b = pts[(i + 1) % len(pts)]
            dx, dy = (b[0] - a[0]) / 3, (b[1] - a[1]) / 3
            p1 = (a[0] + dx, a[1] + dy)
            p2 = (a[0] + 2 * dx, a[1] + 2 * dy)
            # Rotate the middle third by +60 degrees (to the left of a clockwise edge: outward).
            c, sn = 0.5, math.sqrt(3) / 2
            peak = (p1[0] + c * dx - sn * dy, p1[1] + sn * dx + c * dy)
            out += [a, p1, peak, p2]
        pts = out
    name = f"koch_level{level}" + (f"_scale{fmt(scale)}" if scale != 1 else "")
    d = Domain(name, f"Koch snowflake level {level}, side 100, {len(pts)} vertices")
    d.loop(pts[::-1])
    return d.transform(scale)


def gear(teeth, hole_frac, hole_n=48):
    """Root radius 40, tip radius 50, trapezoidal teeth; a central hole (polygon) of radius
    hole_frac * 40."""
    Rr, Rt = 40.0, 50.0
    d = Domain(f"gear_teeth{teeth}_hole{fmt(hole_frac)}", f"gear, {teeth} trapezoidal teeth, root radius {Rr:g}, tip {Rt:g}, central {hole_n}-gon hole radius {hole_frac * Rr:g}")
    pts = []
    for k in range(teeth):
        for f, R in ((0.0, Rr), (0.4, Rr), (0.5, Rt), (0.9, Rt)):
            t = 2 * math.pi * (k + f) / teeth
            pts.append((R * math.cos(t), R * math.sin(t)))
    d.loop(pts)
    d.hole(circle(0, 0, hole_frac * Rr, hole_n)[::-1], (0.0, 0.0))
    return d


def plate(cols, rows, gap, n):
    """Holes (regular n-gons, radius 2) in a grid, gap*2 apart vertex to vertex, gap*2 from the
    border."""
    r = 2.0
    g = gap * r
    pitch = 2 * r + g
    W, H = cols * pitch + g, rows * pitch + g
    d = Domain(f"plate_holes{cols}x{rows}_gap{fmt(gap)}_n{n}", f"perforated plate {W:g} x {H:g}, {cols * rows} {n}-gon holes of radius {r:g}, gap {g:g}")
    d.loop([(0.0, 0.0), (W, 0.0), (W, H), (0.0, H)])
    for i in range(cols):
        for j in range(rows):
            cx, cy = g + r + i * pitch, g + r + j * pitch
            d.hole(circle(cx, cy, r, n)[::-1], (cx, cy))
    return d


def annulus(n, gap, phase_half=False, offset=0.0):
    """Two concentric n-gons, radius 50 and 50 (1 - gap); the inner one is a hole."""
    R = 50.0
    name = f"annulus_n{n}_gap{fmt(gap)}" + ("_staggered" if phase_half else "") + (f"_translate{fmt(offset)}" if offset else "")
    d = Domain(name, f"thin annulus: {n}-gons of radius {R:g} and {R * (1 - gap):g}" + (", inner one turned by half a step" if phase_half else ""))
    d.loop(circle(0, 0, R, n))
    d.hole(circle(0, 0, R * (1 - gap), n, math.pi / n if phase_half else 0.0)[::-1], (0.0, 0.0))
    return d.transform(1.0, (offset, offset))


def maze(cols, rows, cell, seed):
    """A perfect maze (randomized depth-first search, deterministic in seed): the rectangle, and
    the walls that remain as interior constraint segments, split at every junction."""
    rng = random.Random(seed)
    d = Domain(f"maze_{cols}x{rows}", f"rectilinear maze {cols} x {rows} cells of {cell:g}, seed {seed}; walls are interior segments")
    # Walls between cells: vertical wall (i, j) between cell (i-1, j) and (i, j); horizontal (i, j) between (i, j-1) and (i, j).
    vwalls = {(i, j) for i in range(1, cols) for j in range(rows)}
    hwalls = {(i, j) for i in range(cols) for j in range(1, rows)}
    seen, stack = {(0, 0)}, [(0, 0)]
    while stack:
        c = stack[-1]
        nbrs = [(c[0] + dx, c[1] + dy) for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1))
                if 0 <= c[0] + dx < cols and 0 <= c[1] + dy < rows and (c[0] + dx, c[1] + dy) not in seen]
        if not nbrs:
            stack.pop()
            continue
        n = rng.choice(nbrs)
        if n[0] != c[0]:
            vwalls.discard((max(n[0], c[0]), c[1]))
        else:
            hwalls.discard((c[0], max(n[1], c[1])))
        seen.add(n)
        stack.append(n)
    # Unit wall edges between grid nodes.
    edges = [((i, j), (i, j + 1)) for i, j in vwalls] + [((i, j), (i + 1, j)) for i, j in hwalls]
    adj = {}
    for a, b in edges:
        adj.setdefault(a, []).append(b)
        adj.setdefault(b, []).append(a)
    on_border = lambda p: p[0] in (0, cols) or p[1] in (0, rows)

    def breaks(p):  # a junction, an end, a corner, or a point on the border: segments end there
        nb = adj[p]
        return len(nb) != 2 or on_border(p) or (nb[0][0] - p[0], nb[0][1] - p[1]) != (p[0] - nb[1][0], p[1] - nb[1][1])

    # Outer boundary: corners plus the border nodes that walls touch (counter-clockwise).
    border = set(p for p in adj if on_border(p)) | {(0, 0), (cols, 0), (cols, rows), (0, rows)}
    key = lambda p: (0, p[0]) if p[1] == 0 and p[0] < cols else (1, p[1]) if p[0] == cols and p[1] < rows else \
        (2, -p[0]) if p[1] == rows and p[0] > 0 else (3, -p[1])
    d.loop([(p[0] * cell, p[1] * cell) for p in sorted(border, key=key)])
    # Maximal straight runs of wall edges between break points.
    done = set()
    for a, b in edges:
        if frozenset((a, b)) in done:
            continue
        run = [a, b]
        done.add(frozenset((a, b)))
        for end in (0, 1):
            while not breaks(run[-1] if end else run[0]):
                p = run[-1] if end else run[0]
                q = run[-2] if end else run[1]
                nxt = [x for x in adj[p] if x != q][0]
                done.add(frozenset((p, nxt)))
                if end:
                    run.append(nxt)
                else:
                    run.insert(0, nxt)
        d.segment((run[0][0] * cell, run[0][1] * cell), (run[-1][0] * cell, run[-1][1] * cell))
    return d


def isosceles(apex_deg):
    """Isosceles triangle with the given apex angle (legs 100)."""
    d = Domain(f"sharp_apex{fmt(apex_deg)}", f"isosceles triangle, apex {apex_deg:g} degrees, legs 100, base angles {(180 - apex_deg) / 2:g}")
    h = math.radians(apex_deg) / 2
    d.loop([(0.0, 0.0), (100 * math.cos(h), -100 * math.sin(h)), (100 * math.cos(h), 100 * math.sin(h))])
    return d


def sharp_quad():
    """A quadrilateral with corners of 90, 90.1, 90 and 89.9 degrees."""
    d = Domain("sharp_quad_90_90.1_90_89.9", "quadrilateral, corners 90 (0,0), 90.1 (100,0), 90, 89.9 (0,100)")
    a1, a3 = math.radians(89.9), math.radians(-0.1)
    # P2 = (100,0) + s (cos a1, sin a1) = (0,100) + t (cos a3, sin a3)
    det = math.cos(a1) * (-math.sin(a3)) + math.sin(a1) * math.cos(a3)
    s = ((0 - 100) * (-math.sin(a3)) + (100 - 0) * math.cos(a3)) / det
    d.loop([(0.0, 0.0), (100.0, 0.0), (100 + s * math.cos(a1), s * math.sin(a1)), (0.0, 100.0)])
    return d


def hexagon():
    d = Domain("sharp_hexagon_120", "regular hexagon, radius 50: six corners of 120 degrees")
    d.loop(circle(0, 0, 50, 6))
    return d


def near_straight(angle):
    """A 100 x 30 rectangle whose bottom edge is bent at x = 50 to the given interior angle."""
    d = Domain(f"sharp_bend{fmt(angle)}", f"rectangle 100 x 30 with the bottom edge bent at its middle: interior angle {angle:g}" + (" (reflex)" if angle > 180 else ""))
    y = 50 * math.tan(math.radians(angle - 180) / 2)
    d.loop([(0.0, 0.0), (50.0, y), (100.0, 0.0), (100.0, 30.0), (0.0, 30.0)])
    return d


def star_tips(n, tip_deg):
    """A star with n tips of the given angle (outer radius 50)."""
    R, b, t = 50.0, math.radians(tip_deg) / 2, math.pi / n
    r = R * math.tan(b) / (math.sin(t) + math.tan(b) * math.cos(t))
    d = Domain(f"sharp_star{n}_tip{fmt(tip_deg)}", f"star with {n} tips of {tip_deg:g} degrees, radii {R:g} and {r:.6g}")
    pts = []
    for k in range(n):
        pts.append((R * math.cos(2 * t * k), R * math.sin(2 * t * k)))
        pts.append((r * math.cos(2 * t * k + t), r * math.sin(2 * t * k + t)))
    d.loop(pts)
    return d


def cgrid_touching(k):
    """Square 100 with k vertical and k horizontal interior segments from side to side, split at
    every crossing and at the border."""
    d = Domain(f"cgrid_lines{k}_touching", f"square 100, interior grid of {k} x {k} lines reaching the border, split at crossings")
    xs = [100 * (i + 1) / (k + 1) for i in range(k)]
    ticks = [0.0] + xs + [100.0]
    d.loop([(x, 0.0) for x in ticks[:-1]] + [(100.0, y) for y in ticks[:-1]] + [(x, 100.0) for x in ticks[:0:-1]] + [(0.0, y) for y in ticks[:0:-1]])
    for x in xs:
        d.chain([(x, y) for y in ticks])
        d.chain([(y, x) for y in ticks])
    return d


def cgrid_floating(k, angle_deg):
    """Square 100 with a k x k grid of interior segments (spacing 70/k, centred, turned by
    angle_deg) that stops short of the border: each line has stubs of half a spacing beyond the
    outermost crossings. Crossing points are computed once and shared."""
    d = Domain(f"cgrid_lines{k}_floating" + (f"_rot{fmt(angle_deg)}" if angle_deg else ""),
               f"square 100, floating interior grid {k} x {k} lines, spacing {70 / k:g}, turned {angle_deg:g} degrees, split at crossings")
    d.loop([(0.0, 0.0), (100.0, 0.0), (100.0, 100.0), (0.0, 100.0)])
    s = 70.0 / k
    c, sn = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    P = lambda u, v: (50 + c * u - sn * v, 50 + sn * u + c * v)
    coord = lambda i: (i - (k - 1) / 2) * s
    ends = [coord(0) - s / 2] + [coord(i) for i in range(k)] + [coord(k - 1) + s / 2]
    for i in range(k):
        d.chain([P(coord(i), v) for v in ends])
        d.chain([P(u, coord(i)) for u in ends])
    return d


def points_jitter(n, seed):
    rng = random.Random(seed)
    d = Domain(f"points_jitter{n}x{n}", f"square 100 with {n * n} isolated points on a jittered grid (seed {seed})")
    d.loop([(0.0, 0.0), (100.0, 0.0), (100.0, 100.0), (0.0, 100.0)])
    h = 100.0 / n
    for i in range(n):
        for j in range(n):
            d.point(((i + 0.5) * h + rng.uniform(-0.3, 0.3) * h, (j + 0.5) * h + rng.uniform(-0.3, 0.3) * h))
    return d


def points_cluster(n, spacing, side, jitter_n=0):
    d = Domain(f"points_cluster{n}x{n}_d{fmt(spacing)}_side{fmt(side)}" + (f"_jitter{jitter_n}x{jitter_n}" if jitter_n else ""),
               f"square {side:g} with a {n} x {n} cluster of isolated points {spacing:g} apart near (0.3, 0.6) x side"
               + (f", and a jittered {jitter_n} x {jitter_n} grid" if jitter_n else ""))
    d.loop([(0.0, 0.0), (side, 0.0), (side, side), (0.0, side)])
    x0, y0 = 0.3 * side, 0.6 * side
    for i in range(n):
        for j in range(n):
            d.point((x0 + i * spacing, y0 + j * spacing))
    if jitter_n:
        rng = random.Random(7)
        h = side / jitter_n
        for i in range(jitter_n):
            for j in range(jitter_n):
                p = ((i + 0.5) * h + rng.uniform(-0.3, 0.3) * h, (j + 0.5) * h + rng.uniform(-0.3, 0.3) * h)
                if abs(p[0] - x0) > 0.02 * side or abs(p[1] - y0) > 0.02 * side:
                    d.point(p)
    return d


def thin_rect(scale=1.0):
    d = Domain("thin_rect_aspect200" + (f"_scale{fmt(scale)}" if scale != 1 else ""), "rectangle 100 x 0.5 (aspect 1:200)")
    d.loop([(0.0, 0.0), (100.0, 0.0), (100.0, 0.5), (0.0, 0.5)])
    return d.transform(scale)


def thin_L():
    d = Domain("thin_L_arm100_w0.5", "L shape, arms 100 long and 0.5 wide")
    d.loop([(0.0, 0.0), (100.0, 0.0), (100.0, 0.5), (0.5, 0.5), (0.5, 100.0), (0.0, 100.0)])
    return d


def close_hole_square(offset=0.0):
    d = Domain("closehole_square_gap1e-3" + (f"_translate{fmt(offset)}" if offset else ""),
               "square 100 with a 40 x 40 square hole 0.1 (1e-3 of the size) from the left side")
    d.loop([(0.0, 0.0), (100.0, 0.0), (100.0, 100.0), (0.0, 100.0)])
    d.hole([(0.1, 30.0), (0.1, 70.0), (40.1, 70.0), (40.1, 30.0)], (20.1, 50.0))
    return d.transform(1.0, (offset, offset))


def close_hole_circle():
    d = Domain("closehole_circle_gap1e-3", "96-gon of radius 50 with a 48-gon hole of radius 20 whose vertex comes within about 0.1 of the outer boundary")
    d.loop(circle(0, 0, 50, 96))
    cx = 50 - 20 - 0.1
    d.hole(circle(cx, 0, 20, 48)[::-1], (cx, 0.0))
    return d


def ytree(depth, angle_deg):
    """Square 100 with an interior tree of segments: a stem, then `depth` levels of forks whose two
    branches are angle_deg apart (each half as long as its parent)."""
    d = Domain(f"ytree_depth{depth}_angle{fmt(angle_deg)}", f"square 100 with a binary tree of interior segments, {depth} fork levels, {angle_deg:g} degrees between branches")
    d.loop([(0.0, 0.0), (100.0, 0.0), (100.0, 100.0), (0.0, 100.0)])
    root, top = (50.0, 10.0), (50.0, 45.0)
    d.segment(root, top)
    half = math.radians(angle_deg) / 2

    def grow(p, heading, length, level):
        if level == 0:
            return
        for s in (-1, 1):
            h = heading + s * half
            q = (p[0] + length * math.cos(h), p[1] + length * math.sin(h))
            d.segment(p, q)
            grow(q, h, length / 2, level - 1)
    grow(top, math.pi / 2, 40.0 if depth == 1 else 25.0, depth)
    return d


def domains():
    out = [
        comb(12, 0.02), comb(40, 0.005), comb(60, 0.002), comb(20, 0.005, both=True),
        spiral_rect(6, 0.2, 5.0), spiral_rect(12, 0.05, 4.0), spiral_angular(5, 0.1, 6, 10.0),
        koch(2), koch(3), koch(3, 1e-6),
        gear(12, 0.3), gear(30, 0.6), gear(60, 0.9, 96),
        plate(5, 5, 0.5, 16), plate(10, 10, 0.2, 12), plate(12, 8, 0.3, 24),
        annulus(64, 0.01), annulus(128, 0.01), annulus(128, 0.01, phase_half=True, offset=1e6),
        maze(8, 8, 10.0, 1), maze(20, 20, 5.0, 2), maze(40, 25, 2.5, 3),
        isosceles(30), isosceles(29.9), isosceles(30.1), isosceles(59.9), isosceles(60), isosceles(89.9),
        sharp_quad(), hexagon(), near_straight(179.9), near_straight(180.1), star_tips(5, 30),
        cgrid_touching(5), cgrid_floating(10, 0), cgrid_floating(6, 30),
        points_jitter(20, 1), points_cluster(7, 1e-4, 1.0), points_cluster(5, 1e-4, 100.0, jitter_n=10),
        thin_rect(), thin_rect(1e-6), thin_L(),
        close_hole_square(), close_hole_square(1e6), close_hole_circle(),
        ytree(1, 10), ytree(4, 10),
    ]
    names = [d.name for d in out]
    assert len(set(names)) == len(names), "duplicate names"
    return out


# ---------------------------------------------------------------- files

def write_poly(path, d):
    comments = [f"zoo domain {d.name}: {d.note}"]
    comments += [f"hole {h} loop: {' '.join(str(i + 1) for i in loop)}" for h, loop in enumerate(d.hole_loops, 1)]
    write_poly_file(path, comments, d.points, d.segments, d.holes)


def check_file(path):
    pts, segs, holes, hole_loops = read_poly(path)
    if len(hole_loops) != len(holes):
        return f"{len(holes)} hole seeds but {len(hole_loops)} '# hole K loop:' comments"
    if any(i < 0 or i >= len(pts) for s in segs for i in s):
        return "segment index out of range"
    return check(pts, segs, holes, hole_loops) or loops_problem(segs, hole_loops)


def main():
    args = sys.argv[1:]
    if args[:1] == ["--list"]:
        print("\n".join(d.name + ".poly" for d in domains()))
        return 0
    if args[:1] == ["--check"]:
        bad = 0
        if args[1:]:
            for path in args[1:]:
                p = check_file(path)
                print(f"{path}: {p or 'ok'}")
                bad += bool(p)
        else:
            for d in domains():
                p = d.problem()
                print(f"{d.name}: {p or 'ok'} ({len(d.points)} points, {len(d.segments)} segments, {len(d.holes)} holes)")
                bad += bool(p)
        return 1 if bad else 0
    if len(args) != 1 or args[0].startswith("-"):
        sys.exit(__doc__)
    os.makedirs(args[0], exist_ok=True)
    bad = 0
    for d in domains():
        p = d.problem()
        if p:
            print(f"{d.name}: INVALID: {p} (not written)", file=sys.stderr)
            bad += 1
            continue
        write_poly(os.path.join(args[0], d.name + ".poly"), d)
        print(f"{d.name}.poly: {len(d.points)} points, {len(d.segments)} segments, {len(d.holes)} holes")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
