#!/usr/bin/env python3
"""Side-by-side benchmark: `acute mesh` against CGAL Mesh_2 (with and without Lloyd) and gmsh 2D.

Every output is judged by the shared meshcheck (validity, conformity, angles, Q). Results go to
results/compare/<date>/<mode>.md and .json (not committed). Python 3 standard library only.

  bench/compare/run_compare.py --quick                 # a handful of domains at ~2k and ~20k, 1 repetition
  bench/compare/run_compare.py                         # full: every classic domain, ~2k/20k/200k (+1M square)
  bench/compare/run_compare.py --domains A,square --sizes 2000,20000,200000 --reps 3

Meshers (--meshers): acute, cgal20.7, cgal-max, cgal20.7+lloyd, cgal-max+lloyd, gmsh-front2d, gmsh-del2d.
cgal-max uses the largest min-angle bound among --cgal-max-angles that terminates (tried in order
with a time limit on the smallest size of each domain). Peers are tuned to the target vertex count by
rescaling their size parameter (vertex count ~ 1/h^2) until within --tolerance-count of it.
"""
import argparse
import datetime
import json
import math
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, "..", ".."))

ALL_MESHERS = ["acute", "cgal20.7", "cgal-max", "cgal20.7+lloyd", "cgal-max+lloyd", "gmsh-front2d", "gmsh-del2d"]
QUICK_DOMAINS = ["square", "disk", "A", "superior", "nazca_monkey"]
# Initial guess of (edge-size parameter) / (equilateral edge for the target count), refined per domain.
SIZE_FACTOR = {"cgal": 1.45, "gmsh": 1.0}
LLOYD_ITERATIONS = 10
GMSH_SMOOTHING = 5


# ----------------------------------------------------------------------------------------------
# Domains


def read_poly(path):
    """Triangle .poly: ({id: (x, y)}, [(a, b)], [(x, y)] holes). Vertex ids as in the file."""
    lines = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            if line:
                lines.append(line)
    it = iter(lines)
    head = next(it)
    nv = int(head[0])
    if nv == 0:
        raise ValueError(path + ": vertices in a .node file are not supported")
    pts = {}
    for _ in range(nv):
        t = next(it)
        pts[int(t[0])] = (float(t[1]), float(t[2]))
    ns = int(next(it)[0])
    segs = []
    for _ in range(ns):
        t = next(it)
        segs.append((int(t[1]), int(t[2])))
    holes = []
    t = next(it, None)
    if t is not None:
        for _ in range(int(t[0])):
            h = next(it)
            holes.append((float(h[1]), float(h[2])))
    return pts, segs, holes


def write_poly(path, pts, loops, holes=()):
    """pts: list of (x, y); loops: lists of 0-based indices, each closed."""
    segs = [(l[i], l[(i + 1) % len(l)]) for l in loops for i in range(len(l))]
    with open(path, "w") as f:
        f.write("%d 2 0 0\n" % len(pts))
        for i, (x, y) in enumerate(pts):
            f.write("%d %r %r\n" % (i + 1, x, y))
        f.write("%d 0\n" % len(segs))
        for i, (a, b) in enumerate(segs):
            f.write("%d %d %d\n" % (i + 1, a + 1, b + 1))
        f.write("%d\n" % len(holes))
        for i, (x, y) in enumerate(holes):
            f.write("%d %r %r\n" % (i + 1, x, y))


def make_generated_domains(folder):
    square = os.path.join(folder, "square.poly")
    write_poly(square, [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)], [[0, 1, 2, 3]])
    n = 256
    disk = os.path.join(folder, "disk.poly")
    write_poly(disk, [(math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n)) for i in range(n)], [list(range(n))])
    return {"square": square, "disk": disk}


def point_in_polygon(p, poly):
    x, y = p
    inside = False
    n = len(poly)
    for i in range(n):
        x1, y1 = poly[i]
        x2, y2 = poly[(i + 1) % n]
        if (y1 > y) != (y2 > y):
            xc = x1 + (y - y1) * (x2 - x1) / (y2 - y1)
            if xc > x:
                inside = not inside
    return inside


def polygon_area(poly):
    return 0.5 * sum(poly[i][0] * poly[(i + 1) % len(poly)][1] - poly[(i + 1) % len(poly)][0] * poly[i][1] for i in range(len(poly)))


