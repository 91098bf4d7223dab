# Sourced by the script tests that run a Python script: find_python [MODULE...] prints the
# first of python3 on PATH and Debian's /usr/bin/python3 that imports every MODULE (Debian's
# python3-* packages install for the latter), or nothing.
find_python() {
  local cand module ok
  for cand in python3 /usr/bin/python3; do
    command -v "$cand" > /dev/null || continue
    ok=1
    for module in "$@"; do
      "$cand" -c "import $module" 2> /dev/null || { ok=0; break; }
    done
    if [[ $ok == 1 ]]; then
      echo "$cand"
      return
    fi
  done
}
