#!/usr/bin/env bash
# swslam when the disk refuses its outputs part way: simulated without privileges by a file
# size limit (ulimit -f, SIGXFSZ ignored: a write past it fails with EFBIG, as a full disk's
# with ENOSPC). Before, graph.graph was left as a 0-byte file without a word, and the last
# line listed stats.csv and summary.md, which were not written. Now every output is whole or
# absent, each one missing is named, the exit code is 4, and the last line names only what
# exists.
# Usage: disk_full_test.sh SOURCE_DIR BINARY_DIR
set -uo pipefail
src=$1 build=$2
tmp=$(mktemp -d)
trap '[[ -n ${KEEP:-} ]] || rm -rf "$tmp"' EXIT
fail=0
bad() { echo "FAIL: $*"; fail=1; }
run() {  # run OUT [ulimit -f BLOCKS]: swslam on the first 60 scans of lake-short, deterministic
  local out=$1 limit=${2:-unlimited}
  (trap '' XFSZ; ulimit -f "$limit"; exec "$build/apps/swslam" -c "$src/config/default.ini" \
    -i "$src/datasets/lake-short/lake-short.rawlog" -o "$out" --max-scans 60 -d -q --no-render) \
    > "$out.out" 2> "$out.err"
}

run "$tmp/whole" || { bad "the run without a limit failed: $(cat "$tmp/whole.err")"; exit 1; }
graph=$(stat -c %s "$tmp/whole/graph.graph")
# A limit below graph.graph (1 KB blocks), above the smallest outputs.
blocks=$(((graph - 1) / 1024))
((blocks >= 1)) || { bad "graph.graph is only $graph bytes: no limit below it"; exit 1; }
limit=$((blocks * 1024))
run "$tmp/full" "$blocks"
code=$?
echo "limit $limit bytes: exit $code"; cat "$tmp/full.err"; tail -1 "$tmp/full.out"
((code == 4)) || bad "exit $code, not 4"
too_big=0
for f in "$tmp"/whole/*; do
  name=$(basename "$f") size=$(stat -c %s "$f") part=$tmp/full/$name
  if ((size > limit)); then
    too_big=$((too_big + 1))
    [[ -e $part ]] && bad "$name: $(stat -c %s "$part") of $size bytes left under its name"
    # (map.pgm is written with map.yaml, under its name)
    grep -q "^swslam: could not write .*$name'*: .*the disk refused the data: File too large" "$tmp/full.err" ||
      bad "$name: its failure is not named"
  elif [[ -e $part ]]; then
    # Whole: the deterministic outputs byte for byte, the timed ones (stats.csv, summary.md) by size.
    case $name in
      stats.csv | summary.md) (($(stat -c %s "$part") > 0)) || bad "$name is empty" ;;
      *) cmp -s "$f" "$part" || bad "$name differs from the run without a limit" ;;
    esac
  fi
done
((too_big > 0)) || bad "no output was past the limit: the test tests nothing"
# Nothing empty or cut at the limit anywhere in the folder (temporary files included).
while IFS= read -r -d '' f; do
  size=$(stat -c %s "$f")
  [[ $(basename "$f") == .swslam.lock ]] && continue
  ((size > 0 && size < limit)) || bad "$f: $size bytes (empty or cut at the limit)"
done < <(find "$tmp/full" -type f -print0)
# The last line: what it lists exists, what it says was not written does not.
last=$(tail -1 "$tmp/full.out")
listed=$(sed -n 's/^# outputs in [^ ]* (\([^)]*\)).*/\1/p' <<< "$last" | tr -d ',')
missing=$(sed -n 's/.*; not written: //p' <<< "$last" | tr -d ',')
[[ -n $missing ]] || bad "the last line does not say what was not written: $last"
for name in $listed; do [[ -s $tmp/full/$name ]] || bad "the last line lists $name, which does not exist"; done
for name in $missing; do [[ -e $tmp/full/$name ]] && bad "the last line says $name was not written, but it is there"; done
exit $fail
