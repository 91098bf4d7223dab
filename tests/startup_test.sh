#!/usr/bin/env bash
# Every program answers --help, --version and a bad command line before any heavy library is
# loaded: MRPT's observations, images, maps, OpenGL, SLAM, drivers or ROS bridge, OpenCV, GDAL,
# ROS bags, or the program's own lib<program>-run.so that a heavy program loads after parsing
# (apps/CMakeLists.txt). Checked twice: no executable needs one (readelf -d), and the dynamic
# loader's report (LD_DEBUG=files) of each start names none. A real run of swslam-eval, the
# control, shows that the report names what a run loads.
# Usage: startup_test.sh SOURCE_DIR BINARY_DIR
set -uo pipefail
bin=$2/apps
heavy='^lib(mrpt-(obs|img|maps|opengl|slam|graphslam|hwdrivers|ros1bridge|gui)|opencv_[a-z0-9_]+|gdal|rosbag[a-z_]*|swslam[a-z0-9-]*-run)\.so'
fail=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

loaded() {  # the file names of the shared objects a command loads
  LD_DEBUG=files "$@" 2>&1 > /dev/null | sed -nE 's|.*file=([^ ]*/)?([^ /]+) \[[0-9]+\];  generating link map.*|\2|p'
}

programs=0
for app in "$bin"/swslam "$bin"/swslam-*; do
  [[ -f $app && -x $app ]] || continue
  programs=$((programs + 1))
  name=$(basename "$app")
  needed=$(readelf -d "$app" | sed -nE 's/.*\(NEEDED\).*\[(.*)\]/\1/p')
  if grep -E "$heavy" <<< "$needed" > "$work/bad"; then
    echo "FAIL: $name needs $(paste -sd ' ' "$work/bad")"; fail=1
  fi
  for args in --help --version --no-such-flag; do
    libs=$(loaded "$app" $args)
    if grep -E "$heavy" <<< "$libs" > "$work/bad"; then
      echo "FAIL: $name $args loads $(paste -sd ' ' "$work/bad")"; fail=1
    fi
  done
  printf '%-24s %3d libraries needed, %3d loaded at --help\n' "$name" "$(wc -l <<< "$needed")" \
    "$(loaded "$app" --help | wc -l)"
done
((programs)) || { echo "FAIL: no program in $bin"; exit 1; }

# The control: a real run loads the program's library and MRPT's observations, and the report says so.
printf '1 0 0 0 0 0 0 1\n2 1 0 0 0 0 0 1\n' > "$work/t.tum"
libs=$(loaded "$bin/swslam-eval" ate "$work/t.tum" "$work/t.tum")
for lib in libswslam-eval-run.so libmrpt-obs.so; do
  grep -q "^$lib" <<< "$libs" || { echo "FAIL: the control, swslam-eval ate, did not report loading $lib"; fail=1; }
done
((fail)) || echo "startup: $programs programs load no heavy library for --help, --version or a bad command line"
exit $fail
