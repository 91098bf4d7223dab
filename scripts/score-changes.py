#!/usr/bin/env python3
"""Scores a resumed run's change report against the simulator's changes (scripts/bench-long.sh).

Usage: python3 scripts/score-changes.py FIRST_GT_TUM CHANGES_CSV CHANGES_MD

  FIRST_GT_TUM  the session's reference poses: its first pose is the map frame's origin
  CHANGES_CSV   swslam-sim's NAME.changes.csv (kind removed|added, x, y, radius; world frame)
  CHANGES_MD    the resumed run's changes.md (doc/sessions.md)

A true change is found when a region of its kind (removed: disappeared, added: appeared) has
its centroid within the rock's radius + 1 m of it; a region that finds no true change is a
false change. Prints one line per true change, then "found F of N; false changes K".
"""

import math
import sys


def fail(message):
    sys.exit("score-changes: " + message)


def main():
    if len(sys.argv) != 4:
        fail("usage: score-changes.py FIRST_GT_TUM CHANGES_CSV CHANGES_MD")
    gt_path, csv_path, md_path = sys.argv[1:]
    rows = [line.split() for line in open(gt_path) if line.strip() and not line.startswith("#")]
    if not rows or len(rows[0]) != 8:
        fail(f"{gt_path}: no TUM pose")
    x0, y0, qz, qw = (float(rows[0][i]) for i in (1, 2, 6, 7))
    yaw = 2 * math.atan2(qz, qw)
    c, s = math.cos(-yaw), math.sin(-yaw)

    truth = []
    lines = open(csv_path).read().splitlines()
    if not lines or lines[0] != "kind,x,y,radius":
        fail(f"{csv_path}: not a changes.csv")
    for n, line in enumerate(lines[1:], start=2):
        try:
            kind, x, y, r = line.split(",")
            dx, dy = float(x) - x0, float(y) - y0
        except ValueError:
            fail(f"{csv_path} line {n}: expected kind,x,y,radius")
        truth.append(("appeared" if kind == "added" else "disappeared", c * dx - s * dy, s * dx + c * dy, float(r)))

    regions = []
    for line in open(md_path):
        if line.startswith("| appeared |") or line.startswith("| disappeared |"):
            f = [t.strip() for t in line.strip().strip("|").split("|")]
            regions.append((f[0], float(f[1]), float(f[2]), float(f[3])))

    used, found = set(), 0
    for kind, x, y, r in truth:
        near = [i for i, g in enumerate(regions) if g[0] == kind and math.hypot(g[1] - x, g[2] - y) <= r + 1.0]
        used.update(near)
        found += bool(near)
        print(f"  {kind:11s} at ({x:7.2f}, {y:7.2f}), radius {r:.2f} m: {'found' if near else 'MISSED'}")
    false = [g for i, g in enumerate(regions) if i not in used]
    for g in false:
        print(f"  false change: {g[0]} at ({g[1]:.2f}, {g[2]:.2f}), extent {g[3]:.2f} m")
    print(f"found {found} of {len(truth)}; false changes {len(false)}")


if __name__ == "__main__":
    main()
