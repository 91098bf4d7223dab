#!/usr/bin/env python3
"""Errors of a run's graph edges against reference poses, by edge kind.

Usage: python3 scripts/edge-errors.py RUN_DIR GT.tum [--max-xy M] [--max-theta-deg D] [--list]

RUN_DIR holds the run's graph.graph (EDGE_SE2 lines with "# kind=NAME") and keyframes.tum
(node i on the i-th pose line, stamped with its scan's time). Each node takes the reference
pose of GT.tum with the same timestamp (within 1 ms); edges with a node without one are not
counted. An edge's error is the reference relative pose composed with the measurement,
gt^-1 (+) z, in the frame of the reference relative pose. Per kind, the table gives the edges,
those off by more than --max-xy metres (0.1) or --max-theta-deg degrees (2), and the median
and 90th percentile of both errors. --list prints each edge over a bound (kind, from, to,
error x, y, theta in degrees, reference length), which shows where a graph goes wrong and
which edge kinds carry the error (doc/tracking.md). The last two columns are the median and
90th percentile of the normalized error sqrt(e^T Omega e), Omega the edge's information: about
1.5 at the median for edges whose covariances match their errors (three degrees of freedom).

A malformed line is an error naming the file and line. Writes to stdout only. Python 3, no
other package.
"""

import argparse
import bisect
import math
import sys

from planar_poses import InputError, read_poses


def read_edges(path):
    """[(from, to, (x, y, theta), kind, information)] of the EDGE_SE2 lines of a graph file;
    information as its upper triangle (xx, xy, xt, yy, yt, tt)."""
    out = []
    with open(path) as f:
        for n, line in enumerate(f, 1):
            if not line.startswith("EDGE_SE2"):
                continue
            body, _, comment = line.partition("#")
            v = body.split()
            kind = comment.split("kind=")[1].split()[0] if "kind=" in comment else "unknown"
            try:
                a, b = int(v[1]), int(v[2])
                z = tuple(float(x) for x in v[3:6])
                info = tuple(float(x) for x in v[6:12])
                if len(info) != 6:
                    raise ValueError("short information")
            except (ValueError, IndexError):
                raise InputError(f"{path}:{n}: expected EDGE_SE2 FROM TO X Y THETA and 6 information values")
            out.append((a, b, z, kind, info))
    return out


def wrap(a):
    return math.atan2(math.sin(a), math.cos(a))


def relative(a, b):
    """a^-1 (+) b for planar poses (x, y, theta)."""
    c, s = math.cos(a[2]), math.sin(a[2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return (c * dx + s * dy, -s * dx + c * dy, wrap(b[2] - a[2]))


def fmt(v, digits):
    """v with `digits` decimals, never "-0.00"."""
    return f"{round(v, digits) + 0.0:.{digits}f}"


def percentile(values, q):
    v = sorted(values)
    if not v:
        return float("nan")
    k = (len(v) - 1) * q
    lo = math.floor(k)
    hi = min(lo + 1, len(v) - 1)
    return v[lo] + (v[hi] - v[lo]) * (k - lo)


def node_truth(keyframes, gt, tolerance=1e-3):
    """Reference pose of each node (None when GT has no pose within tolerance of its stamp)."""
    stamps = sorted((p[0], p[1:]) for p in gt)
    times = [t for t, _ in stamps]
    out = []
    for t, *_ in keyframes:
        i = bisect.bisect_left(times, t)
        best = None
        for j in (i - 1, i):
            if 0 <= j < len(times) and abs(times[j] - t) <= tolerance:
                if best is None or abs(times[j] - t) < abs(times[best] - t):
                    best = j
        out.append(stamps[best][1] if best is not None else None)
    return out


def normalized(e, info):
    """sqrt(e^T Omega e), Omega given by its upper triangle (xx, xy, xt, yy, yt, tt)."""
    xx, xy, xt, yy, yt, tt = info
    q = (xx * e[0] * e[0] + yy * e[1] * e[1] + tt * e[2] * e[2]
         + 2 * (xy * e[0] * e[1] + xt * e[0] * e[2] + yt * e[1] * e[2]))
    return math.sqrt(max(q, 0.0))


def edge_errors(edges, truth):
    """[(kind, from, to, (ex, ey, etheta), reference length, normalized error)] of the edges with
    both nodes known."""
    out = []
    for a, b, z, kind, info in edges:
        if a >= len(truth) or b >= len(truth):
            raise InputError(f"edge {a} -> {b}: node beyond keyframes.tum ({len(truth)} nodes)")
        if truth[a] is None or truth[b] is None:
            continue
        g = relative(truth[a], truth[b])
        e = relative(g, z)
        out.append((kind, a, b, e, math.hypot(g[0], g[1]), normalized(e, info)))
    return out


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("gt")
    ap.add_argument("--max-xy", type=float, default=0.1)
    ap.add_argument("--max-theta-deg", type=float, default=2.0)
    ap.add_argument("--list", action="store_true")
    args = ap.parse_args(argv)
    try:
        keyframes = read_poses(f"{args.run_dir}/keyframes.tum")
        truth = node_truth(keyframes, read_poses(args.gt))
        errors = edge_errors(read_edges(f"{args.run_dir}/graph.graph"), truth)
    except (InputError, OSError) as e:
        print(f"edge-errors: {e}", file=sys.stderr)
        return 1
    max_th = math.radians(args.max_theta_deg)
    bad = lambda e: math.hypot(e[0], e[1]) > args.max_xy or abs(e[2]) > max_th
    print(f"# {sum(t is not None for t in truth)} of {len(truth)} nodes have a reference pose")
    print("| kind | edges | off | median xy [m] | p90 xy [m] | median theta [deg] | p90 theta [deg] | "
          "median normalized | p90 normalized |")
    print("|---|---|---|---|---|---|---|---|---|")
    for kind in sorted({k for k, *_ in errors}):
        rows = [r for r in errors if r[0] == kind]
        xy = [math.hypot(r[3][0], r[3][1]) for r in rows]
        th = [math.degrees(abs(r[3][2])) for r in rows]
        chi = [r[5] for r in rows]
        print(f"| {kind} | {len(rows)} | {sum(bad(r[3]) for r in rows)} | {fmt(percentile(xy, 0.5), 3)} | "
              f"{fmt(percentile(xy, 0.9), 3)} | {fmt(percentile(th, 0.5), 2)} | {fmt(percentile(th, 0.9), 2)} | "
              f"{fmt(percentile(chi, 0.5), 2)} | {fmt(percentile(chi, 0.9), 2)} |")
    if args.list:
        for kind, a, b, e, length, _ in errors:
            if bad(e):
                print(f"{kind} {a} {b} {fmt(e[0], 3)} {fmt(e[1], 3)} {fmt(math.degrees(e[2]), 2)} {fmt(length, 2)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
