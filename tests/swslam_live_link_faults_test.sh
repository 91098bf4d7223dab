#!/usr/bin/env bash
# swslam-live against a faulty link from the SCIP emulator program.
# - Random bytes instead of SCIP (--garbage-after): the bad data is reported and counted,
#   --duration and the first SIGINT/SIGTERM still end the run cleanly with every output
#   written, a link sending only garbage for --stall-timeout is reconnected, and every scan
#   received is recorded. Before, the app hung inside MRPT's driver (it searches the garbage
#   for a reply's echo for as long as bytes come).
# - The sensor stopped (SIGSTOP) for 2.5 s, then continued: a stall, and mapping resumes.
# - No scan at all (only garbage, or nothing listening): exit 2, the sensor named as never
#   answering with the retry policy, and no empty outputs; a previous run's outputs in the
#   folder are left as they were.
# Usage: swslam_live_link_faults_test.sh SOURCE_DIR BINARY_DIR
set -uo pipefail
src=$1 build=$2
tmp=$(mktemp -d)
emu_pid= live_pid=
trap '[[ -n $live_pid ]] && kill -KILL $live_pid 2> /dev/null; [[ -n $emu_pid ]] && kill $emu_pid 2> /dev/null; [[ -n ${KEEP:-} ]] || rm -rf "$tmp"' EXIT
fail=0
bad() { echo "FAIL: $name: $*"; fail=1; }

# start_emulator NAME ARGS...: the emulator on a free port, its port in $port.
start_emulator() {
  "$build/tests/swslam-scip-emulator" --scenario "$src/datasets/scenarios/lake-short.ini" --port 0 \
    --duration 60 "$@" > "$tmp/$name.emu" 2>&1 &
  emu_pid=$!
  for _ in $(seq 100); do grep -q '127.0.0.1:' "$tmp/$name.emu" 2> /dev/null && break; sleep 0.1; done
  port=$(grep -o '127.0.0.1:[0-9]*' "$tmp/$name.emu" | head -1 | cut -d: -f2)
  printf '[LASER_2D]\ndriver = CHokuyoURG\nIP_DIR = 127.0.0.1\nPORT_DIR = %s\npose_x = 0.4\n' "$port" \
    > "$tmp/$name.ini"
}

# start_live ARGS...: swslam-live on the emulator, outputs in $tmp/$name.
start_live() {
  "$build/apps/swslam-live" -c "$src/config/default.ini" --sensor-config "$tmp/$name.ini" -o "$tmp/$name" \
    -q --no-render --stall-timeout 1 "$@" > "$tmp/$name.out" 2> "$tmp/$name.err" &
  live_pid=$!
}

# wait_live SECONDS: waits for the app at most that long (then kills it); its exit code in $code.
wait_live() {
  local tenths=$(($1 * 10))
  for _ in $(seq "$tenths"); do kill -0 "$live_pid" 2> /dev/null || break; sleep 0.1; done
  if kill -0 "$live_pid" 2> /dev/null; then
    bad "still running after $1 s (hung); killed"
    kill -KILL "$live_pid"
  fi
  wait "$live_pid"
  code=$?
  live_pid=
  kill "$emu_pid" 2> /dev/null
  wait "$emu_pid" 2> /dev/null
  emu_pid=
}

# check MIN_SCANS [clean]: exit 0, every output, the garbage reported and counted (none if
# `clean`), every scan sent (but the last few in flight at the stop) received, recorded and
# in the trajectory.
check() {
  local min=$1 clean=${2:-} out=$tmp/$name
  [[ $code -eq 0 ]] || bad "exit $code"
  for f in trajectory.tum keyframes.tum graph.graph stats.csv summary.md map.gridmap.gz map.png map.bt recording.rawlog; do
    [[ -e $out/$f ]] || bad "$f missing"
  done
  if [[ -z $clean ]]; then grep -q "not SCIP 2.0" "$tmp/$name.err" || bad "the garbage is not reported"; fi
  local line sent
  line=$(grep -o '[0-9]* scans received and [0-9]* recorded.*' "$tmp/$name.out")
  read -r got _ _ _ rec _ <<< "$line"
  garbage=$(grep -o '[0-9]* byte(s) of data that was not SCIP 2.0' <<< "$line" | cut -d' ' -f1)
  sent=$(grep -o '[0-9]* scans sent' "$tmp/$name.emu" | cut -d' ' -f1)
  poses=$(grep -vc '^#' "$out/trajectory.tum")
  if [[ -z $clean ]]; then
    ((${garbage:-0} > 0)) || bad "no garbage counted: '$line'"
  else
    ((${garbage:-1} == 0)) || bad "garbage counted: '$line'"
  fi
  ((got >= min && got == rec && poses == got && sent - got <= 4)) ||
    bad "$sent sent, '$line', $poses poses (at least $min expected)"
  echo "$name: exit $code; emulator: $(tail -1 "$tmp/$name.emu" | sed 's/^swslam-scip-emulator: //')"
  echo "$name: $line; $poses poses"
}

