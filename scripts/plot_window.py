#!/usr/bin/env python3
"""Rasterises a window of a triangle mesh to PNG (stdlib only), for looking at what the repair left.

    plot_window.py MESH.off CX CY R OUT.png [--size 900] [--min-angle 30 --max-angle 90] [--bad N]

Triangles with an angle >= max or < min are filled pink, edges are grey, vertices that are not
Steiner points (given with --domain D.json / D.poly) are blue dots. `--bad N` centres the window on
the N-th bad triangle (0-based) instead of CX CY and prints the bad triangles' centres."""
import argparse, json, math, struct, zlib


def read_off(path):
    toks = []
    with open(path) as f:
        for line in f:
            line = line.split('#')[0].split()
            toks.extend(line)
    assert toks[0].endswith('OFF')
    nv, nf = int(toks[1]), int(toks[2])
    p = 4
    pts = []
    for _ in range(nv):
        pts.append((float(toks[p]), float(toks[p + 1])))
        p += 3
    tris = []
    for _ in range(nf):
        k = int(toks[p])
        tris.append(tuple(int(t) for t in toks[p + 1:p + 1 + k]))
        p += 1 + k
    return pts, tris


def domain_points(path):
    if path.endswith('.json'):
        d = json.load(open(path))
        return list(zip(map(float, d['points_x']), map(float, d['points_y'])))
    pts = []
    with open(path) as f:
        lines = [l.split('#')[0].split() for l in f]
    lines = [l for l in lines if l]
    n = int(lines[0][0])
    for l in lines[1:1 + n]:
        pts.append((float(l[1]), float(l[2])))
    return pts


def angles(a, b, c):
    def ang(p, q, r):
        ux, uy, vx, vy = q[0] - p[0], q[1] - p[1], r[0] - p[0], r[1] - p[1]
        return math.degrees(math.atan2(abs(ux * vy - uy * vx), ux * vx + uy * vy))
    return ang(a, b, c), ang(b, c, a), ang(c, a, b)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('mesh'); ap.add_argument('cx', type=float); ap.add_argument('cy', type=float)
    ap.add_argument('r', type=float); ap.add_argument('out')
    ap.add_argument('--domain'); ap.add_argument('--size', type=int, default=900)
    ap.add_argument('--min-angle', type=float, default=30); ap.add_argument('--max-angle', type=float, default=90)
    ap.add_argument('--bad', type=int)
    a = ap.parse_args()
    pts, tris = read_off(a.mesh)
    bad = []
    for t in tris:
        an = angles(*(pts[i] for i in t))
        if max(an) >= a.max_angle or min(an) < a.min_angle:
            bad.append(t)
    cx, cy = a.cx, a.cy
    for k, t in enumerate(bad):
        c = [sum(pts[i][j] for i in t) / 3 for j in (0, 1)]
        an = angles(*(pts[i] for i in t))
        print(f'bad {k}: centre ({c[0]:.9g}, {c[1]:.9g}) angles {", ".join(f"{x:.3f}" for x in an)}')
        if a.bad == k:
            cx, cy = c
    W = a.size
    img = bytearray(b'\xff' * (W * W * 3))
    s = W / (2 * a.r)
    px = lambda p: ((p[0] - cx) * s + W / 2, W / 2 - (p[1] - cy) * s)

    def put(x, y, col):
        if 0 <= x < W and 0 <= y < W:
            o = (y * W + x) * 3
            img[o:o + 3] = bytes(col)

    badset = set(bad)
    for t in tris:
        q = [px(pts[i]) for i in t]
        if max(v[0] for v in q) < 0 or min(v[0] for v in q) >= W or max(v[1] for v in q) < 0 or min(v[1] for v in q) >= W:
            continue
        if t in badset:
            x0, x1 = max(0, int(min(v[0] for v in q))), min(W - 1, int(max(v[0] for v in q)) + 1)
            y0, y1 = max(0, int(min(v[1] for v in q))), min(W - 1, int(max(v[1] for v in q)) + 1)
            (ax, ay), (bx, by), (ccx, ccy) = q
            den = (bx - ax) * (ccy - ay) - (by - ay) * (ccx - ax)
            if den != 0:
                for y in range(y0, y1 + 1):
                    for x in range(x0, x1 + 1):
                        l1 = ((x - ax) * (ccy - ay) - (y - ay) * (ccx - ax)) / den
                        l2 = ((bx - ax) * (y - ay) - (by - ay) * (x - ax)) / den
                        if l1 >= 0 and l2 >= 0 and l1 + l2 <= 1:
                            put(x, y, (255, 170, 200))
        for k in range(3):
            (x0, y0), (x1, y1) = q[k], q[(k + 1) % 3]
            n = int(max(abs(x1 - x0), abs(y1 - y0))) + 1
            if n > 4 * W:
                n = 4 * W
            for i in range(n + 1):
                u = i / n
                put(int(x0 + u * (x1 - x0)), int(y0 + u * (y1 - y0)), (110, 110, 110))
    if a.domain:
        for p in domain_points(a.domain):
            x, y = px(p)
            for dx in range(-2, 3):
                for dy in range(-2, 3):
                    put(int(x) + dx, int(y) + dy, (30, 60, 230))
    raw = b''.join(b'\x00' + bytes(img[y * W * 3:(y + 1) * W * 3]) for y in range(W))
    chunk = lambda tag, data: struct.pack('>I', len(data)) + tag + data + struct.pack('>I', zlib.crc32(tag + data) & 0xffffffff)
    png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', W, W, 8, 2, 0, 0, 0)) + chunk(b'IDAT', zlib.compress(raw, 6)) + chunk(b'IEND', b'')
    open(a.out, 'wb').write(png)


if __name__ == '__main__':
    main()
