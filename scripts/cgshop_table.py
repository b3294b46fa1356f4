#!/usr/bin/env python3
"""Run `acute repair --keep-vertices --allow-right` on CG:SHOP 2025 instances, judge each output
with meshcheck, and print the Steiner points per instance next to the best known figures.

  scripts/cgshop_table.py --acute build/bin/acute --out /tmp/cgshop [--timeout 60] [--limit N]
  scripts/cgshop_table.py --table-only --out /tmp/cgshop     # re-read earlier results
  ... --time-limit 10 --retry-time-limit 120   # a second, longer run for what the first left obtuse

A row counts as valid when meshcheck exits 0 with the instance as domain and bounds
--min-angle 0 --max-angle 90.000001 (right angles allowed). The total ratio is over the
instances where we have a valid result; instances without one are listed separately.
meshcheck decides angles on doubles with a tolerance, so a triangle obtuse by less than it passes:
the line "valid and exactly non-obtuse" also needs acute's exact count to be 0 (the CG:SHOP
criterion). Then per instance class and per start (which stage of `acute repair` produced it).
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import time

SHARED = os.environ.get("ACUTE_SHARED_DIR") or os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared")


def solved(rec):
    return rec.get("meshcheck_rc") == 0 and rec.get("n_obtuse_exact") == 0


def run_one(args, inst_path, uid, time_limit=None):
    time_limit = time_limit or args.time_limit
    out_off = os.path.join(args.out, uid + ".off")
    out_json = os.path.join(args.out, uid + ".solution.json")
    rec = {"uid": uid, "repair_rc": None, "steiner": None, "seconds": None, "meshcheck_rc": None, "status": None,
           "time_limit": time_limit}
    cmd = [args.acute, "repair", inst_path, "-o", out_off, "-o", out_json, "--allow-right", "--exact", "--json", "-q",
           "--time-limit", str(time_limit)]
    t0 = time.time()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=args.timeout * time_limit / args.time_limit)
        rec["repair_rc"] = p.returncode
        try:
            rep = json.loads(p.stdout)
            rec.update({"steiner": rep.get("n_steiner"), "status": rep.get("status"), "start": rep.get("start"),
                        "n_obtuse_exact": rep.get("n_obtuse_exact")})
        except json.JSONDecodeError:
            rec["error"] = (p.stderr or "").strip()[:200]
    except subprocess.TimeoutExpired:
        rec["repair_rc"] = "timeout"
    rec["seconds"] = round(time.time() - t0, 2)
    if os.path.exists(out_off) and rec["repair_rc"] in (0, 1):
        m = subprocess.run([sys.executable, args.meshcheck, out_off, "--domain", inst_path, "--min-angle", "0",
                            "--max-angle", "90.000001", "--json"], capture_output=True, text=True)
        rec["meshcheck_rc"] = m.returncode
        try:
            mj = json.loads(m.stdout)
            rec["meshcheck_steiner"] = mj["quality"]["n_steiner"]
        except (json.JSONDecodeError, KeyError, TypeError):
            pass
    with open(os.path.join(args.out, uid + ".result.json"), "w") as f:
        json.dump(rec, f)
    return rec


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--acute", default="build/bin/acute")
    ap.add_argument("--meshcheck", default=os.path.join(SHARED, "tools", "meshcheck"))
    ap.add_argument("--instances", default=os.path.join(SHARED, "domains", "cgshop2025", "instances"))
    ap.add_argument("--best", default=os.path.join(SHARED, "domains", "cgshop2025", "BEST_KNOWN.csv"))
    ap.add_argument("--out", required=True)
    ap.add_argument("--timeout", type=float, default=60, help="wall-clock kill per instance (s)")
    ap.add_argument("--time-limit", type=float, default=40, help="acute --time-limit per instance (s)")
    ap.add_argument("--retry-time-limit", type=float, default=0,
                    help="rerun an instance without an exactly non-obtuse result once with this --time-limit")
    ap.add_argument("--limit", type=int, default=0, help="only the first N instances (by size)")
    ap.add_argument("--table-only", action="store_true")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)

    best = {}
    with open(args.best) as f:
        for row in csv.DictReader(f):
            best[row["instance_uid"]] = int(row["steiner_points"])
    uids = sorted((n[: -len(".instance.json")] for n in os.listdir(args.instances) if n.endswith(".instance.json")),
                  key=lambda u: (int(u.split("_")[-2]), u))
    if args.limit:
        uids = uids[: args.limit]
    results = []
    for k, uid in enumerate(uids):
        res_path = os.path.join(args.out, uid + ".result.json")
        if args.table_only or (os.path.exists(res_path) and not args.limit):
            if not os.path.exists(res_path):
                continue
            with open(res_path) as f:
                rec = json.load(f)
        else:
            rec = run_one(args, os.path.join(args.instances, uid + ".instance.json"), uid)
            if args.retry_time_limit > args.time_limit and not solved(rec):
                first = rec
                rec = run_one(args, os.path.join(args.instances, uid + ".instance.json"), uid, args.retry_time_limit)
                rec["seconds"] = round(rec["seconds"] + first["seconds"], 2)
                rec["retried"] = True
            print(f"[{k + 1}/{len(uids)}] {uid}: rc={rec['repair_rc']} meshcheck={rec['meshcheck_rc']} "
                  f"steiner={rec['steiner']} best={best.get(uid)} {rec['seconds']}s", file=sys.stderr, flush=True)
        results.append(rec)

    print(f"| instance | Steiner | best known | ratio | meshcheck | start | seconds |")
    print(f"| --- | ---: | ---: | ---: | ---: | --- | ---: |")
    ours = known = 0
    valid = 0
    invalid = []
    for rec in results:
        uid, b = rec["uid"], best.get(rec["uid"])
        ok = rec.get("meshcheck_rc") == 0
        s = rec.get("steiner")
        ratio = f"{s / b:.2f}" if ok and b and s is not None else ("-" if ok else "n/a")
        print(f"| {uid} | {s if s is not None else '-'} | {b if b is not None else '-'} | {ratio} | "
              f"{rec.get('meshcheck_rc')} | {rec.get('start') or '-'} | {rec.get('seconds')} |")
        if ok and s is not None and b is not None:
            valid += 1
            ours += s
            known += b
        else:
            invalid.append(uid)
    print()
    print(f"instances: {len(results)}; valid (meshcheck exit 0): {valid}; without a valid result: {len(invalid)}")
    if known:
        print(f"Steiner points over the valid ones: ours {ours}, best known {known}, ratio {ours / known:.2f}")
    # meshcheck decides angles on doubles within 1e-9 degrees; acute decides them exactly on the
    # rationals: a result is a valid CG:SHOP solution only when both agree.
    exact = [r for r in results if r.get("meshcheck_rc") == 0 and r.get("n_obtuse_exact") == 0
             and r.get("steiner") is not None and best.get(r["uid"]) is not None]
    if exact:
        eo, ek = sum(r["steiner"] for r in exact), sum(best[r["uid"]] for r in exact)
        print(f"valid and exactly non-obtuse (acute's exact count 0 as well): {len(exact)}; "
              f"Steiner points ours {eo}, best known {ek}, ratio {eo / ek:.2f}")
    # Per class (the uid prefix before the size): valid count and Steiner ratio on the valid ones.
    classes = {}
    for rec in results:
        c = classes.setdefault(rec["uid"].rsplit("_", 2)[0], [0, 0, 0, 0])
        c[0] += 1
        b, s = best.get(rec["uid"]), rec.get("steiner")
        if rec.get("meshcheck_rc") == 0 and s is not None and b is not None:
            c[1] += 1
            c[2] += s
            c[3] += b
    for name, (n, v, s, b) in sorted(classes.items()):
        print(f"  {name}: valid {v}/{n}" + (f", Steiner ours {s}, best known {b}, ratio {s / b:.2f}" if b else ""))
    starts = {}
    for rec in results:
        b, s = best.get(rec["uid"]), rec.get("steiner")
        if rec.get("meshcheck_rc") == 0 and s is not None and b is not None:
            st = starts.setdefault(rec.get("start") or "-", [0, 0, 0])
            st[0] += 1
            st[1] += s
            st[2] += b
    for name, (v, s, b) in sorted(starts.items()):
        print(f"  valid from start {name}: {v}, Steiner ours {s}, best known {b}, ratio {s / b:.2f}")
    if not args.table_only:
        print(f"acute --time-limit {args.time_limit} s per instance (wall-clock kill after {args.timeout} s)"
              + (f"; without an exact result, once more with --time-limit {args.retry_time_limit} s" if args.retry_time_limit else ""))
    retried = [r for r in results if r.get("retried")]
    if retried:
        print(f"retried with a longer time limit: {len(retried)}, of which solved: {sum(1 for r in retried if solved(r))}")
    by_rc = {}
    for rec in results:
        by_rc[str(rec.get("meshcheck_rc"))] = by_rc.get(str(rec.get("meshcheck_rc")), 0) + 1
    print("meshcheck exit codes: " + ", ".join(f"{k}: {v}" for k, v in sorted(by_rc.items())))


if __name__ == "__main__":
    main()