# Garbage after 40 scans on every connection: reconnected after each stall (1 s), until --duration.
name=duration
start_emulator --garbage-after 40 --garbage-connections 1000
start_live --duration 8
wait_live 16
grep -Eq ' [1-9][0-9]* stall\(s\)' "$tmp/$name.out" || bad "the garbage did not count as a stall"
check 80

# check_never_answered: not one scan: exit 2, the sensor named as never answering with the
# retry policy, and nothing written (no empty map, trajectory or recording).
check_never_answered() {
  ((code == 2)) || bad "exit $code, not 2"
  grep -q "swslam-live: the sensor never answered: not one scan from 127.0.0.1:$port in [0-9]* s ([0-9]* connection attempt(s), [0-9]* failed; reconnecting after 250 ms, doubling up to 4000 ms, for as long as the run lasts): is it powered, and at that address?; nothing written" \
    "$tmp/$name.err" || bad "not said: $(cat "$tmp/$name.err")"
  local left
  left=$(find "$tmp/$name" -type f ! -name .swslam.lock 2> /dev/null)
  [[ -z $left ]] || bad "written: $left"
  echo "$name: exit $code; $(grep 'never answered' "$tmp/$name.err")"
}

# The same, stopped by SIGINT; then garbage from the first byte, stopped by SIGTERM: not one
# scan (it wrote a full set of empty outputs and exited 0).
for sig in INT TERM; do
  name=SIG$sig
  if [[ $sig == INT ]]; then start_emulator --garbage-after 40 --garbage-connections 1000
  else start_emulator --garbage-after 0 --garbage-connections 1000; fi
  start_live
  sleep 3.5
  kill -s "$sig" "$live_pid"
  wait_live 5
  grep -q "stopped by signal" "$tmp/$name.err" || bad "no message"
  if [[ $sig == INT ]]; then check 40; else
    grep -q "not SCIP 2.0" "$tmp/$name.err" || bad "the garbage is not reported"
    check_never_answered
  fi
done

# Nothing listening at the sensor's address, until --duration: it retried for ever with one
# message, then exited 0 with a full set of empty outputs.
name=nobody
start_emulator
kill "$emu_pid"; wait "$emu_pid" 2> /dev/null; emu_pid=  # its port, now closed
start_live --duration 2
wait_live 8
check_never_answered

# The same into the folder of a previous run: it was cleared before the sensor was tried; now
# its outputs and recording are left as they were.
name=nobody_kept
cp "$tmp/nobody.ini" "$tmp/$name.ini"  # the same closed port
mkdir -p "$tmp/$name"
for f in trajectory.tum summary.md recording.rawlog; do echo "previous $f" > "$tmp/$name/$f"; done
(cd "$tmp/$name" && md5sum trajectory.tum summary.md recording.rawlog) > "$tmp/$name.md5"
start_live --duration 2
wait_live 8
((code == 2)) || bad "exit $code, not 2"
grep -q "never answered" "$tmp/$name.err" || bad "not said: $(cat "$tmp/$name.err")"
(cd "$tmp/$name" && md5sum -c --quiet "$tmp/$name.md5") || bad "the previous run's outputs changed"
[[ $(find "$tmp/$name" -type f ! -name .swslam.lock | wc -l) -eq 3 ]] || bad "a file was added or removed"

# The sensor process stopped for 2.5 s (its connection open, silent), then continued.
name=stopped
start_emulator
start_live --duration 8
sleep 2
kill -STOP "$emu_pid"
sleep 2.5
kill -CONT "$emu_pid"
wait_live 14
grep -Eq ' [1-9][0-9]* stall\(s\)' "$tmp/$name.out" || bad "no stall counted"
grep -q "receiving scans again" "$tmp/$name.err" || bad "mapping did not resume"
check 120 clean
exit $fail
