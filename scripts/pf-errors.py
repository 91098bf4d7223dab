#!/usr/bin/env python3
"""Scores MRPT pf-localization's run against reference poses (scripts/bench-localize.sh).

Reads the estimate pf-localization logs after each step ("PDF estimation: (x,y,phi)") of an
observations-only rawlog holding an odometry reading before each scan (step 2k+1 is scan k),
maps the log's reference poses into the map's frame (the map's nodes aligned on the map run's
reference poses by their stamps), and prints the step at which the estimate came within 0.5 m
to stay, and the position error from then on.

usage: pf-errors.py PF_LOG KEYFRAMES_TUM MAP_TRUTH_TUM LOG_TRUTH_TUM FIRST_STAMP RATE_HZ
"""
import bisect
import math
import re
import sys

import numpy as np


def tum(path):
    rows = []
    for line in open(path):
        if line.startswith('#') or not line.strip():
            continue
        v = [float(x) for x in line.split()]
        rows.append((v[0], v[1], v[2], 2 * math.atan2(v[6], v[7])))
    rows.sort()
    return rows


def at(rows, t, tol=1e-3):
    stamps = [r[0] for r in rows]
    i = bisect.bisect_left(stamps, t)
    for j in (i - 1, i):
        if 0 <= j < len(rows) and abs(rows[j][0] - t) <= tol:
            return rows[j]
    return None


def main():
    pf_log, keyframes, map_truth, log_truth, first_stamp, rate = sys.argv[1:7]
    first_stamp, rate = float(first_stamp), float(rate)
    nodes, world = [], []
    map_rows = tum(map_truth)
    for t, x, y, _ in tum(keyframes):
        g = at(map_rows, t)
        if g:
            nodes.append((x, y))
            world.append((g[1], g[2]))
    a, b = np.array(world), np.array(nodes)
    ma, mb = a.mean(0), b.mean(0)
    u, _, vt = np.linalg.svd((a - ma).T @ (b - mb))
    d = np.diag([1, np.sign(np.linalg.det(vt.T @ u.T))])
    rot = vt.T @ d @ u.T
    shift = mb - rot @ ma
    truth = tum(log_truth)

    steps = re.compile(r'Step (\d+)\. Executing')
    estimate = re.compile(r'PDF estimation: \(([-\d.e+]+),([-\d.e+]+),([-\d.e+]+)deg\)')
    errors, step = [], None
    times = re.compile(r'Done in ([\d.]+)ms')
    ms = []
    for line in open(pf_log):
        m = steps.search(line)
        if m:
            step = int(m.group(1))
            continue
        m = times.search(line)
        if m:
            ms.append(float(m.group(1)))
            continue
        m = estimate.search(line)
        if m and step is not None:
            scan = (step - 1) // 2
            g = at(truth, first_stamp + scan / rate)
            if g is None:
                continue
            p = rot @ np.array([g[1], g[2]]) + shift
            errors.append((scan, math.hypot(float(m.group(1)) - p[0], float(m.group(2)) - p[1])))
    if not errors:
        sys.exit('pf-errors: no estimate in ' + pf_log)
    settled = None
    for k in range(len(errors)):
        if all(e <= 0.5 for _, e in errors[k:]):
            settled = k
            break
    print('pf-localization: %d scans, %.0f ms a step (mean)' % (len(errors), sum(ms) / max(1, len(ms))))
    if settled is None:
        print('   never within 0.5 m to stay; error at the end %.2f m' % errors[-1][1])
        return
    rest = [e for _, e in errors[settled:]]
    print('   within 0.5 m to stay from scan %d (%.1f s of log); then RMS %.4f m, max %.4f m'
          % (errors[settled][0], errors[settled][0] / rate, math.sqrt(sum(e * e for e in rest) / len(rest)),
             max(rest)))


if __name__ == '__main__':
    main()
