#!/usr/bin/env bash
# One way to read an .ini file for every program: a file that swslam rejects (a stray line, a
# key set twice, an unknown key) is rejected by every program that takes a config, and a
# scenario with a stray line by the simulator, each with a message naming the problem and a
# non-zero exit, before any work.
# Usage: ini_strictness_test.sh SOURCE_DIR BINARY_DIR
set -uo pipefail
src=$1 bin=$2/apps
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
log=$src/datasets/lake-short/lake-short.rawlog
gt=$src/datasets/lake-short/lake-short.gt.tum

# Three broken copies of the default config, each with its expected message.
sed 's/^range_sigma *=.*/range_sigma 0.03/' "$src/config/default.ini" > "$work/stray.ini"
awk '{print} /^\[plicp\]/{print "range_sigma = 0.05"}' "$src/config/default.ini" > "$work/repeated.ini"
awk '{print} /^\[plicp\]/{print "max_iteratoins = 12"}' "$src/config/default.ini" > "$work/unknown.ini"
declare -A expect=([stray]="is neither '\[section\]' nor 'key = value'" [repeated]="is set again"
                   [unknown]="max_iteratoins")

printf '0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n' > "$work/traj.tum"
printf 'VERTEX2 0 0 0 0\nVERTEX2 1 1 0 0\nEDGE2 0 1 1 0 0 1 0 1 1 0 0\n' > "$work/g.graph"
fail=0
check() {  # name, config kind, command...
  local name=$1 kind=$2
  shift 2
  local out code
  out=$("$@" 2>&1 < /dev/null)
  code=$?
  if ((code == 0)); then
    echo "FAIL: $name took the $kind config (exit 0)"; fail=1
  elif ! grep -q -- "${expect[$kind]}" <<< "$out"; then
    echo "FAIL: $name on the $kind config: exit $code without the expected message:"
    head -3 <<< "$out"; fail=1
  else
    echo "ok: $name rejects the $kind config (exit $code): $(grep -m1 -- "${expect[$kind]}" <<< "$out" | cut -c1-110)"
  fi
}
for kind in stray repeated unknown; do
  c=$work/$kind.ini
  check swslam $kind "$bin/swslam" -c "$c" -i "$log" -o "$work/out" -q
  check swslam-live $kind "$bin/swslam-live" -c "$c" --sensor-config "$src/config/hokuyo-utm30lx.ini" \
    -o "$work/live" --duration 1
  check swslam-regen-map $kind "$bin/swslam-regen-map" -r "$work/out" -i "$log" -o "$work/regen" -c "$c"
  check swslam-bench-matcher $kind "$bin/swslam-bench-matcher" -i "$log" -g "$gt" -c "$c"
  check swslam-bench-map $kind "$bin/swslam-bench-map" -i "$log" -g "$gt" -c "$c"
  check swslam-graph-optimize $kind "$bin/swslam-graph-optimize" -i "$work/g.graph" -o "$work/o.graph" --config "$c"
  check "swslam-eval consistency" $kind "$bin/swslam-eval" consistency "$work/traj.tum" "$log" -c "$c"
  check "swslam-eval laser-optimum" $kind "$bin/swslam-eval" laser-optimum "$work/traj.tum" "$log" -c "$c"
done
# The sensor's own file of swslam-live is read the same way.
printf '[LASER_2D]\ndriver = CHokuyoURG\nprocess_rate 10\n' > "$work/sensor.ini"
check "swslam-live --sensor-config" stray "$bin/swslam-live" -c "$src/config/default.ini" \
  --sensor-config "$work/sensor.ini" -o "$work/live" --duration 1
# Scenarios too.
sed '0,/^seed *=.*/s//seed 3/' "$src/datasets/scenarios/lake-short.ini" > "$work/scenario.ini"
grep -q '^seed 3$' "$work/scenario.ini" || { echo "FAIL: the scenario has no seed key to break"; fail=1; }
check swslam-sim stray "$bin/swslam-sim" --scenario "$work/scenario.ini" --output "$work/sim"
exit $fail
