#!/usr/bin/env bash
# Fuzzes the file readers with libFuzzer (doc/reliability.md, "Fuzzing"): configures and
# builds ./build-fuzz (clang, ASan + UBSan, only the modules the harnesses need), runs each
# harness for SECONDS_PER_HARNESS (default 600), then prints one row per harness: executions,
# exec/s, libFuzzer's final coverage (cov: edges, ft: features), corpus size, crashes and
# where their inputs were saved. Exits 1 if any harness found a crash (also an uncaught
# exception, a sanitizer report, a leak, an allocation above the limit or a timeout).
#
# Usage: scripts/fuzz.sh [SECONDS_PER_HARNESS] [HARNESS...]
#   harnesses (tests/fuzz/<name>_fuzz.cpp): rawlog_reader carmen_line carmen_log carmen2rawlog
#   graph_io tum_io relations_io ini_config stats_csv ros1_bag ros2_bag cdr_messages (default: all)
# Environment: FUZZ_RSS_MB / FUZZ_MALLOC_MB (2048), FUZZ_TIMEOUT (10 s per input; rawlog_reader
#   at least 30 s),
#   FUZZ_FORK=1 (go on after a crash, below), FUZZ_JOBS (build parallelism, default nproc),
#   FUZZ_PARALLEL (harnesses fuzzed at once, default 1: on a shared machine, at most its cores),
#   FUZZ_SEED (libFuzzer's -seed: the same mutations in the same order on every machine, as CI
#   runs it; a slower machine runs a prefix of them),
#   CXX (a clang++, default clang++ or clang++-14).
# Kept between runs: build-fuzz/corpus/<name>/ (the corpus grown so far). Each run's logs and
# crash inputs: build-fuzz/fuzz-out/<name>/ (emptied first).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

all=(rawlog_reader carmen_line carmen_log carmen2rawlog graph_io tum_io relations_io ini_config stats_csv ros1_bag
  ros2_bag cdr_messages)
