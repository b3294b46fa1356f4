#!/usr/bin/env python3
"""Splits the failures of a stress run (scripts/stress/run.sh) by one cause we cannot remove.

Usage: scripts/stress/classify.py OUT      (the run's work directory: log.txt and sSEED.poly)

A segment that is long in y but spans fewer than 64 doubles in x (the generator's "nearly
collinear 1e-15" subdivisions of a vertical wall) can carry at most that many Steiner points: the
referee walks a segment's chain along x unless its ends share x, and needs every point to advance
strictly, so no double-coordinate mesh can grade finely along it. (A nearly level wall, few doubles
high in y, is no such limit: the chain may repeat y. Before 2026-12-07 our own chain order was
strict in y too, and such walls failed as well: their count is printed apart.) Prints the
pass rate with and without the domains that have such a segment, and the failing seeds of each kind.
"""
import math
import sys


def tight_segments(path):
    rows = [l.split('#')[0].split() for l in open(path)]
    rows = [r for r in rows if r]
    n = int(rows[0][0])
    pts = {int(rows[i][0]): (float(rows[i][1]), float(rows[i][2])) for i in range(1, n + 1)}
    m = int(rows[n + 1][0])
    count = [0, 0]  # [tight in x: the referee's limit, tight in y: level]
    for j in range(m):
        a, b = pts[int(rows[n + 2 + j][1])], pts[int(rows[n + 2 + j][2])]
        for i in (0, 1):
            if a[i] == b[i]:
                continue
            doubles = abs(a[i] - b[i]) / math.ulp(max(abs(a[i]), abs(b[i])))
            if doubles < 64 and abs(a[1 - i] - b[1 - i]) > 1000 * abs(a[i] - b[i]):
                count[i] += 1
    return count


def main():
    out = sys.argv[1]
    runs = [l.split() for l in open(f"{out}/log.txt") if l.strip()]
    kinds = {True: [0, []], False: [0, []]}
    level = [0, 0]  # domains with a level-tight segment (and none tight in x): run, passed
    for seed, verdict, *_ in runs:
        in_x, in_y = tight_segments(f"{out}/s{seed}.poly")
        tight = in_x > 0
        kinds[tight][0] += 1
        if verdict != 'ok':
            kinds[tight][1].append(f"{seed}:{verdict}")
        if not tight and in_y > 0:
            level[0] += 1
            level[1] += verdict == 'ok'
    print(f"(of those without: {level[0]} have a nearly level segment under 64 doubles high in y; {level[1]} meet the bounds)")
    for tight, label in ((False, "without"), (True, "with")):
        total, failing = kinds[tight]
        print(f"{label} a segment under 64 doubles wide in x: {total - len(failing)}/{total} meet the bounds; failing: {' '.join(failing) or 'none'}")


if __name__ == '__main__':
    main()
