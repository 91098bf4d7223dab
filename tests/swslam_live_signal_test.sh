#!/usr/bin/env bash
# swslam-live ends cleanly on SIGINT and SIGTERM while mapping from the SCIP emulator: exit 0,
# every output written, and the recording holds every scan received.
set -uo pipefail
src=$1 build=$2
tmp=$(mktemp -d)
emu_pid=
trap '[[ -n $emu_pid ]] && kill $emu_pid 2> /dev/null; rm -rf "$tmp"' EXIT
fail=0
for sig in INT TERM; do
  "$build/tests/swslam-scip-emulator" --scenario "$src/datasets/scenarios/lake-short.ini" --port 0 \
    --duration 60 > "$tmp/emu.txt" 2>&1 &
  emu_pid=$!
  for _ in $(seq 100); do grep -q '127.0.0.1:' "$tmp/emu.txt" 2> /dev/null && break; sleep 0.1; done
  port=$(grep -o '127.0.0.1:[0-9]*' "$tmp/emu.txt" | head -1 | cut -d: -f2)
  printf '[LASER_2D]\ndriver = CHokuyoURG\nIP_DIR = 127.0.0.1\nPORT_DIR = %s\npose_x = 0.4\n' "$port" > "$tmp/sensor.ini"
  out=$tmp/$sig
  "$build/apps/swslam-live" -c "$src/config/default.ini" --sensor-config "$tmp/sensor.ini" -o "$out" -q \
    --no-render > "$tmp/$sig.out" 2> "$tmp/$sig.err" &
  pid=$!
  # Wait for the first scans to be recorded, then let it map for a moment.
  for _ in $(seq 300); do [[ -s $out/recording.rawlog ]] && break; sleep 0.1; done
  sleep 2
  kill -s "$sig" "$pid"
  wait "$pid"
  code=$?
  kill "$emu_pid" 2> /dev/null; wait "$emu_pid" 2> /dev/null; emu_pid=
  if [[ $code -ne 0 ]]; then echo "FAIL: SIG$sig: exit $code"; cat "$tmp/$sig.err"; fail=1; continue; fi
  grep -q "stopped by signal" "$tmp/$sig.err" || { echo "FAIL: SIG$sig: no message"; fail=1; }
  for f in trajectory.tum keyframes.tum graph.graph stats.csv summary.md map.gridmap.gz map.png map.bt recording.rawlog; do
    [[ -s $out/$f ]] || { echo "FAIL: SIG$sig: $f missing"; fail=1; }
  done
  received=$(grep -o '[0-9]* scans received and [0-9]* recorded' "$tmp/$sig.out")
  read -r got _ _ _ rec _ <<< "$received"
  poses=$(grep -vc '^#' "$out/trajectory.tum")
  if ! ((got > 40 && got == rec && poses == got)); then
    echo "FAIL: SIG$sig: '$received', $poses poses"; fail=1
  fi
  echo "SIG$sig: exit $code; $received; $poses poses"
done
exit $fail