seconds=${1:-600}
[[ $seconds =~ ^[0-9]+$ && $seconds -gt 0 ]] || { echo "fuzz: SECONDS_PER_HARNESS must be a positive integer, got '$seconds'" >&2; exit 2; }
shift || true
harnesses=("$@")
((${#harnesses[@]})) || harnesses=("${all[@]}")
for h in "${harnesses[@]}"; do
  [[ " ${all[*]} " == *" $h "* ]] || { echo "fuzz: unknown harness '$h' (one of: ${all[*]})" >&2; exit 2; }
done

rss_mb=${FUZZ_RSS_MB:-2048} malloc_mb=${FUZZ_MALLOC_MB:-2048} timeout=${FUZZ_TIMEOUT:-10}
cxx=${CXX:-}
if [[ -z $cxx ]]; then
  for c in clang++ clang++-14; do command -v "$c" > /dev/null && { cxx=$c; break; }; done
fi
[[ -n $cxx ]] || { echo "fuzz: no clang++ (scripts/install-deps.sh --with-fuzz installs it)" >&2; exit 2; }

# Readable stacks in the reports: llvm-14 installs the symbolizer under a versioned name.
if [[ -z ${ASAN_SYMBOLIZER_PATH:-} ]] && ! command -v llvm-symbolizer > /dev/null; then
  for s in /usr/bin/llvm-symbolizer-14 /usr/lib/llvm-14/bin/llvm-symbolizer; do
    [[ -x $s ]] && { export ASAN_SYMBOLIZER_PATH=$s; break; }
  done
fi

build=build-fuzz
mkdir -p $build
cmake -S . -B $build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER="$cxx" \
  -DSWSLAM_FUZZ=ON -DSWSLAM_BUILD_TESTS=OFF -DSWSLAM_BUILD_APPS=OFF > $build/configure.log ||
  { cat $build/configure.log; exit 2; }
cmake --build $build -j "${FUZZ_JOBS:-$(nproc)}" --target "${harnesses[@]/#/fuzz_}"

# The ini harness's dictionary: every section and key of the documented configuration.
out=$build/fuzz-out
mkdir -p $out
{
  echo "# sections and keys of config/default.ini and config/expert.ini (written by scripts/fuzz.sh)"
  grep -ho '^\[[A-Za-z0-9_]*\]' config/default.ini config/expert.ini | sort -u | sed 's/.*/"&"/'
  sed -n 's/^\([A-Za-z0-9_]*\) *=.*/"\1 = "/p' config/default.ini config/expert.ini
  printf '"%s"\n' true false yes no inf -inf nan 1e19 -1 '\x0a' '#' ';'
} > $out/ini_config.dict

# The ROS 2 harnesses' seeds: bags written by independent writers (tests/ros2/make-bags.mjs, the
# npm packages of its package-lock.json).
if [[ " ${harnesses[*]} " == *" ros2_bag "* || " ${harnesses[*]} " == *" cdr_messages "* ]]; then
  npm_dir=$build/ros2-npm
  mkdir -p $npm_dir
  cp tests/ros2/package.json tests/ros2/package-lock.json tests/ros2/make-bags.mjs $npm_dir/
  (cd $npm_dir && npm ci --no-audit --no-fund --loglevel=error) &&
    node $npm_dir/make-bags.mjs synthetic $build/ros2-bags > /dev/null ||
    { echo "fuzz: cannot write the ROS 2 seeds (node, npm and sqlite3: scripts/install-deps.sh)" >&2; exit 2; }
fi

dict_of() {
  case $1 in
    ros1_bag) echo tests/fuzz/dicts/rosbag.dict ;;
    ros2_bag) echo tests/fuzz/dicts/mcap.dict ;;
    cdr_messages) echo tests/fuzz/dicts/cdr.dict ;;
    carmen_line | carmen_log | carmen2rawlog) echo tests/fuzz/dicts/carmen.dict ;;
    graph_io) echo tests/fuzz/dicts/graph.dict ;;
    tum_io | relations_io | stats_csv) echo tests/fuzz/dicts/numbers.dict ;;
    rawlog_reader) echo tests/fuzz/dicts/rawlog.dict ;;
    ini_config) echo $out/ini_config.dict ;;
  esac
}

# Default: a harness stops at its first crash. FUZZ_FORK=1: fork mode (one child process at
# a time), which saves each crash, leak, OOM or timeout and goes on, to count them all.
mode=()
[[ ${FUZZ_FORK:-0} == 1 ]] && mode=(-fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1)
[[ -n ${FUZZ_SEED:-} ]] && mode+=(-seed="$FUZZ_SEED")