def poly_to_geo(poly_path, geo_path, h):
    """Write a gmsh .geo for a .poly, with Triangle's semantics: the domain is the union of the bounded
    faces of the segments' arrangement minus the faces holding a hole seed. Faces are traced from the
    planar graph (half-edges sorted by angle); dangling segments and free points are embedded in their
    face. Returns None, or the reason the domain is not supported (crossing segments, bridges)."""
    pts, segs, holes = read_poly(poly_path)
    edges = {}
    for a, b in segs:
        if a != b:
            edges.setdefault((min(a, b), max(a, b)), len(edges) + 1)
    adj = {}
    for (a, b) in edges:
        adj.setdefault(a, set()).add(b)
        adj.setdefault(b, set()).add(a)
    # Prune dangling trees: they become embedded curves.
    dangling = []
    stack = [v for v in adj if len(adj[v]) == 1]
    while stack:
        v = stack.pop()
        if len(adj.get(v, ())) != 1:
            continue
        (u,) = adj[v]
        dangling.append((min(u, v), max(u, v)))
        adj[u].discard(v)
        del adj[v]
        if len(adj[u]) == 1:
            stack.append(u)
        elif not adj[u]:
            del adj[u]
    order = {}
    for v, ns in adj.items():
        x, y = pts[v]
        order[v] = sorted(ns, key=lambda w: math.atan2(pts[w][1] - y, pts[w][0] - x))
    cycles, used = [], set()
    for u in adj:
        for v in adj[u]:
            if (u, v) in used:
                continue
            cyc, a, b = [], u, v
            while (a, b) not in used:
                used.add((a, b))
                cyc.append((a, b))
                ring = order[b]
                # The face on the left of a->b continues along the edge just clockwise of b->a.
                b, a = ring[(ring.index(a) - 1) % len(ring)], b
            cycles.append(cyc)
    faces, inner = [], []
    for cyc in cycles:
        if len({(min(a, b), max(a, b)) for a, b in cyc}) != len(cyc):
            return "a segment bridges two loops (same face on both sides)"
        poly = [pts[a] for a, _ in cyc]
        (faces if polygon_area(poly) > 0 else inner).append((abs(polygon_area(poly)), poly, cyc))

    def face_of(p):
        best = -1
        for j, (ar, poly, _) in enumerate(faces):
            if point_in_polygon(p, poly) and (best < 0 or ar < faces[best][0]):
                best = j
        return best

    holes_in = [[] for _ in faces]
    for ar, poly, cyc in inner:
        # A clockwise cycle bounds a component from outside: it is an inner boundary of the smallest
        # face of another component around it (none: the unbounded face). Components share no vertex.
        best = -1
        for j, (far, fpoly, _) in enumerate(faces):
            if far > ar and point_in_polygon(poly[0], fpoly) and (best < 0 or far < faces[best][0]):
                best = j
        if best >= 0:
            holes_in[best].append(cyc)
    removed = {face_of(s) for s in holes} - {-1}
    out = ["// written by bench/compare/run_compare.py from %s" % os.path.basename(poly_path), "h = %r;" % h]
    for v, (x, y) in pts.items():
        out.append("Point(%d) = {%r, %r, 0, h};" % (v, x, y))
    for (a, b), i in edges.items():
        out.append("Line(%d) = {%d, %d};" % (i, a, b))
    loop_id = 0

    def curve_loop(cyc):
        nonlocal loop_id
        loop_id += 1
        ids = [edges[(a, b)] if a < b else -edges[(b, a)] for a, b in cyc]
        out.append("Curve Loop(%d) = {%s};" % (loop_id, ", ".join(map(str, ids))))
        return loop_id

    n_surf = 0
    for j, (_, _, cyc) in enumerate(faces):
        if j in removed:
            continue
        loops = [curve_loop(cyc)] + [curve_loop(c) for c in holes_in[j]]
        out.append("Plane Surface(%d) = {%s};" % (j + 1, ", ".join(map(str, loops))))
        n_surf += 1
    if n_surf == 0:
        return "no surface"
    on_graph = set(adj) | {v for e in dangling for v in e}
    for v in pts:
        if v not in on_graph:
            f = face_of(pts[v])
            if f >= 0 and f not in removed:
                out.append("Point{%d} In Surface{%d};" % (v, f + 1))
    for a, b in dangling:
        mid = ((pts[a][0] + pts[b][0]) / 2, (pts[a][1] + pts[b][1]) / 2)
        f = face_of(mid)
        if f >= 0 and f not in removed:
            out.append("Curve{%d} In Surface{%d};" % (edges[(a, b)], f + 1))
    with open(geo_path, "w") as f:
        f.write("\n".join(out) + "\n")
    return None


def msh2_to_off(msh_path, off_path, poly_path):
    """gmsh MSH 2 ASCII -> OFF: triangles only, unused nodes dropped, CCW, geometry points snapped to
    the exact .poly coordinates (gmsh prints 16 significant digits)."""
    pts, _, _ = read_poly(poly_path)
    nodes, tris, snap = {}, [], {}
    with open(msh_path) as f:
        lines = iter(f.read().split("\n"))
    for line in lines:
        if line.startswith("$Nodes"):
            for _ in range(int(next(lines))):
                t = next(lines).split()
                nodes[int(t[0])] = (float(t[1]), float(t[2]))
        elif line.startswith("$Elements"):
            for _ in range(int(next(lines))):
                t = next(lines).split()
                etype, ntags = int(t[1]), int(t[2])
                rest = [int(x) for x in t[3 + ntags:]]
                if etype == 2:
                    tris.append(rest)
                elif etype == 15 and ntags >= 2:
                    snap[rest[0]] = int(t[3 + 1])  # elementary tag = the .geo Point number
    for n, p in snap.items():
        if p in pts:
            nodes[n] = pts[p]
    index, verts, faces = {}, [], []
    for t in tris:
        ids = []
        for n in t:
            if n not in index:
                index[n] = len(verts)
                verts.append(nodes[n])
            ids.append(index[n])
        (ax, ay), (bx, by), (cx, cy) = (verts[i] for i in ids)
        if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) < 0:
            ids = [ids[0], ids[2], ids[1]]
        faces.append(ids)
    with open(off_path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(verts), len(faces)))
        f.writelines("%r %r 0\n" % v for v in verts)
        f.writelines("3 %d %d %d\n" % tuple(t) for t in faces)
    return len(verts)


