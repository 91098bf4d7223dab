#!/usr/bin/env bash
# End to end: swslam-carmen2rawlog on a tiny generated CARMEN log (gzip-compressed, like
# the real ones). Checks the outputs exist and load, and that bad input fails cleanly.
# Args: SOURCE_DIR BINARY_DIR
set -euo pipefail
BIN="$2/apps/swslam-carmen2rawlog"
DIR="$(mktemp -d)"
trap 'rm -rf "$DIR"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# 12 FLASER scans of 180 beams (the first saturating at 81.91 m), one ODOM line each,
# one malformed line, one duplicate timestamp.
awk 'BEGIN {
  print "PARAM robot_frontlaser_offset 0.1 nohost 0"
  for (k = 0; k < 12; k++) {
    t = 100 + 0.2 * k; if (k == 5) t = 100 + 0.2 * 4
    printf "ODOM %g 0 0 0.5 0 0 %.3f host %.3f\n", 0.1 * k, t - 0.05, t - 0.05
    line = "FLASER 180"
    for (i = 0; i < 180; i++) line = line " " ((k == 0 && i < 6) ? "81.91" : sprintf("%.2f", 2 + 0.01 * i))
    printf "%s %g 0 0 %g 0 0 %.3f host %.3f\n", line, 0.1 * k, 0.1 * k, t, t
    if (k == 7) print "FLASER 4 1 2"
  }
}' | gzip > "$DIR/tiny.log.gz"

"$BIN" -i "$DIR/tiny.log.gz" -o "$DIR/out.rawlog" --ground-truth "$DIR/gt.tum" > "$DIR/summary.txt" 2> "$DIR/warnings.txt" \
  || fail "conversion failed: $(cat "$DIR/warnings.txt")"
cat "$DIR/summary.txt"
[ -s "$DIR/out.rawlog" ] || fail "no rawlog"
gzip -t "$DIR/out.rawlog" || fail "rawlog is not valid gzip"
grep -q "FLASER: 12 scans, beams 180, aperture 180 deg, max_range 81.91 m" "$DIR/summary.txt" || fail "scan summary"

# One 500 m glitch among the readings: the saturation stays 81.91 m (it used to become
# 500.01 m, every "no return" ray a wall), and the glitch is said.
zcat "$DIR/tiny.log.gz" | awk '/^FLASER 180/ && !done { $50 = "500.0"; done = 1 } { print }' | gzip > "$DIR/glitch.log.gz"
"$BIN" -i "$DIR/glitch.log.gz" -o "$DIR/glitch.rawlog" > "$DIR/glitch.txt" 2> "$DIR/glitch.err" ||
  fail "glitch conversion failed: $(cat "$DIR/glitch.err")"
grep -q "max_range 81.91 m (saturation detected)" "$DIR/glitch.txt" || fail "glitch moved the max range: $(grep FLASER: "$DIR/glitch.txt")"
grep -q "1 reading(s) above the saturation value 81.91 m (largest 500.00 m)" "$DIR/glitch.err" || fail "glitch not said"
grep -q "invalid rays 6 of 2160" "$DIR/summary.txt" || fail "max-range readings not invalid"
grep -q "odometry: 12" "$DIR/summary.txt" || fail "odometry count"
grep -q "malformed lines: 1 (first at line 18)" "$DIR/summary.txt" || fail "malformed count"
grep -q "FLASER: 12 stamps, 1 non-increasing" "$DIR/summary.txt" || fail "timestamp check"
grep -q ":18: malformed line skipped" "$DIR/warnings.txt" || fail "warning names the line"
[ "$(grep -vc '^#' "$DIR/gt.tum")" = 12 ] || fail "ground truth lines"
awk '!/^#/ && NF != 8 { exit 1 }' "$DIR/gt.tum" || fail "ground truth format"
[ "$(grep -v '^#' "$DIR/gt.tum" | head -1 | cut -d" " -f1)" = 100.000000 ] || fail "ground truth timestamp"

# If MRPT's tools are installed, they must read the output.
if command -v rawlog-edit > /dev/null; then
  rawlog-edit --info -i "$DIR/out.rawlog" > "$DIR/info.txt" 2>&1 || fail "rawlog-edit cannot read"
  grep -Eq "FLASER / +12 " "$DIR/info.txt" || fail "rawlog-edit scan count: $(cat "$DIR/info.txt")"
  grep -Eq "ODOM / +12 " "$DIR/info.txt" || fail "rawlog-edit odometry count"
