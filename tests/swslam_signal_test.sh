#!/usr/bin/env bash
# SIGINT and SIGTERM end a threaded `swslam` run cleanly: the threads are joined and every
# output is written for the scans processed so far (exit 130), without the final refinement.
# The replay is paced at 10x the log rate (about 6 s) so that the signal arrives mid-run.
set -uo pipefail
src=$1 bin=$2/apps
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
total=$(zcat -f "$src/datasets/lake-short/lake-short.gt.tum" | grep -vc '^#')
for sig in INT TERM; do
  out=$tmp/$sig
  "$bin/swslam" -c "$src/config/default.ini" -i "$src/datasets/lake-short/lake-short.rawlog" \
    -o "$out" -q --realtime-factor 10 > "$tmp/$sig.log" 2>&1 &
  pid=$!
  # The signal handlers are in place once the output folder exists (a loaded machine can
  # take seconds to start the process); then let it map for a moment.
  for _ in $(seq 300); do [[ -d $out ]] && break; sleep 0.1; done
  sleep 1
  kill -s "$sig" "$pid"
  wait "$pid"
  code=$?
  if [[ $code -ne 130 ]]; then
    echo "FAIL: SIG$sig: exit $code (expected 130; did the run end before the signal?)"
    cat "$tmp/$sig.log"; fail=1; continue
  fi
  grep -q "stopped by signal .* (without the final refinement)" "$tmp/$sig.log" || { echo "FAIL: SIG$sig: no message"; fail=1; }
  for f in trajectory.tum keyframes.tum graph.graph stats.csv summary.md map.gridmap.gz map.png map.yaml map.pgm map.bt; do
    [[ -s $out/$f ]] || { echo "FAIL: SIG$sig: $f missing"; fail=1; }
  done
  n=$(grep -vc '^#' "$out/trajectory.tum")
  if ! ((n > 0 && n < total)); then
    echo "FAIL: SIG$sig: $n of $total poses written"; fail=1
  fi
  grep -q '\.tmp' <<< "$(ls "$out")" && { echo "FAIL: SIG$sig: temporary file left"; fail=1; }
  echo "SIG$sig: exit $code, $n of $total poses written"
done

# A replay paced very slowly (a scan every few hours) waits in slices: one signal ends it at once.
out=$tmp/slow
"$bin/swslam" -c "$src/config/default.ini" -i "$src/datasets/lake-short/lake-short.rawlog" \
  -o "$out" -q -d --no-render --realtime-factor 0.000001 > "$tmp/slow.log" 2>&1 &
pid=$!
for _ in $(seq 300); do [[ -d $out ]] && break; sleep 0.1; done
sleep 1
kill -s TERM "$pid"
for _ in $(seq 100); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
if kill -0 "$pid" 2> /dev/null; then
  echo "FAIL: a slowly paced run still runs 10 s after SIGTERM"; kill -9 "$pid"; fail=1
else
  wait "$pid"
  code=$?
  [[ $code -eq 130 ]] || { echo "FAIL: slowly paced run: exit $code (expected 130)"; cat "$tmp/slow.log"; fail=1; }
  echo "slow pacing: exit $code"
fi
exit $fail
