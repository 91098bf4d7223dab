#!/usr/bin/env bash
# Installs the Debian bookworm packages swslam needs to build, test and run.
# Skips apt entirely when every package is already installed.
# Usage: scripts/install-deps.sh [--with-bench] [--with-tools] [--with-fuzz]
#   --with-bench adds Ceres for swslam-bench-graph;
#   --with-tools adds MRPT's programs (mrpt-apps: RawLogViewer, rawlog-edit, icp-slam,
#   carmen2rawlog), which scripts/bench-valley.sh runs side by side with swslam;
#   --with-fuzz adds clang 14 with its libFuzzer and sanitizer runtimes, and llvm-symbolizer
#   for readable stacks, which scripts/fuzz.sh builds the harnesses with.
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  libeigen3-dev libgtest-dev liboctomap-dev libsuitesparse-dev
  libmrpt-obs-dev libmrpt-slam-dev libmrpt-maps-dev libmrpt-graphs-dev
  libmrpt-graphslam-dev libmrpt-opengl-dev libmrpt-hwdrivers-dev libmrpt-tclap-dev
  mrpt-common
  librosbag-storage-dev libsensor-msgs-dev libnav-msgs-dev libtf2-msgs-dev libmrpt-ros1bridge-dev
  libsqlite3-dev libzstd-dev liblz4-dev libyaml-cpp-dev sqlite3
  libegl1 libegl-mesa0 libgl1-mesa-dri
  python3-matplotlib
)
# The ROS 2 test bags are written by npm packages (tests/ros2/make-bags.sh): Debian's Node.js and
# npm, unless a Node.js with its npm is installed already (NodeSource's nodejs package holds npm
# and conflicts with Debian's).
command -v npm > /dev/null || packages+=(nodejs npm)
for arg in "$@"; do
  case $arg in
    --with-bench) packages+=(libceres-dev) ;;
    --with-tools) packages+=(mrpt-apps) ;;
    --with-fuzz) packages+=(clang-14 libclang-rt-14-dev llvm-14) ;;
    *) echo "install-deps: unknown option '$arg' (expected --with-bench, --with-tools or --with-fuzz)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done
if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  sudo_cmd=(sudo)
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update
"${sudo_cmd[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
