#!/usr/bin/env python3
"""Shewchuk's Triangle (npm triangle-wasm, -pq30 with an area bound tuned to the vertex count) beside
the bounds [30, 90), judged by meshcheck. Usage: triangle_table.py DOMAIN.poly... [--vertices 2000 20000]
Needs node and `npm install triangle-wasm` in bench/compare. Prints a Markdown table."""
import argparse, json, os, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
MESHCHECK = os.environ.get("MESHCHECK") or os.path.join(HERE, "..", "..", "..", "shared", "tools", "meshcheck")


def run(domain, area, out):
    p = subprocess.run(["node", os.path.join(HERE, "triangle_wasm.js"), domain, out, "pq30a" + f"{area:.24f}".rstrip("0")],
                       capture_output=True, text=True, timeout=600, check=True)
    return json.loads(p.stdout.strip().splitlines()[-1])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("domains", nargs="+")
    ap.add_argument("--vertices", type=int, nargs="+", default=[2000, 20000])
    args = ap.parse_args()
    print("| domain | target V | V | T | min | max | % obtuse | % below 30 (free) | Triangle s |")
    print("|---|---|---|---|---|---|---|---|---|")
    tmp = tempfile.mkdtemp()
    for d in args.domains:
        name = os.path.splitext(os.path.basename(d))[0]
        out = os.path.join(tmp, name + ".off")
        run(d, 1e9, out)  # the bare quality mesh: the domain area, from meshcheck
        j = json.loads(subprocess.run([sys.executable, MESHCHECK, out, "--domain", d, "--json"], capture_output=True, text=True).stdout)
        total = j["domain"]["area"]
        for n in args.vertices:
            area = (total or 1.0) / n
            for _ in range(4):  # tune the area bound until the vertex count is within 15%
                r = run(d, area, out)
                if abs(r["vertices"] - n) <= 0.15 * n: break
                area *= r["vertices"] / n
            j = json.loads(subprocess.run([sys.executable, MESHCHECK, out, "--domain", d, "--tolerance", "1e-10", "--json",
                                           "--min-angle", "30", "--max-angle", "90"], capture_output=True, text=True).stdout)
            q = j["quality"]
            print(f"| {name} | {n} | {q['n_vertices']} | {q['n_triangles']} | {q['min_angle']:.2f} | {q['max_angle']:.2f} | "
                  f"{q['pct_obtuse']:.2f} | {100.0 * q['n_below_min_free'] / q['n_triangles']:.2f} | {r['seconds']:.3f} |")


if __name__ == "__main__":
    main()
