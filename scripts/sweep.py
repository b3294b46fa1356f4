#!/usr/bin/env python3
"""Runs `acute mesh` over many domains and judges every output with shared/tools/meshcheck.

Usage: scripts/sweep.py [--acute build/bin/acute] [--method acute] [--vertices N | --size H]
                        [--min-angle 30 --max-angle 90] [--jobs 2] [--timeout 600] [--out DIR] [--extra 'ARGS'] DOMAIN...
Prints one Markdown table row per domain and a summary line; exit 1 if any run failed validity.
"""
import argparse, json, os, subprocess, sys, time
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
# The referee beside the repository (../shared); MESHCHECK=path for a worktree elsewhere.
MESHCHECK = os.environ.get("MESHCHECK") or os.path.join(HERE, "..", "..", "shared", "tools", "meshcheck")


def run_one(args, domain):
    name = os.path.splitext(os.path.basename(domain))[0]
    out = os.path.join(args.out, f"{name}_{args.method}.off")
    cmd = [args.acute, "mesh", domain, "-o", out, "--method", args.method, "-q", "--json",
           "--min-angle", str(args.min_angle), "--max-angle", str(args.max_angle), "--seed", str(args.seed)]
    if args.vertices: cmd += ["--vertices", str(args.vertices)]
    if args.size: cmd += ["--size", str(args.size)]
    if name == "box": cmd += ["--convex-hull"]
    cmd += args.extra.split()
    t0 = time.time()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=args.timeout)
        rc, err = p.returncode, p.stderr.strip().splitlines()[:1]
    except subprocess.TimeoutExpired:
        rc, err = "timeout", ["timeout"]
    secs = time.time() - t0
    row = dict(domain=name, rc=rc, secs=secs, err=err[0] if err else "")
    try:
        report = json.loads(p.stdout)
        row["cvt"], row["start"] = report.get("n_vertices_cvt"), report.get("n_vertices_start")
    except (json.JSONDecodeError, NameError, AttributeError):
        pass
    if rc not in (0, 1) or not os.path.exists(out):
        return row
    mc = [sys.executable, args.meshcheck, out, "--domain", domain, "--tolerance", "1e-10", "--json",
          "--min-angle", str(args.min_angle), "--max-angle", str(args.max_angle)]
    if name == "box": mc = [sys.executable, args.meshcheck, out, "--tolerance", "1e-10", "--json",
                            "--min-angle", str(args.min_angle), "--max-angle", str(args.max_angle)]
    p = subprocess.run(mc, capture_output=True, text=True)
    try:
        j = json.loads(p.stdout)
    except json.JSONDecodeError:
        row["meshcheck"] = "unreadable: " + p.stderr.strip()[:200]
        return row
    q = j.get("quality") or {}
    row.update(meshcheck=j["exit_code"], nv=q.get("n_vertices"), nt=q.get("n_triangles"),
               min=q.get("min_angle"), free_min=q.get("free_min_angle"), max=q.get("max_angle"),
               obtuse=q.get("n_obtuse"), right=q.get("n_right"), below=q.get("n_below_min_free"),
               forced=q.get("n_forced_corners"))
    return row


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("domains", nargs="+")
    ap.add_argument("--acute", default=os.path.join(HERE, "..", "build", "bin", "acute"))
    ap.add_argument("--method", default="acute")
    ap.add_argument("--vertices", type=int, default=0)
    ap.add_argument("--size", type=float, default=0)
    ap.add_argument("--min-angle", type=float, default=30)
    ap.add_argument("--max-angle", type=float, default=90)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=600)
    ap.add_argument("--out", default="/tmp/acute-sweep")
    ap.add_argument("--extra", default="", help="more arguments for acute mesh, e.g. '--time-limit 60'")
    ap.add_argument("--meshcheck", default=MESHCHECK, help="the referee (default: ../shared/tools/meshcheck)")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    with ThreadPoolExecutor(args.jobs) as ex:
        rows = list(ex.map(lambda d: run_one(args, d), args.domains))
    # CVT V: the CVT (or refinement) start; start V: that start with its hub patches, where the repair begins.
    print("| domain | exit | meshcheck | CVT V | start V | V | V / CVT | T | min | free min | max | obtuse | right | below min (free) | s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    ok = invalid = 0
    f = lambda x, d=3: "-" if x is None else (f"{x:.{d}f}" if isinstance(x, float) else str(x))
    for r in rows:
        print(f"| {r['domain']} | {r['rc']} | {r.get('meshcheck', '-')} | {f(r.get('cvt'))} | {f(r.get('start'))} | {f(r.get('nv'))} | "
              f"{f(r['nv'] / r['cvt'] if r.get('cvt') and r.get('nv') else None)} | {f(r.get('nt'))} | {f(r.get('min'))} | "
              f"{f(r.get('free_min'))} | {f(r.get('max'))} | {f(r.get('obtuse'))} | {f(r.get('right'))} | {f(r.get('below'))} | {r['secs']:.2f} |"
              + (f" {r['err']}" if r.get("meshcheck") is None else ""))
        ok += r.get("meshcheck") == 0
        invalid += r.get("meshcheck") not in (0, 1)
    growth = [r["nv"] / r["start"] for r in rows if r.get("start") and r.get("nv")]
    over_cvt = sorted(((r["nv"] / r["cvt"], r["domain"]) for r in rows if r.get("cvt") and r.get("nv")), reverse=True)
    print(f"\nsweep: {ok} of {len(rows)} meet the bounds; {invalid} invalid or failed runs"
          + (f"; vertices / start: max {max(growth):.3f}" if growth else "")
          + (f"; vertices / CVT: max {over_cvt[0][0]:.3f} ({over_cvt[0][1]}), {sum(g > 1.1 for g, _ in over_cvt)} over 1.1" if over_cvt else ""))
    return 1 if invalid else 0


if __name__ == "__main__":
    sys.exit(main())
