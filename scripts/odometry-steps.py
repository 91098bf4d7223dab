#!/usr/bin/env python3
"""Per-scan motions of a trajectory against a log's odometry, for logs without ground truth.

Usage: python3 scripts/odometry-steps.py EST.tum ODOMETRY [--max-error M] [--list]

EST.tum is a TUM file (one pose per scan, as swslam's trajectory.tum).
ODOMETRY is the log's absolute odometry: either the text file that MRPT's
`rawlog-edit --export-odometry-txt` writes (columns time, x, y, phi, ...; lines starting
with % are comments), or a TUM file. The odometry pose at each time of EST.tum is
interpolated linearly between the two readings around it, with the heading unwrapped. A pose
outside the odometry's time span has none, and the steps that touch it are not counted.

Odometry drifts over a run, but from one scan to the next it is accurate. A step of EST
(the relative motion between consecutive poses) that differs from the odometry's step by
centimetres is therefore a tracking error. The script prints the steps compared, the median
and 95th percentile of the translation error, and how many steps are off by more than 5 cm
and 20 cm. With --list it also prints each step over --max-error metres (0.05): its scan
index (the later pose's, counting from 0) and its error (doc/tracking.md).

A malformed line is an error naming the file and line. Writes to stdout only. Python 3, no
other package.
"""

import argparse
import bisect
import math
import sys

from planar_poses import InputError, read_poses


def read_odometry(path):
    """The odometry's poses; none is an error."""
    out = read_poses(path, odometry_txt=True)
    if not out:
        raise InputError(f"{path}: no poses")
    return out


def unwrapped(poses):
    """The same poses with headings that never jump by more than pi from one to the next."""
    out, offset, prev = [], 0.0, None
    for t, x, y, th in poses:
        if prev is not None:
            d = th + offset - prev
            offset -= 2 * math.pi * round(d / (2 * math.pi))
        prev = th + offset
        out.append((t, x, y, prev))
    return out


def interpolate(odometry, times, t):
    """Odometry pose at time t (None outside its span); odometry sorted by time, unwrapped,
    `times` its times."""
    k = bisect.bisect_left(times, t)
    if k < len(times) and times[k] == t:
        return odometry[k][1:]
    if k == 0 or k == len(times):
        return None
    (t0, *a), (t1, *b) = odometry[k - 1], odometry[k]
    s = (t - t0) / (t1 - t0)
    return tuple(u + s * (w - u) for u, w in zip(a, b))


def relative(a, b):
    """b seen from a: (dx, dy) in a's frame."""
    c, s = math.cos(a[2]), math.sin(a[2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return c * dx + s * dy, -s * dx + c * dy


def step_errors(est, odometry):
    """[(scan index, error)] of each step of est with an odometry pose at both ends."""
    odo = unwrapped(sorted(odometry))
    times = [p[0] for p in odo]
    at = [interpolate(odo, times, t) for t, *_ in est]
    out = []
    for k in range(1, len(est)):
        if at[k - 1] is None or at[k] is None:
            continue
        e = relative(est[k - 1][1:], est[k][1:])
        o = relative(at[k - 1], at[k])
        out.append((k, math.hypot(e[0] - o[0], e[1] - o[1])))
    return out


def quantile(sorted_values, q):
    return sorted_values[min(len(sorted_values) - 1, int(q * (len(sorted_values) - 1) + 0.5))]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("est")
    ap.add_argument("odometry")
    ap.add_argument("--max-error", type=float, default=0.05)
    ap.add_argument("--list", action="store_true")
    args = ap.parse_args()
    try:
        errors = step_errors(read_poses(args.est), read_odometry(args.odometry))
    except (InputError, OSError) as e:
        print(f"odometry-steps: {e}", file=sys.stderr)
        return 1
    if not errors:
        print("odometry-steps: no step of the trajectory lies within the odometry's time span",
              file=sys.stderr)
        return 1
    values = sorted(e for _, e in errors)
    print(f"steps={len(errors)} median_m={quantile(values, 0.5):.4f} p95_m={quantile(values, 0.95):.4f} "
          f"over_5cm={sum(e > 0.05 for e in values)} over_20cm={sum(e > 0.2 for e in values)}")
    if args.list:
        for k, e in errors:
            if e > args.max_error:
                print(f"scan {k} {e:.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
