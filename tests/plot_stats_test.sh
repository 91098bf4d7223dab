#!/usr/bin/env bash
# scripts/plot-stats.py: a synthetic stats.csv gives fig6.png and fig7.png that load as
# images, with no temporary file left; bad inputs fail with a message naming the line
# and write nothing. Exits 77 (CTest: skipped) when no python3 has matplotlib.
# Usage: plot_stats_test.sh SOURCE_DIR BINARY_DIR
set -euo pipefail
src=$1
script=$src/scripts/plot-stats.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The python3 on PATH first, then Debian's (python3-matplotlib installs for that one).
source "$src/tests/python_support.sh"
py=$(find_python matplotlib)
if [[ -z $py ]]; then
  echo "SKIP plot_stats_test: no python3 with matplotlib (install python3-matplotlib)"
  exit 77
fi

header=scan,timestamp,source,valid_rays,correspondences,match_sq_residuals,active_sq_residuals,match_ms,tracking_ms,graph_ms,map_ms,keyframe,new_node,loops,full_optimization,switched_off,ambiguous,prior_decided
good=$work/stats.csv
{
  echo "$header"
  # 400 scans at 40 Hz: matched mostly, a few odometry fallbacks, a node every 10th
  # scan (graph and map work), a loop edge at scan 300.
  awk 'BEGIN {
    for (k = 0; k < 400; k++) {
      src = k == 0 ? "first" : (k % 97 == 0 ? "odometry" : (k % 131 == 0 ? "constant_motion" : (k % 89 == 0 ? "searched" : "match")));
      node = k % 10 == 0;
      printf "%d,%.6f,%s,%d,%d,%.6g,%.6g,%.3f,%.3f,%.3f,%.3f,%d,%d,%d,%d,0,0,0\n", k, 1700000000 + k / 40.0,
        src, 400 + 300 * sin(k / 30.0), 350 + 250 * sin(k / 30.0), 0.2 + 0.1 * cos(k / 7.0),
        5 + 2 * cos(k / 50.0), 0.3 + 0.05 * sin(k), 0.1, node ? 12 + sin(k) : 0, node ? 3.5 : 0,
        int(k / 10), node, k == 300, k == 300
    }
  }'
} > "$good"

out=$work/out
for axis in time scan; do
  rm -rf "$out"
  "$py" "$script" "$good" "$out" --x "$axis" > "$work/log.txt"
  for fig in fig6 fig7; do
    [[ -s $out/$fig.png ]] || { echo "$fig.png missing (--x $axis)" >&2; exit 1; }
    "$py" -c '
import sys, matplotlib.image as mi
a = mi.imread(sys.argv[1])
assert a.ndim == 3 and a.shape[0] > 300 and a.shape[1] > 600, a.shape
' "$out/$fig.png" || { echo "$fig.png does not load as an image" >&2; exit 1; }
  done
  [[ $(ls -A "$out") == $'fig6.png\nfig7.png' ]] || { echo "unexpected files:" >&2; ls -A "$out" >&2; exit 1; }
done
grep -q "wrote $out/fig7.png" "$work/log.txt"

# A stats.csv written before the prior_decided column is read as well.
sed '1s/,prior_decided$//; 2,$s/,0$//' "$good" > "$work/older.csv"
[[ $(head -1 "$work/older.csv" | tr ',' '\n' | wc -l) -eq 17 ]]
rm -rf "$out"
"$py" "$script" "$work/older.csv" "$out" > /dev/null
[[ -s $out/fig6.png && -s $out/fig7.png ]] || { echo "figures missing for an older stats.csv" >&2; exit 1; }

# Fig. 7 stays readable when a full optimization's sum dwarfs the rest: a log scale, and the
# full optimizations drawn apart (stars), out of the sliding window's line with the scans that
# carry their sum forward.
"$py" - "$script" "$good" <<'PY'
import importlib.util, math, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
spec = importlib.util.spec_from_file_location("plot_stats", sys.argv[1])
m = importlib.util.module_from_spec(spec)
spec.loader.exec_module(m)
cols = m.read_stats(sys.argv[2])
# The second-last scan's full optimization; the last scan carries its sum forward.
cols["active_sq_residuals"][-2:] = [1e6, 1e6]
cols["full_optimization"][-2:] = [1, 0]
fig = m.fig7(plt, cols, cols["scan"], "scan")
top = fig.axes[0]
assert top.get_yscale() == "log", top.get_yscale()
lines = {l.get_label(): l for l in top.get_lines()}
window = [v for v in lines["graph, sliding window: sum of w r^2 (eq. 11)"].get_ydata() if not math.isnan(v)]
full = list(lines["graph, full optimization (whole graph)"].get_ydata())
assert max(window) < 10 and 1e6 in full, (max(window), full)
assert 1e6 not in window
PY

# Bad inputs: each fails, names the problem (and the line), writes no figure.
bad() {  # name expected-message; the csv is on stdin
  cat > "$work/$1.csv"
  rm -rf "$out"
  if "$py" "$script" "$work/$1.csv" "$out" 2> "$work/err.txt"; then
    echo "bad input '$1' was accepted" >&2
    exit 1
  fi
  grep -qF -- "$2" "$work/err.txt" ||
    { echo "bad input '$1': message lacks '$2':" >&2; cat "$work/err.txt" >&2; exit 1; }
  [[ ! -e $out/fig6.png && ! -e $out/fig7.png ]] || { echo "figure written for '$1'" >&2; exit 1; }
  cat "$work/err.txt"
}
head -3 "$good" > "$work/head.csv"
{ cat "$work/head.csv"; echo "3,1700000000.075,match,abc,300,0.2,4.5,0.3,0.1,0,0,0,0,0,0,0,0,0"; } |
  bad garbage "garbage.csv:4: column 'valid_rays': 'abc' is not a non-negative integer"
{ cat "$work/head.csv"; echo "3,1700000000.075,match,400,300,,4.5,0.3,0.1,0,0,0,0,0,0,0,0,0"; } |
  bad missing "missing.csv:4: column 'match_sq_residuals': missing value"
{ cat "$work/head.csv"; echo "3,1700000000.075,guess,400,300,0.2,4.5,0.3,0.1,0,0,0,0,0,0,0,0,0"; } |
  bad source "source.csv:4: column 'source': 'guess' is not one of first|match|searched|odometry|constant_motion"
{ cat "$work/head.csv"; echo "3,1700000000.075,match,400,300,0.2,4.5,nan,0.1,0,0,0,0,0,0,0,0,0"; } |
  bad nan "nan.csv:4: column 'match_ms': 'nan' is not a finite number"
{ cat "$work/head.csv"; echo "3,1700000000.075,match,400,300,0.2,4.5,0.3,0.1"; } |
  bad short "short.csv:4: 9 values, expected 18"
{ cat "$work/head.csv"; echo "1,1700000000.075,match,400,300,0.2,4.5,0.3,0.1,0,0,0,0,0,0,0,0,0"; } |
  bad order "order.csv:4: scan 1 does not follow scan 1"
sed '1s/loops/loop/' "$good" | bad header "header.csv:1: header is"
echo "$header" | bad empty "empty.csv: no scan rows"
: | bad nothing "nothing.csv: empty file"

# An output path that is a file is an error.
touch "$work/file"
if "$py" "$script" "$good" "$work/file" 2> "$work/err.txt"; then
  echo "a file as output folder was accepted" >&2
  exit 1
fi
grep -q "is not a folder" "$work/err.txt"
echo "plot_stats_test: OK"
