#!/usr/bin/env bash
# End to end: swslam-eval on small synthetic trajectories (ATE/RPE and relations), on the
# lake-short scans (consistency, laser optimum), and its
# errors on bad input (clear message, exit code 1).
# Args: SOURCE_DIR BINARY_DIR
set -euo pipefail
SRC="$1"
BIN="$2/apps/swslam-eval"
DIR="$(mktemp -d)"
trap 'rm -rf "$DIR"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
value() { grep "^$1=" "$2" | cut -d= -f2; }
# near VALUE TARGET TOL: |VALUE - TARGET| <= TOL
near() { awk -v v="$1" -v t="$2" -v e="$3" 'BEGIN { d = v - t; exit !(d <= e && -d <= e) }'; }

# Truth: 300 poses at 10 Hz along a looping path (~0.3 m steps).
awk 'BEGIN { print "# timestamp x y z qx qy qz qw"; x = 0; y = 0; a = 0
  for (k = 0; k < 300; k++) {
    printf "%.6f %.9g %.9g 0 0 0 %.9g %.9g\n", 100 + 0.1 * k, x, y, sin(a / 2), cos(a / 2)
    a += 0.05 * sin(0.02 * k); x += 0.3 * cos(a); y += 0.3 * sin(a) } }' > "$DIR/gt.tum"

# 1. A rigidly moved copy (with every other pose dropped): zero ATE and RPE.
awk -v off_x=12 -v off_y=-4 -v off_yaw=2.0 -f "$SRC/scripts/perturb-tum.awk" "$DIR/gt.tum" \
  | awk '/^#/ || NR % 2' > "$DIR/moved.tum"
"$BIN" ate "$DIR/moved.tum" "$DIR/gt.tum" > "$DIR/a.txt" || fail "ate on moved copy"
cat "$DIR/a.txt"
[ "$(value matched "$DIR/a.txt")" = 150 ] || fail "matched count"
[ "$(value gt_unmatched "$DIR/a.txt")" = 150 ] || fail "unmatched count"
near "$(value ate_rmse "$DIR/a.txt")" 0 1e-6 || fail "ATE of a rigid copy"
near "$(value rpe_seg_trans_rmse "$DIR/a.txt")" 0 1e-6 || fail "RPE of a rigid copy"
near "$(value align_yaw_deg "$DIR/a.txt")" -114.592 1e-3 || fail "alignment yaw"
grep -q '^# ATE ' "$DIR/a.txt" || fail "human summary"

# 2. A 2% scale error: RPE per pose 0.02 * 0.3 m, per 1 m segment (4 steps) 0.024 m.
awk -v scale=1.02 -f "$SRC/scripts/perturb-tum.awk" "$DIR/gt.tum" > "$DIR/scaled.tum"
"$BIN" ate "$DIR/scaled.tum" "$DIR/gt.tum" --max-dt 0.001 > "$DIR/b.txt" \
  || fail "ate on scaled copy"
near "$(value rpe_trans_rmse "$DIR/b.txt")" 0.006 1e-6 || fail "RPE per pose of a scale error"
near "$(value rpe_seg_trans_rmse "$DIR/b.txt")" 0.024 1e-4 || fail "RPE per metre of a scale error"
awk -v v="$(value ate_rmse "$DIR/b.txt")" 'BEGIN { exit !(v > 0.1) }' || fail "ATE of a scale error"

# 3. Relations built from the truth: zero error on the truth, non-zero on a noisy copy.
awk -v gap=10 -v every=2 -f "$SRC/scripts/tum-relations.awk" "$DIR/gt.tum" > "$DIR/gt.relations"
"$BIN" relations "$DIR/gt.tum" "$DIR/gt.relations" > "$DIR/c.txt" || fail "relations on truth"
cat "$DIR/c.txt"
[ "$(value used "$DIR/c.txt")" = 145 ] || fail "relations used"
near "$(value trans_abs_mean "$DIR/c.txt")" 0 1e-6 || fail "relations error of the truth"
near "$(value rot_abs_mean_deg "$DIR/c.txt")" 0 1e-5 || fail "relations rotation of the truth"
awk -v sigma=0.02 -v seed=4 -f "$SRC/scripts/perturb-tum.awk" "$DIR/gt.tum" > "$DIR/noisy.tum"
"$BIN" relations "$DIR/noisy.tum" "$DIR/gt.relations" > "$DIR/d.txt" \
  || fail "relations on noisy copy"
awk -v v="$(value trans_abs_mean "$DIR/d.txt")" 'BEGIN { exit !(v > 0.01) }' || fail "noise unseen"

# 4. Consistency of the bundled lake-short scans: at the true poses the scans agree far better
#    than at poses with 5 cm / 1 deg of noise, scored on the same pairs.
LOG="$SRC/datasets/lake-short/lake-short.rawlog"
awk -v sigma=0.05 -v seed=4 -f "$SRC/scripts/perturb-tum.awk" \
  "$SRC/datasets/lake-short/lake-short.gt.tum" > "$DIR/lake-noisy.tum"
"$BIN" consistency "$SRC/datasets/lake-short/lake-short.gt.tum" "$LOG" -c "$SRC/config/default.ini" \
  --compare "$DIR/lake-noisy.tum" --stride 10 > "$DIR/e.txt" 2> /dev/null || fail "consistency"
