#!/usr/bin/env bash
# Issue 6's figures: swslam-live against the SCIP 2.0 emulator (tests/scip) serving the
# lake-short scenario at 40 Hz over loopback TCP, for 20 s, with one dropped connection.
# Prints the scans the emulator sent, the scans swslam-live received and recorded, its
# reconnections, and the Table I summary; then replays the recording through swslam.
# Usage: scripts/bench-live.sh   (writes out/bench-live/)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh > build.log 2>&1 || { tail -50 build.log; exit 1; }
out=out/bench-live
rm -rf "$out" && mkdir -p "$out"
build/tests/swslam-scip-emulator --scenario datasets/scenarios/lake-short.ini --port 0 \
  --duration 18 --drop-after 400 > "$out/emulator.txt" 2>&1 &
emu=$!
for _ in $(seq 50); do grep -q '127.0.0.1:' "$out/emulator.txt" 2> /dev/null && break; sleep 0.1; done
port=$(grep -o '127.0.0.1:[0-9]*' "$out/emulator.txt" | head -1 | cut -d: -f2)
printf '[LASER_2D]\ndriver = CHokuyoURG\nIP_DIR = 127.0.0.1\nPORT_DIR = %s\npose_x = 0.4\npose_z = 0.5\n' \
  "$port" > "$out/sensor.ini"
build/apps/swslam-live -c config/default.ini --sensor-config "$out/sensor.ini" -o "$out/live" \
  --duration 20 --save-period 5 -q 2> "$out/live.err" | tee "$out/live.txt"
wait "$emu" || true
echo "== emulator"
tail -1 "$out/emulator.txt"
echo "== sensor events"
grep "sensor" "$out/live.err" || true
echo "== replay of the recording (swslam --deterministic)"
build/apps/swslam -c config/default.ini -i "$out/live/recording.rawlog" -o "$out/replay" -d -q \
  --no-render 2> /dev/null | grep -E "Scans processed|graph nodes"
