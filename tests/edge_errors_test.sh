#!/usr/bin/env bash
# scripts/edge-errors.py: on a hand-made graph whose reference poses are known, exact edges
# have zero error and an edge moved by 0.5 m (along +y) is counted off and listed with that
# error, its normalized error 0.5 with unit information and 1.0 with 4; a node without a
# reference pose drops its edges; a malformed reference line fails with a message naming the
# file and line, and so does an edge without its information. Exits 77 (CTest: skipped)
# without python3.
# Usage: edge_errors_test.sh SOURCE_DIR BINARY_DIR
set -euo pipefail
src=$1
script=$src/scripts/edge-errors.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$src/tests/python_support.sh"
py=$(find_python)
if [[ -z $py ]]; then
  echo "SKIP edge_errors_test: no python3"
  exit 77
fi
fail() { echo "FAIL edge_errors_test: $*"; exit 1; }

# Reference: node 0 at the origin, node 1 at (2, 0) facing +y (quaternion of 90 deg), node 2
# at (2, 3) facing +y; node 3's stamp (3.0) has no reference pose, node 1's is 0.5 ms off.
q=0.70710678
cat > "$work/gt.tum" << EOF
# timestamp x y z qx qy qz qw
0.0 0 0 0 0 0 0 1
1.0 2 0 0 0 0 $q $q
2.0 2 3 0 0 0 $q $q
EOF
mkdir "$work/run"
cat > "$work/run/keyframes.tum" << EOF
# timestamp x y z qx qy qz qw
0.0 0 0 0 0 0 0 1
1.0005 0 0 0 0 0 0 1
2.0 0 0 0 0 0 0 1
3.0 0 0 0 0 0 0 1
EOF
# 1 -> 2 seen from node 1 (facing +y): 3 m ahead, no turn. The loop 0 -> 2 measures
# (2, 3.5, 90 deg) against the reference (2, 3, 90 deg): gt^-1 (+) z = (0.5, 0, 0), 0.5 m along
# the x axis of the reference relative pose's frame (which faces +y).
cat > "$work/run/graph.graph" << EOF
VERTEX_SE2 0 0 0 0
FIX 0
EDGE_SE2 0 1 2 0 1.5707963 1 0 0 1 0 1 # kind=consecutive
EDGE_SE2 1 2 3 0 0 1 0 0 1 0 1 # kind=consecutive
EDGE_SE2 0 2 2 3.5 1.5707963 1 0 0 1 0 1 # kind=loop
EDGE_SE2 0 2 2 3.5 1.5707963 4 0 0 4 0 4 # kind=loop
EDGE_SE2 2 3 1 0 0 1 0 0 1 0 1 # kind=consecutive
EOF
out=$("$py" "$script" "$work/run" "$work/gt.tum" --list)
echo "$out"
grep -q '^# 3 of 4 nodes have a reference pose$' <<< "$out" || fail "node count"
grep -q '^| consecutive | 2 | 0 | 0.000 | 0.000 | 0.00 | 0.00 | 0.00 | 0.00 |$' <<< "$out" || fail "exact edges"
grep -q '^| loop | 2 | 2 | 0.500 | 0.500 | 0.00 | 0.00 | 0.75 | 0.95 |$' <<< "$out" || fail "loop row"
[[ $(grep -c '^loop 0 2 0.500 0.000 0.00 3.61$' <<< "$out" || true) == 2 ]] || fail "listed loops"
[[ $(grep -c '^consecutive ' <<< "$out" || true) == 0 ]] || fail "exact edges listed"

# A larger bound lets the loop pass.
out=$("$py" "$script" "$work/run" "$work/gt.tum" --max-xy 0.6)
grep -q '^| loop | 2 | 0 |' <<< "$out" || fail "--max-xy"

# A malformed reference line: exit 1, file and line named.
printf '0.0 0 0\n' > "$work/bad.tum"
if err=$("$py" "$script" "$work/run" "$work/bad.tum" 2>&1); then fail "malformed input accepted"; fi
grep -q "bad.tum:1: expected 8 numbers" <<< "$err" || fail "message: $err"
# An edge without its 6 information values: exit 1, file and line named.
mkdir "$work/short"
cp "$work/run/keyframes.tum" "$work/short/"
printf 'VERTEX_SE2 0 0 0 0\nEDGE_SE2 0 1 2 0 1.5707963 1 0 0\n' > "$work/short/graph.graph"
if err=$("$py" "$script" "$work/short" "$work/gt.tum" 2>&1); then fail "edge without information accepted"; fi
grep -q "short/graph.graph:2: expected EDGE_SE2 FROM TO X Y THETA and 6 information values" <<< "$err" || fail "message: $err"
echo "PASS edge_errors_test"
