#!/usr/bin/env bash
# swslam-scip-emulator end to end: it serves lake-short on a free port, answers PP and
# streams the scans of a finite MD request over TCP (bash's /dev/tcp), survives SIGSTOP and
# SIGCONT, and stops cleanly on SIGTERM; a scenario whose sensor is not a UTM-30LX is refused naming the key.
# Usage: scip_emulator_app_test.sh SOURCE_DIR BINARY_DIR
set -euo pipefail
src=$1
bin=$2
emu=$bin/tests/swslam-scip-emulator
out=$(mktemp -d)
pid=
cleanup() {
  [[ -n $pid ]] && kill "$pid" 2>/dev/null || true
  rm -rf "$out"
}
trap cleanup EXIT
fail() { echo "scip_emulator_app_test: $*" >&2; exit 1; }

# The program prints its port on its first line: read it through a FIFO (no polling).
mkfifo "$out/stdout"
"$emu" --scenario "$src/datasets/scenarios/lake-short.ini" --port 0 --duration 60 \
  > "$out/stdout" 2> "$out/stderr" &
pid=$!
exec 3< "$out/stdout"
read -r -t 60 -u 3 banner || fail "no banner: $(cat "$out/stderr")"
echo "$banner"
[[ $banner =~ UTM-30LX\ on\ 127\.0\.0\.1:([0-9]+) ]] || fail "unexpected banner: $banner"
port=${BASH_REMATCH[1]}

# Reads the lines of one reply (up to its empty line) into the array `reply`.
read_reply() {
  reply=()
  local line
  while read -r -t 10 -u 4 line; do
    [[ -z $line ]] && return 0
    reply+=("$line")
  done
  fail "reply cut short after: ${reply[*]}"
}

exec 4<> "/dev/tcp/127.0.0.1/$port"
printf 'PP\n' >&4
read_reply
[[ ${reply[0]} == PP && ${reply[1]} == 00P ]] || fail "PP reply: ${reply[*]}"
[[ " ${reply[*]} " == *" DMAX:60000;J "* && " ${reply[*]} " == *" AMAX:1080;Z "* ]] ||
  fail "PP parameters: ${reply[*]}"

printf 'MD0000108001003\n' >&4
read_reply
[[ ${reply[*]} == "MD0000108001003 00P" ]] || fail "MD acknowledgement: ${reply[*]}"
for left in 02 01 00; do
  read_reply
  [[ ${reply[0]} == MD00001080010$left && ${reply[1]} == 99b ]] || fail "scan: ${reply[*]:0:3}"
  # timestamp + 1081 ranges of 3 characters in lines of 64: 1 + 51 lines.
  ((${#reply[@]} == 2 + 1 + 51)) || fail "scan of ${#reply[@]} lines"
done
exec 4>&-

# Stopped and continued (SIGSTOP, SIGCONT), it goes on serving until told to end.
kill -STOP "$pid"
sleep 0.2
kill -CONT "$pid"
sleep 0.3
kill -0 "$pid" 2> /dev/null || fail "it exited on SIGSTOP/SIGCONT"

kill -TERM "$pid"
status=0
wait "$pid" || status=$?
pid=
((status == 0)) || fail "exit status $status: $(cat "$out/stderr")"
read -r -t 10 -u 3 summary || fail "no summary line"
echo "$summary"
[[ $summary == *"1 connections, 3 scans sent"* ]] || fail "unexpected summary: $summary"
exec 3<&-

sed 's/^resolution_DEG .*/resolution_DEG  = 0.5/' "$src/datasets/scenarios/lake-short.ini" \
  > "$out/coarse.ini"
if "$emu" --scenario "$out/coarse.ini" --port 0 --duration 1 > /dev/null 2> "$out/err.txt"; then
  fail "a 0.5 deg sensor was accepted"
fi
grep -q "resolution_DEG = 0.5" "$out/err.txt" || fail "error does not name the key: $(cat "$out/err.txt")"
cat "$out/err.txt"
echo "scip_emulator_app_test: OK"