fi

# --laser-only and --repair-timestamps; existing outputs need -w.
"$BIN" -i "$DIR/tiny.log.gz" -o "$DIR/out.rawlog" -q > /dev/null 2>&1 && fail "overwrote without -w"
"$BIN" -w -q -i "$DIR/tiny.log.gz" -o "$DIR/out.rawlog" --laser-only --repair-timestamps > "$DIR/s2.txt" \
  || fail "laser-only conversion failed"
grep -q "odometry: 0 (12 ODOM lines dropped" "$DIR/s2.txt" || fail "laser-only"
grep -q "repaired 1 (period 0.2 s)" "$DIR/s2.txt" || fail "timestamp repair"

# --reference-odometry: one odometry reading per scan (the reference pose), only laser-only
# with repaired timestamps.
"$BIN" -w -q -i "$DIR/tiny.log.gz" -o "$DIR/ref.rawlog" --laser-only --repair-timestamps --reference-odometry \
  > /dev/null || fail "reference-odometry conversion failed"
if command -v rawlog-edit > /dev/null; then
  rawlog-edit --info -i "$DIR/ref.rawlog" > "$DIR/ref-info.txt" 2>&1 || fail "rawlog-edit cannot read"
  grep -Eq "REFERENCE_ODOMETRY / +12 " "$DIR/ref-info.txt" || fail "reference odometry count: $(cat "$DIR/ref-info.txt")"
fi
for flags in "" "--laser-only" "--repair-timestamps"; do
  # shellcheck disable=SC2086
  if "$BIN" -w -q -i "$DIR/tiny.log.gz" -o "$DIR/ref2.rawlog" --reference-odometry $flags 2> "$DIR/err.txt"; then
    fail "reference odometry accepted with only '$flags'"
  fi
  grep -q "needs laser-only conversion with repaired timestamps" "$DIR/err.txt" || fail "error message: $(cat "$DIR/err.txt")"
done

# Bad input: a clear error and exit code 1, no output.
if "$BIN" -i "$DIR/missing.log" -o "$DIR/none.rawlog" 2> "$DIR/err.txt"; then fail "missing input accepted"; fi
grep -q "cannot open" "$DIR/err.txt" || fail "error message: $(cat "$DIR/err.txt")"
[ ! -e "$DIR/none.rawlog" ] || fail "output written for a missing input"

# A .log.gz cut short: the scans before the cut are written, the cut said, exit 2.
head -c "$(( $(stat -c %s "$DIR/tiny.log.gz") - 40 ))" "$DIR/tiny.log.gz" > "$DIR/cut.log.gz"
set +e
"$BIN" -i "$DIR/cut.log.gz" -o "$DIR/cut.rawlog" --ground-truth "$DIR/cut.tum" > "$DIR/cut.txt" 2> "$DIR/cut.err"
code=$?
set -e
[ "$code" = 2 ] || fail "a cut .log.gz exited $code: $(cat "$DIR/cut.err")"
grep -q "the gzip stream is cut short after .* bytes of content (a truncated file), after line" "$DIR/cut.err" ||
  fail "cut not said: $(cat "$DIR/cut.err")"
gzip -t "$DIR/cut.rawlog" || fail "no valid rawlog of the scans before the cut"
[ "$(grep -vc '^#' "$DIR/cut.tum")" -ge 1 ] || fail "no ground truth of the scans before the cut"

# Stamps in microseconds (a 2023 clock): refused, saying so; nothing written.
zcat "$DIR/tiny.log.gz" | awk '/^(FLASER|ODOM)/ { $(NF) = sprintf("%.0f", 1.7e15 + $(NF) * 1e6); $(NF - 2) = $(NF) } { print }' \
  > "$DIR/us.log"
if "$BIN" -i "$DIR/us.log" -o "$DIR/us.rawlog" 2> "$DIR/us.err"; then fail "a log in microseconds accepted"; fi
grep -q "timestamps are out of range.*(microseconds rather than seconds?): not converted" "$DIR/us.err" ||
  fail "microseconds not said: $(cat "$DIR/us.err")"
[ ! -e "$DIR/us.rawlog" ] || fail "output written for a log in microseconds"
echo "carmen2rawlog_test: OK"
