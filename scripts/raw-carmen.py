#!/usr/bin/env python3
"""Writes a raw-format CARMEN log (FLASER lines whose odom_x odom_y odom_theta fields carry a
drifting wheel odometry, no ODOM line), like the Freiburg benchmark's .clf files, and its
reference trajectory as TUM. Two sources of scans:

  raw-carmen.py room OUT.log[.gz] REF.tum [--scans N] [--seed S]
      a simulated room (a 12 x 9 m hall with four pillars and a wall stub), 181 beams over
      180 deg, 1 cm range noise; the robot drives laps of a rounded rectangle.
  raw-carmen.py corrected IN-corrected.log[.gz] OUT.log[.gz] REF.tum [--scans N] [--seed S]
      the FLASER scans of a corrected log (../shared/datasets), with their reference poses.

Odometry: each step's true motion in the robot frame, the forward distance scaled by 1.02, plus
0.02 rad of yaw per metre driven (a wheel-diameter difference) and Gaussian noise (1 cm per
metre, 0.005 rad per step), integrated from the first reference pose; seeded, so the same
arguments write the same file. As in a raw log, the line's x y theta are the odometry too.
Timestamps: 1000 + 0.2 k s for scan k (the corrected logs' own are broken, doc/carmen.md).
"""
import argparse
import gzip
import io
import math
import random


def open_text(path, mode):
    if not path.endswith(".gz"):
        return open(path, mode)
    if mode == "r":
        return gzip.open(path, "rt")
    return io.TextIOWrapper(gzip.GzipFile(path, "wb", mtime=0))  # the same bytes every time


def wrap(a):
    return math.atan2(math.sin(a), math.cos(a))