def off_area(path):
    with open(path) as f:
        tok = f.read().split()
    i = 1 if tok[0] == "OFF" else 0
    nv, nf = int(tok[i]), int(tok[i + 1])
    i += 3
    v = []
    for _ in range(nv):
        v.append((float(tok[i]), float(tok[i + 1])))
        i += 3
    area = 0.0
    for _ in range(nf):
        a, b, c = (v[int(x)] for x in tok[i + 1:i + 4])
        area += 0.5 * abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
        i += 1 + int(tok[i])
    return area


def domain_area(acute, poly, work):
    """Area of the domain: sum over the triangles of `acute mesh --method cdt` (no Steiner points)."""
    out = os.path.join(work, "area.off")
    p = subprocess.run([acute, "mesh", poly, "-o", out, "--method", "cdt", "-q"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       text=True)
    if p.returncode not in (0, 1) or not os.path.exists(out):
        raise RuntimeError("cannot compute the area of %s: %s" % (poly, p.stderr.strip()[:200]))
    area = off_area(out)
    os.unlink(out)
    return area


def off_vertex_count(path):
    with open(path) as f:
        head = f.readline().split()
        counts = head[1:] if len(head) > 1 else f.readline().split()
        return int(counts[0])


# ----------------------------------------------------------------------------------------------
# Running


class Timeout(Exception):
    pass


def timed(cmd, timeout, cwd=None):
    """Run under /usr/bin/time: (wall s, cpu s (user + sys), peak RSS MB, returncode, stdout, stderr)."""
    with tempfile.NamedTemporaryFile("r", suffix=".time", delete=False) as tf:
        tfile = tf.name
    full = (["/usr/bin/time", "-f", "%M %U %S", "-o", tfile] if os.path.exists("/usr/bin/time") else []) + cmd
    t0 = time.perf_counter()
    # Own session, so that a timeout kills the mesher too, not only /usr/bin/time.
    p = subprocess.Popen(full, stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=cwd, text=True, start_new_session=True)
    try:
        out, err = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, 9)
        p.communicate()
        os.unlink(tfile)
        raise Timeout()
    wall = time.perf_counter() - t0
    rss = cpu = None
    try:
        with open(tfile) as f:
            last = [l.split() for l in f if re.match(r"^\d+ [\d.]+ [\d.]+\s*$", l)]
        if last:
            rss, cpu = int(last[-1][0]) / 1024.0, float(last[-1][1]) + float(last[-1][2])
    finally:
        os.unlink(tfile)
    return wall, cpu, rss, p.returncode, out, err