cat "$DIR/e.txt"
nth() { grep "^$1=" "$3" | sed -n "$2p" | cut -d= -f2; }  # KEY N FILE: the N-th trajectory's value
[ "$(value scans "$DIR/e.txt")" = 247 ] || fail "consistency scans (every 10th of 2461)"
[ "$(nth all_pairs 1 "$DIR/e.txt")" = "$(nth all_pairs 2 "$DIR/e.txt")" ] || fail "same pairs"
awk -v t="$(nth all_frac_good 1 "$DIR/e.txt")" -v n="$(nth all_frac_good 2 "$DIR/e.txt")" \
  'BEGIN { exit !(t > 0.5 && n < t - 0.2) }' || fail "noisy poses not told from true ones"

# 5. Laser optimum of the lake-short scans (every 20th): the true poses hardly move, and the
#    optimum from poses with a 2 % scale error (ATE 0.53 m) comes back near the truth, written
#    as a TUM trajectory.
"$BIN" laser-optimum "$SRC/datasets/lake-short/lake-short.gt.tum" "$LOG" -c "$SRC/config/default.ini" \
  --stride 20 > "$DIR/f.txt" 2> /dev/null || fail "laser-optimum on the truth"
cat "$DIR/f.txt"
[ "$(value scans "$DIR/f.txt")" = 124 ] || fail "laser-optimum scans (every 20th of 2461)"
[ "$(value status "$DIR/f.txt")" = converged ] || fail "laser-optimum status"
awk -v p="$(value pairs "$DIR/f.txt")" -v e="$(value edges "$DIR/f.txt")" 'BEGIN { exit !(e > 123 && e <= p) }' \
  || fail "laser-optimum edges"
awk -v v="$(value moved_rmse_m "$DIR/f.txt")" 'BEGIN { exit !(v < 0.05) }' || fail "the truth moved"
awk -v scale=1.02 -f "$SRC/scripts/perturb-tum.awk" "$SRC/datasets/lake-short/lake-short.gt.tum" \
  > "$DIR/lake-scaled.tum"
"$BIN" laser-optimum "$DIR/lake-scaled.tum" "$LOG" -c "$SRC/config/default.ini" --stride 20 \
  -o "$DIR/lake-optimum.tum" > "$DIR/g.txt" 2> /dev/null || fail "laser-optimum on scaled poses"
awk -v v="$(value moved_rmse_m "$DIR/g.txt")" 'BEGIN { exit !(v > 0.3) }' || fail "scaled poses did not move"
"$BIN" ate "$DIR/lake-optimum.tum" "$SRC/datasets/lake-short/lake-short.gt.tum" > "$DIR/h.txt" \
  || fail "ate of the written optimum"
[ "$(value matched "$DIR/h.txt")" = 124 ] || fail "optimum poses written"
awk -v v="$(value ate_rmse "$DIR/h.txt")" 'BEGIN { exit !(v < 0.08) }' || fail "optimum far from the truth"

# 6. Bad input: a clear message and exit code 1.
expect_error() {  # PATTERN ARGS...
  local pattern="$1"; shift
  local rc=0
  "$BIN" "$@" > /dev/null 2> "$DIR/err.txt" || rc=$?
  [ "$rc" = 1 ] || fail "exit code $rc for: $*"
  grep -q "$pattern" "$DIR/err.txt" || fail "message for $*: $(cat "$DIR/err.txt")"
}
expect_error "cannot open" ate "$DIR/missing.tum" "$DIR/gt.tum"
expect_error "cannot open" relations "$DIR/gt.tum" "$DIR/missing.relations"
printf '1 2 3\n' > "$DIR/bad.tum"
expect_error "line 1" ate "$DIR/bad.tum" "$DIR/gt.tum"
printf '# nothing\n' > "$DIR/empty.tum"
expect_error "holds no poses" ate "$DIR/empty.tum" "$DIR/gt.tum"
awk '!/^#/ { $1 += 1000 } 1' "$DIR/gt.tum" > "$DIR/late.tum"
expect_error "associate within" ate "$DIR/late.tum" "$DIR/gt.tum"
expect_error "no relation has both stamps" relations "$DIR/late.tum" "$DIR/gt.relations"
expect_error "max-dt" ate "$DIR/gt.tum" "$DIR/gt.tum" --max-dt -1
expect_error "" nonsense "$DIR/gt.tum" "$DIR/gt.tum"
expect_error "needs --config" consistency "$DIR/gt.tum" "$LOG"
expect_error "have a pose within" consistency "$DIR/gt.tum" "$LOG" -c "$SRC/config/default.ini"
expect_error "cannot" consistency "$DIR/gt.tum" "$DIR/missing.rawlog" -c "$SRC/config/default.ini"
expect_error "needs --config" laser-optimum "$DIR/gt.tum" "$LOG"
expect_error "have a pose within" laser-optimum "$DIR/gt.tum" "$LOG" -c "$SRC/config/default.ini"
expect_error "no directory" laser-optimum "$SRC/datasets/lake-short/lake-short.gt.tum" "$LOG" -c "$SRC/config/default.ini" -o "$DIR/missing/optimum.tum"
expect_error "stride" laser-optimum "$SRC/datasets/lake-short/lake-short.gt.tum" "$LOG" -c "$SRC/config/default.ini" --stride 0
echo "eval_app_test: OK"
