#!/usr/bin/env bash
# swslam-sim end to end: regenerating lake-short gives the committed dataset (same
# decompressed rawlog, same ground truth), and a bad scenario fails naming the key
# without writing anything.
# Usage: sim_app_test.sh SOURCE_DIR BINARY_DIR
set -euo pipefail
src=$1
bin=$2
sim=$bin/apps/swslam-sim
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

"$sim" --quiet --scenario "$src/datasets/scenarios/lake-short.ini" --output "$out/gen"
for f in lake-short.gt.tum lake-short.gt.txt; do
  cmp "$out/gen/$f" "$src/datasets/lake-short/$f" ||
    { echo "datasets/lake-short/$f is stale: run scripts/gen-datasets.sh lake-short" >&2; exit 1; }
done
# Compare the serialized content, not the gzip stream (zlib versions may differ).
cmp <(gzip -dc "$out/gen/lake-short.rawlog") <(gzip -dc "$src/datasets/lake-short/lake-short.rawlog") ||
  { echo "datasets/lake-short/lake-short.rawlog is stale: run scripts/gen-datasets.sh lake-short" >&2; exit 1; }
[[ -z $(find "$out/gen" -name '.*tmp*') ]] || { echo "temporary files left behind" >&2; exit 1; }

sed 's/^rate_hz/rate_Hz_typo/' "$src/datasets/scenarios/lake-short.ini" > "$out/typo.ini"
if "$sim" --scenario "$out/typo.ini" --output "$out/bad" 2> "$out/err.txt"; then
  echo "a misspelled key was accepted" >&2
  exit 1
fi
grep -q "rate_Hz_typo" "$out/err.txt" || { echo "error does not name the key:" >&2; cat "$out/err.txt" >&2; exit 1; }
[[ ! -e $out/bad ]] || { echo "output written despite the error" >&2; exit 1; }
cat "$out/err.txt"
echo "sim_app_test: OK"