# Fuzzes harness $1 and writes its row of the table to build-fuzz/fuzz-out/<name>/row.
fuzz_one() {
  local h=$1
  local dir=$out/$h corpus=$build/corpus/$h
  rm -rf "$dir"
  mkdir -p "$dir" "$corpus"
  local seeds=()
  [[ -d tests/fuzz/seeds/$h ]] && seeds+=("$root/tests/fuzz/seeds/$h")
  [[ -d $build/ros2-bags/fuzz-seeds/$h ]] && seeds+=("$root/$build/ros2-bags/fuzz-seeds/$h")
  [[ $h == ini_config ]] && seeds+=("$root/config")
  [[ -d tests/fuzz/regressions/$h ]] && seeds+=("$root/tests/fuzz/regressions/$h")
  # A damaged count makes the rawlog decoder's child fill its 1 GB budget before it is
  # stopped: seconds under AddressSanitizer, more on a busy machine (doc/reliability.md).
  local t=$timeout
  [[ $h == rawlog_reader && $t -lt 30 ]] && t=30
  echo "fuzz: $h for ${seconds}s (log: $dir/fuzz.log)"
  local status=0
  # New inputs go to the first folder (the corpus); the harness's scratch files to its own
  # folder; -close_fd_mask=1 keeps the readers' warnings on stdout out of the log.
  (cd "$dir" && TMPDIR="$root/$dir" "$root/$build/tests/fuzz/fuzz_$h" "$root/$corpus" "${seeds[@]}" \
    -dict="$root/$(dict_of "$h")" -max_total_time="$seconds" -timeout="$t" \
    -rss_limit_mb="$rss_mb" -malloc_limit_mb="$malloc_mb" -close_fd_mask=1 -print_final_stats=1 \
    "${mode[@]}" -artifact_prefix="$root/$dir/" > fuzz.log 2>&1) || status=$?
  # The last status line: "#<executions> <event> cov: <edges> ft: <features> corp: ..."; fork
  # mode: "#<executions>: cov: <edges> ft: <features> corp: ... time: <seconds>s job: ...".
  local log=$dir/fuzz.log
  local last execs rate elapsed cov ft corp found crashes=0 saved=-
  last=$(grep -E '^#[0-9]+:?[[:space:]].*cov: ' "$log" | tail -1 || true)
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  [[ -n $execs ]] || execs=$(sed -n 's/^#\([0-9]*\).*/\1/p' <<< "$last")
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  elapsed=$(sed -n 's/.* time: \([0-9]*\)s.*/\1/p' <<< "$last")
  [[ -z $rate && -n $execs && -n $elapsed && $elapsed -gt 0 ]] && rate=$((execs / elapsed))
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<< "$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<< "$last")
  corp=$(find "$corpus" -type f | wc -l)
  found=$(find "$dir" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'oom-*' \
    -o -name 'timeout-*' \) | sort)
  if [[ -n $found ]]; then
    crashes=$(wc -l <<< "$found")
    # By kind, e.g. "3(2oom,1crash)"; replaying one prints its report.
    crashes+="($(sed 's|.*/||; s|-.*||' <<< "$found" | sort | uniq -c | awk '{printf "%s%d%s", (NR > 1 ? "," : ""), $1, $2}'))"
    saved=$dir/
    sed "s|^|fuzz: $h found: |; s|$| (replay: $build/tests/fuzz/fuzz_$h FILE)|" <<< "$found"
  fi
  local bad=0
  if [[ -n $found || $status -ne 0 ]]; then
    bad=1
    [[ -n $found ]] || crashes="?(exit $status)" saved=$dir/
  fi
  echo "$h|${execs:-?}|${rate:-?}|${cov:-?}|${ft:-?}|$corp|$crashes|$saved|$bad" > "$dir/row"
}

# FUZZ_PARALLEL harnesses at a time (each one process), in the order given.
parallel=${FUZZ_PARALLEL:-1}
[[ $parallel =~ ^[0-9]+$ && $parallel -gt 0 ]] || { echo "fuzz: FUZZ_PARALLEL must be a positive integer, got '$parallel'" >&2; exit 2; }
for h in "${harnesses[@]}"; do
  while (($(jobs -rp | wc -l) >= parallel)); do wait -n || true; done
  fuzz_one "$h" &
done
wait

failed=0
rows=()
for h in "${harnesses[@]}"; do
  row=$(cat "$out/$h/row" 2> /dev/null || echo "$h|?|?|?|?|?|?(no result)|$out/$h/|1")
  rows+=("${row%|*}")
  [[ ${row##*|} == 1 ]] && failed=1
done

echo
summary=$out/summary.txt
{
  echo "fuzz: ${seconds} s per harness, -rss_limit_mb=$rss_mb -malloc_limit_mb=$malloc_mb -timeout=$timeout" \
    "(rawlog_reader at least 30), $parallel at a time"
  printf '%-14s %10s %8s %6s %6s %7s %8s  %s\n' harness executions exec/s cov ft corpus crashes saved
  for r in "${rows[@]}"; do
    IFS='|' read -r h e s c f n k d <<< "$r"
    printf '%-14s %10s %8s %6s %6s %7s %8s  %s\n' "$h" "$e" "$s" "$c" "$f" "$n" "$k" "$d"
  done
} | tee "$summary"
if ((failed)); then
  echo "fuzz: FAILED: a harness found a crash (inputs and logs in the folders above)"
  exit 1
fi
echo "fuzz: no crash"
