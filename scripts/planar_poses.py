"""Planar poses from text files, shared by the scripts in this folder.

read_poses(path) reads a TUM file (t x y z qx qy qz qw; '#' comments) as [(t, x, y, theta)],
theta from the quaternion's z and w (its norm must be 1 within 1 %). With odometry_txt=True it also reads the absolute
odometry that MRPT's `rawlog-edit --export-odometry-txt` writes (t x y phi ...; '%'
comments). A malformed line raises InputError naming the file and line.
"""

import math


class InputError(Exception):
    pass


def read_poses(path, odometry_txt=False):
    out = []
    expected = "expected 8 numbers (t x y z qx qy qz qw)"
    if odometry_txt:
        expected += " or rawlog-edit odometry (t x y phi ...)"
    with open(path) as f:
        for n, line in enumerate(f, 1):
            s = line.strip()
            if not s or s.startswith("#") or (odometry_txt and s.startswith("%")):
                continue
            v = s.split()
            try:
                if len(v) == 8:
                    t, x, y, _, qx, qy, qz, qw = map(float, v)
                    if abs(math.sqrt(qx * qx + qy * qy + qz * qz + qw * qw) - 1) > 0.01:
                        raise InputError(f"{path}:{n}: the quaternion is not a unit one")
                    th = 2 * math.atan2(qz, qw)
                elif odometry_txt and len(v) >= 4:
                    t, x, y, th = map(float, v[:4])
                else:
                    raise ValueError
            except ValueError:
                raise InputError(f"{path}:{n}: {expected}")
            if not all(math.isfinite(a) for a in (t, x, y, th)):
                raise InputError(f"{path}:{n}: a value is not finite")
            out.append((t, x, y, th))
    return out
