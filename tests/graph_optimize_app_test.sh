#!/usr/bin/env bash
# End to end: swslam-graph-optimize on MRPT's circle graph (TORO form) and on bad input.
# Args: SOURCE_DIR BINARY_DIR
set -euo pipefail
BIN="$2/apps/swslam-graph-optimize"
IN=/usr/share/mrpt/datasets/graph_2d_circle_50nodes.graph
DIR="$(mktemp -d)"
trap 'rm -rf "$DIR"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$BIN" -i "$IN" -o "$DIR/out.g2o" --alpha 2 --max-iters 50 > "$DIR/log.txt" || fail "optimize failed"
cat "$DIR/log.txt"
grep -q "loaded 50 vertices, 101 edges, 0 skipped lines" "$DIR/log.txt" || fail "load summary"
grep -q "status: converged" "$DIR/log.txt" || fail "not converged"
final=$(awk '/final chi2/ {print $3}' "$DIR/log.txt")
awk -v c="$final" 'BEGIN { exit !(c < 0.01) }' || fail "final chi2 $final"
[ "$(grep -c '^VERTEX_SE2' "$DIR/out.g2o")" = 50 ] || fail "vertices written"
[ "$(grep -c '^EDGE_SE2' "$DIR/out.g2o")" = 101 ] || fail "edges written"
grep -q '^FIX 0$' "$DIR/out.g2o" || fail "gauge written"

# The written graph is already optimal: optimizing it again changes nothing.
"$BIN" -i "$DIR/out.g2o" -o "$DIR/again.g2o" --alpha -inf --c 2 > "$DIR/again.txt" || fail "re-optimize"
again=$(awk '/initial chi2/ {print $3}' "$DIR/again.txt")
awk -v c="$again" 'BEGIN { exit !(c != "" && c < 0.01) }' || fail "reloaded graph is not the optimum: '$again'"

# Garbage lines are skipped with their line numbers.
{ head -3 "$IN"; echo "this is not a graph line"; tail -n +4 "$IN"; } > "$DIR/garbage.graph"
"$BIN" -i "$DIR/garbage.graph" -o "$DIR/g.g2o" > "$DIR/garbage.txt" || fail "garbage file rejected"
grep -q "1 skipped lines" "$DIR/garbage.txt" || fail "skip count"
grep -q "skipped line 4: unknown keyword 'this'" "$DIR/garbage.txt" || fail "skip line number"

# A vertex that only an edge names is placed from it (an edge-only g2o file).
echo "EDGE2 0 99 1 0 0 1 0 1 1 0 0" >> "$DIR/garbage.graph"
"$BIN" -i "$DIR/garbage.graph" -o "$DIR/placed.g2o" > "$DIR/placed.txt" || fail "a vertex only an edge names refused"
grep -q "placed 1 vertices that only edges name" "$DIR/placed.txt" || fail "placed vertex not said: $(cat "$DIR/placed.txt")"

# Bad records and bad options fail with a message and no output file.
echo "EDGE2 0 1 nan 0 0 1 0 1 1 0 0" >> "$DIR/garbage.graph"
if "$BIN" -i "$DIR/garbage.graph" -o "$DIR/bad.g2o" 2> "$DIR/err.txt" > /dev/null; then fail "non-finite edge accepted"; fi
grep -q "measurement is not finite" "$DIR/err.txt" || fail "non-finite edge message: $(cat "$DIR/err.txt")"
[ ! -e "$DIR/bad.g2o" ] || fail "output written on error"
if "$BIN" -i "$IN" -o "$DIR/bad.g2o" --alpha 3 2> "$DIR/err.txt" > /dev/null; then fail "alpha 3 accepted"; fi
grep -q "alpha must be in" "$DIR/err.txt" || fail "alpha message"
if "$BIN" -i "$IN" -o "$DIR/bad.g2o" --alpha abc 2> "$DIR/err.txt" > /dev/null; then fail "alpha abc accepted"; fi
grep -q "alpha 'abc' is not a number" "$DIR/err.txt" || fail "alpha abc message: $(cat "$DIR/err.txt")"
if "$BIN" -i "$IN" -o "$DIR/bad.g2o" --alpha=2 2> "$DIR/err.txt" > /dev/null; then fail "bad syntax accepted"; fi
[ ! -e "$DIR/bad.g2o" ] || fail "output written on a command-line error"
if "$BIN" -i "$DIR/nope.graph" -o "$DIR/bad.g2o" 2> "$DIR/err.txt" > /dev/null; then fail "missing file accepted"; fi
grep -q "cannot open" "$DIR/err.txt" || fail "missing file message"
echo "graph_optimize_app_test: OK"

