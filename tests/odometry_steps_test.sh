#!/usr/bin/env bash
# scripts/odometry-steps.py: a trajectory that follows the odometry (interpolated between its
# readings, the heading turning across +-pi) has no step error; one pose moved by 0.3 m makes its
# two steps 0.3 m off and they are listed; poses outside the odometry's span are not counted;
# a malformed odometry line, or a trajectory's quaternion that is not a unit one, fails with
# a message naming the file and line. Exits 77 (CTest: skipped) without python3.
# Usage: odometry_steps_test.sh SOURCE_DIR BINARY_DIR
set -euo pipefail
src=$1
script=$src/scripts/odometry-steps.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$src/tests/python_support.sh"
py=$(find_python)
if [[ -z $py ]]; then
  echo "SKIP odometry_steps_test: no python3"
  exit 77
fi
fail() { echo "FAIL odometry_steps_test: $*"; exit 1; }

# Odometry as rawlog-edit exports it, 10 Hz: a straight line at 1 m/s while the heading turns
# at 0.5 rad/s from 170 deg, past 180 deg (linear in time, so interpolation is exact).
"$py" - "$work" << 'EOF2'
import math, sys
work = sys.argv[1]
def pose(t):
    a = math.radians(170) + 0.5 * t
    return t * math.cos(0.3), t * math.sin(0.3), math.atan2(math.sin(a), math.cos(a))
with open(f"{work}/odo.txt", "w") as f:
    f.write("%             Time       GLOBAL_ODO_X       GLOBAL_ODO_Y GLOBAL_ODO_PHI_RAD HAS_ENCODERS\n")
    for k in range(60):
        t = 10 + 0.1 * k
        x, y, th = pose(t - 10)
        f.write(f"{t:.3f} {x:.9f} {y:.9f} {th:.9f} 0\n")
def tum(path, moved):
    with open(path, "w") as f:
        f.write("# timestamp x y z qx qy qz qw\n")
        t = 9.9  # before the odometry: not counted
        for k in range(40):
            x, y, th = pose(t - 10)
            if moved and k == 20:
                x += 0.3
            f.write(f"{t:.4f} {x:.9f} {y:.9f} 0 0 0 {math.sin(th / 2):.9f} {math.cos(th / 2):.9f}\n")
            t += 0.066 if k % 2 else 0.134  # irregular scan times, between readings
tum(f"{work}/follows.tum", False)
tum(f"{work}/moved.tum", True)
EOF2

out=$("$py" "$script" "$work/follows.tum" "$work/odo.txt")
[[ $out == "steps=38 median_m=0.0000 p95_m=0.0000 over_5cm=0 over_20cm=0" ]] || fail "follows: $out"

out=$("$py" "$script" "$work/moved.tum" "$work/odo.txt" --list)
# Here-strings, not pipes: under pipefail a writer that head or grep -q leaves early gets
# SIGPIPE, and the check failed on a loaded machine although the output was right.
[[ ${out%%$'\n'*} =~ ^steps=38\ .*\ over_5cm=2\ over_20cm=2$ ]] || fail "moved: $out"
grep -q "^scan 20 0.300$" <<< "$out" || fail "moved, scan 20 not listed: $out"
grep -q "^scan 21 0.300$" <<< "$out" || fail "moved, scan 21 not listed: $out"
[[ $(grep -c "^scan " <<< "$out") -eq 2 ]] || fail "moved, more steps listed: $out"

echo "10.0 0 0 x 0" > "$work/bad.txt"
if "$py" "$script" "$work/follows.tum" "$work/bad.txt" 2> "$work/err"; then fail "malformed line accepted"; fi
grep -q "bad.txt:1:" "$work/err" || fail "error does not name the line: $(cat "$work/err")"
printf '# t x y z qx qy qz qw\n10.0 0 0 0 0 0 0 0\n' > "$work/zero.tum"
if "$py" "$script" "$work/zero.tum" "$work/odo.txt" 2> "$work/err"; then fail "zero quaternion accepted"; fi
grep -q "zero.tum:2: the quaternion is not a unit one" "$work/err" || fail "zero quaternion: $(cat "$work/err")"
echo "PASS odometry_steps_test"
