#!/usr/bin/env bash
# Every app: a bad command line exits non-zero with a message; --help exits 0.
set -uo pipefail
bin=$2/apps
fail=0
for app in "$bin"/swslam "$bin"/swslam-*; do
  [[ -x $app ]] || continue
  name=$(basename "$app")
  if "$app" --no-such-flag > /dev/null 2>&1; then
    echo "FAIL: $name --no-such-flag exited 0"; fail=1
  fi
  if ! "$app" --help > /dev/null 2>&1; then
    echo "FAIL: $name --help exited non-zero"; fail=1
  fi
done
exit $fail