def relative(a, b):
    """b in a's frame (a^-1 + b)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    c, s = math.cos(a[2]), math.sin(a[2])
    return (c * dx + s * dy, -s * dx + c * dy, wrap(b[2] - a[2]))


def compose(a, d):
    c, s = math.cos(a[2]), math.sin(a[2])
    return (a[0] + c * d[0] - s * d[1], a[1] + s * d[0] + c * d[1], wrap(a[2] + d[2]))


def drifting_odometry(reference, rng):
    odo = [reference[0]]
    for a, b in zip(reference, reference[1:]):
        dx, dy, dth = relative(a, b)
        dist = math.hypot(dx, dy)
        step = (1.02 * dx + rng.gauss(0, 0.01 * dist), 1.02 * dy + rng.gauss(0, 0.01 * dist),
                dth + 0.02 * dist + rng.gauss(0, 0.005))
        odo.append(compose(odo[-1], step))
    return odo


# --- the simulated room -------------------------------------------------------------------
def room_segments():
    segs = []

    def box(x0, y0, x1, y1):
        segs.extend([((x0, y0), (x1, y0)), ((x1, y0), (x1, y1)), ((x1, y1), (x0, y1)), ((x0, y1), (x0, y0))])

    box(0, 0, 12, 9)  # the hall
    for cx, cy in ((3, 3), (9, 3), (3, 6), (9.5, 6.5)):
        box(cx - 0.25, cy - 0.25, cx + 0.25, cy + 0.25)  # pillars
    segs.append(((6, 0), (6, 2.2)))  # a wall stub
    box(5.2, 6.8, 6.8, 7.4)  # a table
    return segs


def cast(segs, x, y, a, max_range):
    dx, dy = math.cos(a), math.sin(a)
    best = max_range
    for (x1, y1), (x2, y2) in segs:
        ex, ey = x2 - x1, y2 - y1
        den = dx * ey - dy * ex
        if abs(den) < 1e-12:
            continue
        t = ((x1 - x) * ey - (y1 - y) * ex) / den
        u = ((x1 - x) * dy - (y1 - y) * dx) / den
        if 0 < t < best and 0 <= u <= 1:
            best = t
    return best


def room_path(n):
    """Laps of a rounded rectangle (x in 1.8..10.2, y in 1.6..7.4, corners of radius 1), 0.3 m apart."""
    x0, x1, y0, y1, r = 1.8, 10.2, 1.6, 7.4, 1.0
    pieces = []  # (length, function of s -> pose)
    straight = lambda p, h, L: (L, lambda s: (p[0] + s * math.cos(h), p[1] + s * math.sin(h), h))

    def arc(c, h0):
        return (r * math.pi / 2, lambda s: (c[0] + r * math.cos(h0 - math.pi / 2 + s / r),
                                             c[1] + r * math.sin(h0 - math.pi / 2 + s / r), wrap(h0 + s / r)))

    pieces = [straight((x0 + r, y0), 0, x1 - x0 - 2 * r), arc((x1 - r, y0 + r), 0),
              straight((x1, y0 + r), math.pi / 2, y1 - y0 - 2 * r), arc((x1 - r, y1 - r), math.pi / 2),
              straight((x1 - r, y1), math.pi, x1 - x0 - 2 * r), arc((x0 + r, y1 - r), math.pi),
              straight((x0, y1 - r), -math.pi / 2, y1 - y0 - 2 * r), arc((x0 + r, y0 + r), -math.pi / 2)]
    lap = sum(p[0] for p in pieces)
    poses = []
    for k in range(n):
        s = (0.3 * k) % lap
        for length, f in pieces:
            if s <= length:
                poses.append(f(s))
                break
            s -= length
    return poses


def room_scans(n, rng):
    segs = room_segments()
    reference = room_path(n)
    scans = []
    for x, y, th in reference:
        ranges = []
        for i in range(181):
            r = cast(segs, x, y, th - math.pi / 2 + math.pi * i / 180, 30)
            ranges.append(30.0 if r >= 30 else max(0.02, r + rng.gauss(0, 0.01)))
        scans.append(ranges)
    return reference, scans, ["PARAM robot_front_laser_max 30 nohost 0"]


def corrected_scans(path, n):
    reference, scans, params = [], [], []
    with open_text(path, "r") as f:
        for line in f:
            tok = line.split()
            if tok and tok[0] == "PARAM":
                params.append(line.rstrip("\n"))
            if not tok or tok[0] != "FLASER":
                continue
            k = int(tok[1])
            scans.append([float(v) for v in tok[2:2 + k]])
            reference.append(tuple(float(v) for v in tok[2 + k:5 + k]))
            if n and len(scans) == n:
                break
    return reference, scans, params


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("source", choices=["room", "corrected"])
    ap.add_argument("files", nargs="+", help="[IN] OUT.log[.gz] REF.tum")
    ap.add_argument("--scans", type=int, default=0, help="at most this many (room: default 120)")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    if a.source == "room":
        if len(a.files) != 2:
            ap.error("room: OUT.log REF.tum")
        reference, scans, params = room_scans(a.scans or 120, rng)
        out, ref = a.files
        origin = "a simulated room (scripts/raw-carmen.py room)"
    else:
        if len(a.files) != 3:
            ap.error("corrected: IN.log OUT.log REF.tum")
        reference, scans, params = corrected_scans(a.files[0], a.scans)
        out, ref = a.files[1:]
        origin = "the FLASER scans of " + a.files[0].split("/")[-1]
    odometry = drifting_odometry(reference, rng)
    with open_text(out, "w") as f:
        f.write("# raw-format CARMEN log written by scripts/raw-carmen.py (seed %d): scans of %s;\n" % (a.seed, origin))
        f.write("# FLASER x y theta and odom_x odom_y odom_theta are a drifting odometry; no ODOM line\n")
        for p in params:
            f.write(p + "\n")
        for k, (ranges, o) in enumerate(zip(scans, odometry)):
            t = "%.3f" % (1000 + 0.2 * k)
            pose = "%.6f %.6f %.6f" % o
            f.write("FLASER %d %s %s %s %s sim %s\n" % (len(ranges), " ".join("%.3f" % r for r in ranges), pose, pose, t, t))
    with open(ref, "w") as f:
        f.write("# timestamp x y z qx qy qz qw: reference poses of %s\n" % out.split("/")[-1])
        for k, (x, y, th) in enumerate(reference):
            f.write("%.3f %.6f %.6f 0 0 0 %.9f %.9f\n" % (1000 + 0.2 * k, x, y, math.sin(th / 2), math.cos(th / 2)))


if __name__ == "__main__":
    main()
