#!/usr/bin/env bash
# The modules stand in layers (doc/architecture.md): every include of a swslam header must
# point to the file's own module or to a module the file's module links, and that module's
# layer must be lower. Unit tests (*_test.cpp) may also use modules of their own layer as
# instruments, never a higher one. The table of modules, layers and links is the one CMake
# wrote from libslam/CMakeLists.txt. Prints each module's layer and links, then every
# violation; fails on any.
# Usage: layering_test.sh SOURCE_DIR BINARY_DIR
set -euo pipefail
src=$1 bin=$2
table=$bin/swslam_modules.txt
[[ -f $table ]] || { echo "layering: $table is missing (configure first)"; exit 1; }

declare -A layer deps
while read -r name lay rest; do
  [[ $name == \#* || -z $name ]] && continue
  layer[$name]=$lay
  deps[$name]=" $rest "
done < "$table"

fail=0
violation() { echo "VIOLATION: $*"; fail=1; }

for m in "${!layer[@]}"; do
  for d in ${deps[$m]}; do
    [[ -n ${layer[$d]:-} ]] || { violation "module $m links '$d', which is not a module"; continue; }
    ((layer[$d] < layer[$m])) || violation "module $m (layer ${layer[$m]}) links $d (layer ${layer[$d]})"
  done
done

checked=0
for dir in "$src"/libslam/swslam/*/; do
  m=$(basename "$dir")
  [[ -n ${layer[$m]:-} ]] || { violation "folder libslam/swslam/$m is not a module of libslam/CMakeLists.txt"; continue; }
  for f in "$dir"*.h "$dir"*.cpp; do
    [[ -f $f ]] || continue
    rel=${f#"$src"/}
    # "..." includes of swslam headers would bypass the check (and the installed layout).
    if grep -nE '#include "(\.\./|swslam/)' "$f" > /dev/null; then
      violation "$rel includes a swslam header with quotes or a relative path"
    fi
    while IFS=: read -r line target; do
      checked=$((checked + 1))
      t=${target%%/*}
      [[ $t == "$m" ]] && continue
      if [[ -z ${layer[$t]:-} ]]; then
        violation "$rel:$line includes swslam/$target: '$t' is not a module"
      elif [[ $f == *_test.cpp ]]; then
        ((layer[$t] <= layer[$m])) ||
          violation "$rel:$line (test of $m, layer ${layer[$m]}) includes swslam/$target (layer ${layer[$t]})"
      elif [[ ${deps[$m]} != *" $t "* ]]; then
        violation "$rel:$line includes swslam/$target, but $m (layer ${layer[$m]}) does not link $t" \
          "(layer ${layer[$t]})"
      fi
    done < <(grep -noE '^#include <swslam/[a-z0-9_]+/[a-z0-9_]+\.h>' "$f" |
             sed -E 's|^([0-9]+):#include <swslam/(.*)>|\1:\2|')
  done
done

for m in $(printf '%s\n' "${!layer[@]}" | sort); do
  printf 'layer %s  %-12s links:%s\n' "${layer[$m]}" "$m" "${deps[$m]% }"
done | sort
echo "layering: ${#layer[@]} modules, $checked includes checked"
if ((fail)); then
  echo "layering: FAILED"
  exit 1
fi
echo "layering: no include runs up, none sideways but from a unit test, no module loop"