class Runner:
    def __init__(self, args, work):
        self.args = args
        self.work = work
        self.factor = {}  # (domain, mesher) -> size factor learned so far

    def out_path(self, domain, mesher, n):
        return os.path.join(self.work, "%s.%s.%d.off" % (domain, re.sub(r"[^A-Za-z0-9.]+", "_", mesher), n))

    def command(self, mesher, poly, out, n, h, angle):
        a = self.args
        if mesher == "acute":
            return [a.acute, "mesh", poly, "-o", out, "--vertices", str(n), "-q", "--json"] + a.acute_args.split(), out
        if mesher.startswith("cgal"):
            cmd = [a.cgal, poly, out, "--angle", repr(angle), "--size", repr(h)]
            if mesher.endswith("+lloyd"):
                cmd += ["--lloyd", str(LLOYD_ITERATIONS)]
            return cmd, out
        algo = mesher.split("-", 1)[1]
        geo, msh = out[:-4] + ".geo", out[:-4] + ".msh"
        reason = poly_to_geo(poly, geo, h)
        if reason:
            raise RuntimeError("gmsh skipped: " + reason)
        return [a.gmsh, geo, "-2", "-algo", algo, "-clmax", repr(h), "-smooth", str(GMSH_SMOOTHING), "-nt", "1",
                "-format", "msh2", "-o", msh, "-v", "1"], msh

    def run_once(self, mesher, domain, poly, out, n, h, angle, timeout):
        cmd, produced = self.command(mesher, poly, out, n, h, angle)
        if os.path.exists(produced):
            os.unlink(produced)
        wall, cpu, rss, rc, so, se = timed(cmd, timeout)
        extra = {}
        if mesher == "acute":
            try:
                j = json.loads(so)
                extra = {"status": j.get("status"), "iterations": j.get("iterations")}
            except ValueError:
                pass
            if rc not in (0, 1) or not os.path.exists(out):
                raise RuntimeError("acute exit %d: %s" % (rc, se.strip().splitlines()[-1:] if se.strip() else ""))
        elif rc != 0 or not os.path.exists(produced):
            raise RuntimeError("%s exit %d: %s" % (mesher, rc, " ".join(se.strip().splitlines()[-2:])))
        if mesher.startswith("cgal"):
            try:
                extra = json.loads(so.strip().splitlines()[-1])
            except (ValueError, IndexError):
                pass
        if mesher.startswith("gmsh"):
            nv = msh2_to_off(produced, out, poly)
            os.unlink(produced)
        else:
            nv = off_vertex_count(out)
        return wall, cpu, rss, nv, extra

    def run(self, mesher, domain, poly, n, area, angle=None, timeout=None):
        """Tuned (for peers) and repeated run. Returns a result dict (without the meshcheck part)."""
        a = self.args
        timeout = timeout or a.timeout
        out = self.out_path(domain, mesher, n)
        kind = "cgal" if mesher.startswith("cgal") else "gmsh" if mesher.startswith("gmsh") else "acute"
        h_eq = math.sqrt(2.0 * area / (math.sqrt(3.0) * n))
        # Lloyd moves vertices without adding any: it reuses the size tuned for the plain refinement.
        base = mesher.replace("+lloyd", "")
        tuned = self.factor.get((domain, base, n, angle)) if base != mesher else None
        fac = tuned or self.factor.get((domain, base), SIZE_FACTOR.get(kind, 1.0))
        rec = {"domain": domain, "mesher": mesher, "target": n, "angle_bound": angle, "tuning_runs": 0}
        times, cpus, rsss = [], [], []
        for attempt in range(a.max_tuning + 1):
            h = h_eq * fac
            wall, cpu, rss, nv, extra = self.run_once(mesher, domain, poly, out, n, h, angle, timeout)
            rec["tuning_runs"] += 1
            hit = abs(nv - n) <= a.tolerance_count * n
            if kind == "acute" or tuned or hit or attempt == a.max_tuning:
                times.append(wall)
                cpus.append(cpu)
                rsss.append(rss)
                break
            # Vertex count ~ area / h^2 (+ a boundary term): a square-root update, clamped (gmsh's
            # count stops following h where the boundary spacing sets the size).
            default = SIZE_FACTOR.get(kind, 1.0)
            fac = min(4 * default, max(0.25 * default, fac * math.sqrt(max(nv, 1) / n)))
        if kind != "acute":
            rec["size_param"] = h
            if hit:
                self.factor[(domain, base)] = fac
            self.factor[(domain, base, n, angle)] = fac
        for _ in range(a.reps - 1):
            wall, cpu, rss, nv2, extra = self.run_once(mesher, domain, poly, out, n, h, angle, timeout)
            times.append(wall)
            cpus.append(cpu)
            rsss.append(rss)
        known = [c for c in cpus if c is not None]
        rec.update({"time_s": statistics.median(times), "times_s": times, "cpu_s": statistics.median(known) if known else None,
                    "peak_mb": max(r for r in rsss if r is not None) if any(r is not None for r in rsss) else None,
                    "extra": extra, "out": out})
        return rec

    def check(self, rec, poly):
        a = self.args
        cmd = [sys.executable, a.meshcheck, rec["out"], "--domain", poly, "--json", "--tolerance", a.meshcheck_tolerance]
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        try:
            j = json.loads(p.stdout)
        except ValueError:
            rec["check"] = {"exit_code": p.returncode, "verdict": p.stderr.strip()[:200]}
            return None
        q = j.get("quality") or {}
        rec["check"] = {"exit_code": j.get("exit_code"), "verdict": j.get("verdict"), "tiles_domain": j.get("tiles_domain"),
                        "tiles_domain_exactly": j.get("tiles_domain_exactly")}
        rec["quality"] = {k: q.get(k) for k in ("n_vertices", "n_triangles", "n_steiner", "min_angle", "max_angle", "n_obtuse",
                                                 "pct_obtuse", "n_right", "pct_right", "n_below_min", "pct_below_min", "q_min",
                                                 "q_mean", "n_forced_corners", "free_min_angle", "mean_min_angle")}
        return (j.get("domain") or {}).get("area")


# ----------------------------------------------------------------------------------------------
# Reporting


def fmt(v, spec="%.2f"):
    return "—" if v is None else spec % v


def ratio_per_vertex(acute, peer, key="time_s"):
    """(acute time per vertex) / (peer time per vertex): the time ratio at equal vertex count."""
    try:
        ta = acute[key] / acute["quality"]["n_vertices"]
        tp = peer[key] / peer["quality"]["n_vertices"]
        return ta / tp
    except (KeyError, TypeError, ZeroDivisionError):
        return None