# Three false loops added to the circle: graduated non-convexity to Geman-McClure switches off
# exactly those three and lists them; the result is the circle's optimum without them.
{ cat "$IN"; echo "EDGE2 5 30 80 60 1.0 1 0 1 1 0 0"; echo "EDGE2 12 40 -90 30 -2 1 0 1 1 0 0";
  echo "EDGE2 20 45 0 100 0.5 1 0 1 1 0 0"; } > "$DIR/false.graph"
"$BIN" -i "$DIR/false.graph" -o "$DIR/false.g2o" --kernel gnc --alpha -2 > "$DIR/gnc.txt" || fail "gnc failed"
cat "$DIR/gnc.txt"
grep -q "graduated non-convexity" "$DIR/gnc.txt" || fail "gnc not said"
grep -q "switched off: 3 edges" "$DIR/gnc.txt" || fail "switched-off count"
for pair in "5 -> 30" "12 -> 40" "20 -> 45"; do
  grep -q ": $pair (loop)" "$DIR/gnc.txt" || fail "false loop $pair not listed"
done
"$BIN" -i "$IN" -o "$DIR/clean.g2o" --alpha 2 > /dev/null || fail "clean optimum"
paste <(grep '^VERTEX_SE2' "$DIR/clean.g2o") <(grep '^VERTEX_SE2' "$DIR/false.g2o") |
  awk '{ d = sqrt(($3 - $8)^2 + ($4 - $9)^2); if (d > m) m = d } END { print "largest distance to the clean optimum:", m; exit !(m < 0.01) }' ||
  fail "gnc result is not the clean optimum"
"$BIN" -i "$IN" -o "$DIR/x.g2o" --kernel nonsense > /dev/null 2>&1 && fail "unknown --kernel accepted"
echo "graph_optimize_app_test: OK"

# Bad graphs: each a named error and no output, or (pieces) a warning and each piece held.
printf 'VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\n' > "$DIR/noedge.g2o"
bad_graph() {  # FILE EXPECTED_MESSAGE
  if "$BIN" -i "$1" -o "$DIR/bad.g2o" 2> "$DIR/err.txt" > /dev/null; then fail "$1 accepted"; fi
  grep -q "$2" "$DIR/err.txt" || fail "$1: message '$(cat "$DIR/err.txt")'"
  [ ! -e "$DIR/bad.g2o" ] || fail "$1: output written"
}
bad_graph "$DIR/noedge.g2o" "the graph has no edges: nothing to optimize"
{ cat "$DIR/noedge.g2o"; echo "EDGE_SE2 0 1 1 0 0 100 0 0 -100 0 1000"; } > "$DIR/nonpd.g2o"
bad_graph "$DIR/nonpd.g2o" "nonpd.g2o:3: edge 0 -> 1: information matrix is not positive definite"
{ cat "$DIR/noedge.g2o"; echo "EDGE_SE2 0 1 nan 0 0 100 0 0 100 0 1000"; } > "$DIR/nan.g2o"
bad_graph "$DIR/nan.g2o" "nan.g2o:3: edge 0 -> 1: measurement is not finite"
{ cat "$DIR/noedge.g2o"; echo "VERTEX_SE2 2 2 0 0"; echo "VERTEX_SE2 3 3 0 0";
  echo "EDGE_SE2 0 1 1 0 0 100 0 0 100 0 1000"; echo "EDGE_SE2 2 3 1.5 0 0 100 0 0 100 0 1000"; } > "$DIR/pieces.g2o"
"$BIN" -i "$DIR/pieces.g2o" -o "$DIR/pieces.out.g2o" > "$DIR/pieces.txt" || fail "two pieces rejected"
grep -q "falls apart into 2 connected components" "$DIR/pieces.txt" || fail "pieces not reported: $(cat "$DIR/pieces.txt")"
grep -q '^VERTEX_SE2 2 2 0 0$' "$DIR/pieces.out.g2o" || fail "the second piece's first node moved"
grep -q '^VERTEX_SE2 3 3.5 0 0$' "$DIR/pieces.out.g2o" || fail "the second piece was not optimized: $(grep 'VERTEX_SE2 3' "$DIR/pieces.out.g2o")"
echo "graph_optimize_app_test: bad graphs OK"