def markdown(report):
    meta = report["meta"]
    L = ["# acute vs CGAL Mesh_2 vs gmsh — %s mode, %s" % (meta["mode"], meta["date"]), "",
         "Machine: %s; %s cores; Python %s; load average at start %s, at end %s." % (
             meta["cpu"], meta["cores"], meta["python"], meta["load_start"], meta["load_end"]),
         "acute: `%s%s` (%s). CGAL %s (`%s`). gmsh %s (`%s`). Referee: `%s --tolerance %s`." % (
             meta["acute"], (" " + meta["acute_args"]) if meta.get("acute_args") else "", meta["acute_rev"], meta["cgal_version"], meta["cgal"], meta["gmsh_version"], meta["gmsh"],
             meta["meshcheck"], meta.get("meshcheck_tolerance", "1e-9")),
         "Wall time of the whole process (read, mesh, write), median of %d (%d at >= 200k); cpu = user + sys; peak RSS "
         "from /usr/bin/time. All meshers single-threaded, run one at a time. Peers' size "
         "parameter tuned to the target vertex count (±%d%%). acute/peer = (acute s per vertex) / (peer s per vertex)." % (
             meta["reps"], meta.get("big_reps", meta["reps"]), round(100 * meta["tolerance_count"])),
         "CGAL: Delaunay_mesh_size_criteria_2(B = sin²(angle), S), Lloyd = lloyd_optimize_mesh_2, %d iterations; "
         "cgal-max = largest of %s degrees that terminated. gmsh: -algo front2d|del2d, -smooth %d (Mesh.Optimize and "
         "-optimize_netgen act on tetrahedra only), -nt 1." % (LLOYD_ITERATIONS, meta["cgal_max_angles"], GMSH_SMOOTHING),
         "valid = meshcheck tiles the domain (`exact` when no vertex needed the tolerance). min∠ free = min angle away from "
         "input corners below 30°.", ""]
    # Summary first.
    L += ["## Summary", ""]
    L += summary(report)
    L += ["", "## Time to mesh", ""]
    L += time_table(report)
    L += ["", "## Runs", "",
          "| domain | target | mesher | valid | V | T | min∠ | free min∠ | max∠ | % >90 | # =90 | % <30 | Q min | Q mean | wall s | cpu s | peak MB | acute/peer |",
          "|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in report["runs"]:
        name = r["mesher"] + (" (%g°)" % r["angle_bound"] if r.get("angle_bound") and "max" in r["mesher"] else "")
        if "error" in r:
            L.append("| %s | %d | %s | %s |%s" % (r["domain"], r["target"], name, r["error"].replace("|", "/"), " |" * 14))
            continue
        q, c = r.get("quality") or {}, r.get("check") or {}
        valid = "exact" if c.get("tiles_domain_exactly") else ("yes" if c.get("tiles_domain") else "**NO**")
        L.append("| %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["domain"], r["target"], name, valid, fmt(q.get("n_vertices"), "%d"), fmt(q.get("n_triangles"), "%d"),
            fmt(q.get("min_angle")), fmt(q.get("free_min_angle")), fmt(q.get("max_angle"), "%.3f"), fmt(q.get("pct_obtuse")),
            fmt(q.get("n_right"), "%d"), fmt(q.get("pct_below_min")), fmt(q.get("q_min"), "%.3f"), fmt(q.get("q_mean"), "%.3f"),
            fmt(r.get("time_s"), "%.3f"), fmt(r.get("cpu_s"), "%.2f"), fmt(r.get("peak_mb"), "%.0f"), fmt(r.get("ratio"), "%.2f")))
    return "\n".join(L) + "\n"


def time_table(report):
    """Per domain and target: each mesher's time, memory and throughput beside the angles it reached."""
    L = ["Triangles per second = triangles / wall (cpu) time of the whole process, read and write included. status: acute's own verdict "
         "(ok = every angle in bounds except at input corners narrower than the min bound).", "",
         "| domain | target V | mesher | status | T | wall s | cpu s | peak MB | M triangles/s wall (cpu) | % obtuse | # right | max∠ | free min∠ |",
         "|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in report["runs"]:
        if r.get("mesher") == "-":
            continue
        if "error" in r:
            L.append("| %s | %d | %s | %s |%s" % (r["domain"], r["target"], r["mesher"], r["error"].replace("|", "/"), " |" * 9))
            continue
        q = r.get("quality") or {}
        status = (r.get("extra") or {}).get("status") or "—" if r["mesher"] == "acute" else "—"
        tps = q["n_triangles"] / r["time_s"] / 1e6 if q.get("n_triangles") and r.get("time_s") else None
        tps_cpu = q["n_triangles"] / r["cpu_s"] / 1e6 if q.get("n_triangles") and r.get("cpu_s") else None
        L.append("| %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["domain"], r["target"], r["mesher"] + (" (%g°)" % r["angle_bound"] if r.get("angle_bound") and "max" in r["mesher"] else ""),
            status, fmt(q.get("n_triangles"), "%d"), fmt(r.get("time_s"), "%.2f"), fmt(r.get("cpu_s"), "%.2f"),
            fmt(r.get("peak_mb"), "%.0f"), "%s (%s)" % (fmt(tps, "%.3f"), fmt(tps_cpu, "%.3f")), fmt(q.get("pct_obtuse")), fmt(q.get("n_right"), "%d"),
            fmt(q.get("max_angle"), "%.3f"), fmt(q.get("free_min_angle"))))
    return L


def geomean(xs):
    return math.exp(statistics.mean(math.log(x) for x in xs)) if xs else None


def summary(report):
    runs = [r for r in report["runs"] if "error" not in r and r.get("quality")]
    meshers = [m for m in report["meta"]["meshers"] if any(r["mesher"] == m for r in runs)]
    targets = sorted({r["target"] for r in runs})
    L = ["Per mesher over its (domain, size) runs: runs that tile the domain; runs with no obtuse triangle; with no "
         "obtuse or right one (every angle < 90°); runs whose free min angle is >= 30°; both goals (< 90° and free min "
         ">= 30°); worst max angle; mean of Q mean; geometric mean over domains of the acute/peer time ratio at equal "
         "vertex count, wall (cpu), per target size (> 1: acute slower).", "",
         "| mesher | valid | 0 obtuse | all < 90° | free min ≥ 30° | both | worst max∠ | mean Q | %s |" % " | ".join(
             "acute/peer @%s" % (("%dk" % (t // 1000)) if t >= 1000 else t) if t < 10**6 else "acute/peer @%dM" % (t // 10**6) for t in targets),
         "|---|---:|---:|---:|---:|---:|---:|---:|%s" % ("---:|" * len(targets))]
    for m in meshers:
        rs = [r for r in runs if r["mesher"] == m]
        ok = [r for r in rs if r["check"].get("tiles_domain")]
        nonobt = [r for r in rs if (r["quality"]["n_obtuse"] or 0) == 0]
        acute = [r for r in nonobt if (r["quality"]["n_right"] or 0) == 0]
        free = [r for r in rs if (r["quality"].get("free_min_angle") or 0) >= 30 - 1e-9]
        both = [r for r in acute if r in free]
        worst = max(r["quality"]["max_angle"] for r in rs)
        qmean = statistics.mean(r["quality"]["q_mean"] for r in rs)
        cells = []
        for t in targets:
            wall = geomean([r["ratio"] for r in rs if r["target"] == t and r.get("ratio")])
            cpu = geomean([r["ratio_cpu"] for r in rs if r["target"] == t and r.get("ratio_cpu")])
            cells.append("—" if wall is None else "%.2f (%s)" % (wall, fmt(cpu)))
        L.append("| %s | %d/%d | %d | %d | %d | %d | %.3f | %.3f | %s |" % (
            m, len(ok), len(rs), len(nonobt), len(acute), len(free), len(both), worst, qmean, " | ".join(cells)))
    return L


def merge_reports(paths):
    """One report from runs made separately (e.g. 2k/20k with 3 repetitions, 200k/1M with one): the
    runs in order, each mesher once, and every setting that differs listed as 'value (file); ...'."""
    reports = []
    for p in paths:
        with open(p) as f:
            reports.append((os.path.basename(p), json.load(f)))
    meta = dict(reports[0][1]["meta"])
    for key in {k for _, r in reports for k in r["meta"]}:
        values = [(name, r["meta"].get(key)) for name, r in reports]
        if key in ("meshers", "sizes"):
            merged = []
            for _, v in values:
                merged += [x for x in (v or []) if x not in merged]
            meta[key] = merged
        elif len({json.dumps(v, sort_keys=True) for _, v in values}) > 1:
            meta[key] = "; ".join("%s (%s)" % (v, name) for name, v in values)
    meta["reps"] = max(int(r["meta"]["reps"]) for _, r in reports)
    meta["big_reps"] = min(int(r["meta"].get("big_reps") or r["meta"]["reps"]) for _, r in reports)
    return {"meta": meta, "runs": [run for _, r in reports for run in r["runs"]]}


def tool_version(cmd):
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=30)
        return p.stdout.strip().splitlines()[0] if p.stdout.strip() else "?"
    except (OSError, subprocess.TimeoutExpired):
        return "?"


def cgal_version():
    try:
        with open("/usr/include/CGAL/version.h") as f:
            m = re.search(r'CGAL_VERSION_STR\s+CGAL_STR\(([^)]*)\)|#define CGAL_VERSION\s+(\S+)', f.read())
            return (m.group(1) or m.group(2)) if m else "?"
    except OSError:
        return "?"


def cpu_name():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "?"


def find_tool(given, candidates):
    if given:
        return given if os.path.exists(given) or shutil.which(given) else None
    for c in candidates:
        if c and (os.path.exists(c) or (not os.sep in c and shutil.which(c))):
            return shutil.which(c) or c
    return None


# ----------------------------------------------------------------------------------------------


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="a handful of domains at ~2k and ~20k, 1 repetition")
    ap.add_argument("--domains", help="comma list of names (meshes/NAME.poly, square, disk); default by mode")
    ap.add_argument("--sizes", help="comma list of target vertex counts; default 2000,20000 (quick) or 2000,20000,200000")
    ap.add_argument("--million", action="store_true", help="add ~1M vertices on the square (default in full mode)")
    ap.add_argument("--no-million", action="store_true")
    ap.add_argument("--meshers", default=",".join(ALL_MESHERS))
    ap.add_argument("--reps", type=int, help="repetitions (median time); default 1 quick, 3 full")
    ap.add_argument("--big-reps", type=int, help="repetitions for targets >= 200k vertices (default: --reps)")
    ap.add_argument("--name", help="base name of the .md/.json files (default: the mode)")
    ap.add_argument("--acute", help="acute binary (default build/bin/acute)")
    ap.add_argument("--cgal", help="cgal_mesh2 driver (default build*/bin/cgal_mesh2)")
    ap.add_argument("--gmsh", help="gmsh binary (default from PATH)")
    ap.add_argument("--meshcheck", default=os.path.join(REPO, "..", "shared", "tools", "meshcheck"))
    ap.add_argument("--meshcheck-tolerance", default="1e-9", help="meshcheck --tolerance (default 1e-9)")
    ap.add_argument("--cgal-max-angles", default="30,28,26,24,22")
    ap.add_argument("--acute-args", default="", help="extra options for acute mesh, e.g. '--time-limit 60'")
    ap.add_argument("--timeout", type=float, help="seconds per mesher run (default 120 quick, 900 full)")
    ap.add_argument("--tolerance-count", type=float, default=0.10, help="accepted relative miss of the vertex count")
    ap.add_argument("--max-tuning", type=int, default=3)
    ap.add_argument("--out", help="results folder (default results/compare/<date>)")
    ap.add_argument("--keep-meshes", action="store_true")
    ap.add_argument("--render", metavar="JSON", nargs="+",
                    help="only rewrite the Markdown next to a results JSON; with several, merge them into "
                         "OUT/NAME.json and .md (default: beside the first, 'merged')")
    a = ap.parse_args()
    if a.render:
        if len(a.render) == 1:
            with open(a.render[0]) as f:
                report = json.load(f)
            base = os.path.splitext(a.render[0])[0]
        else:
            report = merge_reports(a.render)
            base = os.path.join(a.out or os.path.dirname(a.render[0]), a.name or "merged")
            with open(base + ".json", "w") as f:
                json.dump(report, f, indent=1)
        with open(base + ".md", "w") as f:
            f.write(markdown(report))
        return

    mode = "quick" if a.quick else "full"
    name = a.name or mode
    a.reps = a.reps or (1 if a.quick else 3)
    a.big_reps = a.big_reps or a.reps
    base_reps = a.reps
    a.timeout = a.timeout or (120 if a.quick else 900)
    sizes = [int(s) for s in a.sizes.split(",")] if a.sizes else ([2000, 20000] if a.quick else [2000, 20000, 200000])
    million = (not a.quick or a.million) and not a.no_million
    meshers = [m for m in a.meshers.split(",") if m]
    for m in meshers:
        if m not in ALL_MESHERS:
            ap.error("unknown mesher " + m)
    a.acute = find_tool(a.acute, [os.path.join(REPO, "build", "bin", "acute")])
    a.cgal = find_tool(a.cgal, [os.path.join(REPO, d, "bin", "cgal_mesh2") for d in ("build", "build-compare")])
    a.gmsh = find_tool(a.gmsh, ["gmsh"])
    a.meshcheck = os.path.normpath(a.meshcheck)
    if not os.path.exists(a.meshcheck):
        sys.exit("run_compare: meshcheck not found at %s (give --meshcheck)" % a.meshcheck)
    skipped = []
    if not a.acute:
        sys.exit("run_compare: acute binary not found (build acute_cli or give --acute)")
    if not a.cgal:
        skipped.append("CGAL driver not found (install libcgal-dev, build target cgal_mesh2, or give --cgal): CGAL skipped")
        meshers = [m for m in meshers if not m.startswith("cgal")]
    if not a.gmsh:
        skipped.append("gmsh not found (apt-get install gmsh): gmsh skipped")
        meshers = [m for m in meshers if not m.startswith("gmsh")]
    for s in skipped:
        print("run_compare: " + s, file=sys.stderr)

    date = datetime.date.today().isoformat()
    out_dir = a.out or os.path.join(REPO, "results", "compare", date)
    work = os.path.join(out_dir, "work-" + mode)
    os.makedirs(work, exist_ok=True)
    domains = make_generated_domains(out_dir)
    for p in sorted(os.listdir(os.path.join(REPO, "meshes"))):
        if p.endswith(".poly") and p != "box.poly":  # box.poly is meant for Triangle's -c (convex hull)
            domains[p[:-5]] = os.path.join(REPO, "meshes", p)
    names = a.domains.split(",") if a.domains else (QUICK_DOMAINS if a.quick else list(domains))
    for n in names:
        if n not in domains:
            sys.exit("run_compare: unknown domain %s (known: %s)" % (n, ", ".join(domains)))

    acute_rev = "?"
    try:
        st = os.stat(a.acute)
        acute_rev = "built %s" % datetime.datetime.fromtimestamp(st.st_mtime).strftime("%Y-%m-%d %H:%M")
        head = subprocess.run(["git", "-C", REPO, "rev-parse", "--short", "HEAD"], stdout=subprocess.PIPE, text=True).stdout.strip()
        acute_rev += ", repository HEAD %s" % head
    except OSError:
        pass
    meta = {"mode": mode, "date": date, "cpu": cpu_name(), "cores": os.cpu_count(), "python": platform.python_version(),
            "uname": " ".join(platform.uname()), "load_start": "%.2f" % os.getloadavg()[0], "acute": a.acute,
            "acute_args": a.acute_args, "acute_rev": acute_rev, "cgal": a.cgal, "cgal_version": cgal_version(), "gmsh": a.gmsh,
            "gmsh_version": tool_version([a.gmsh, "--version"]) if a.gmsh else None, "meshcheck": a.meshcheck,
            "reps": a.reps, "big_reps": a.big_reps, "sizes": sizes, "million_on_square": million, "meshers": meshers,
            "tolerance_count": a.tolerance_count, "meshcheck_tolerance": a.meshcheck_tolerance, "cgal_max_angles": a.cgal_max_angles, "skipped": skipped,
            "lloyd_iterations": LLOYD_ITERATIONS, "gmsh_smoothing": GMSH_SMOOTHING}
    report = {"meta": meta, "runs": []}
    runner = Runner(a, work)
    max_angles = [float(x) for x in a.cgal_max_angles.split(",")]
    t_start = time.perf_counter()

    def save():
        meta["load_end"] = "%.2f" % os.getloadavg()[0]
        meta["elapsed_s"] = round(time.perf_counter() - t_start, 1)
        with open(os.path.join(out_dir, name + ".json"), "w") as f:
            json.dump(report, f, indent=1)
        with open(os.path.join(out_dir, name + ".md"), "w") as f:
            f.write(markdown(report))

    for dname in names:
        poly = domains[dname]
        dsizes = sizes + ([1000000] if million and dname == "square" else [])
        cgal_max = None  # chosen on the first size
        try:
            area = domain_area(a.acute, poly, work)
        except RuntimeError as e:
            print("run_compare: %s: skipped (%s)" % (dname, e), file=sys.stderr)
            report["runs"].append({"domain": dname, "mesher": "-", "target": 0, "error": str(e)[:160]})
            continue
        for n in dsizes:
            a.reps = a.big_reps if n >= 200000 else base_reps
            results = {}
            for m in meshers:
                angle = 20.7 if "20.7" in m else None
                label = "%s n=%d %s" % (dname, n, m)
                try:
                    if "max" in m:
                        if cgal_max is None:
                            base = results.get("cgal20.7")
                            limit = max(5.0, 20 * base["time_s"]) if base and "time_s" in base else a.timeout
                            for ang in max_angles:
                                try:
                                    rec = runner.run(m, dname, poly, n, area, ang, timeout=min(limit, a.timeout))
                                    cgal_max = ang
                                    break
                                except (Timeout, RuntimeError) as e:
                                    print("  %s: %g degrees did not finish (%s)" % (label, ang, type(e).__name__), file=sys.stderr)
                            if cgal_max is None:
                                cgal_max = -1
                                raise RuntimeError("no bound in %s terminated" % a.cgal_max_angles)
                        elif cgal_max < 0:
                            raise RuntimeError("no bound in %s terminated" % a.cgal_max_angles)
                        else:
                            rec = runner.run(m, dname, poly, n, area, cgal_max)
                    else:
                        rec = runner.run(m, dname, poly, n, area, angle)
                    runner.check(rec, poly)
                    if not a.keep_meshes and os.path.exists(rec["out"]):
                        os.unlink(rec["out"])
                    rec.pop("out", None)
                except Timeout:
                    rec = {"domain": dname, "mesher": m, "target": n, "error": "timeout (%g s)" % a.timeout}
                except (RuntimeError, OSError, ValueError) as e:
                    rec = {"domain": dname, "mesher": m, "target": n, "error": str(e)[:160]}
                results[m] = rec
                report["runs"].append(rec)
                q = rec.get("quality") or {}
                print("%-40s %s" % (label, rec.get("error") or "V=%s min=%.2f max=%.2f t=%.3fs" % (
                    q.get("n_vertices"), q.get("min_angle") or 0, q.get("max_angle") or 0, rec["time_s"])), flush=True)
            ac = results.get("acute")
            if ac and "error" not in ac:
                for m, r in results.items():
                    if m != "acute" and "error" not in r:
                        r["ratio"] = ratio_per_vertex(ac, r)
                        r["ratio_cpu"] = ratio_per_vertex(ac, r, "cpu_s")
            save()
    save()
    print("wrote %s/%s.md and .json (%.0f s)" % (out_dir, name, time.perf_counter() - t_start))


if __name__ == "__main__":
    main()
