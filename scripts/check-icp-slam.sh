#!/usr/bin/env bash
# Checks that MRPT's own icp-slam runs on a simulated rawlog (default: lake-short) and
# scores its path and the raw odometry against the ground truth. Needs the Debian
# package mrpt-apps (not a build dependency: apt-get install mrpt-apps).
# Usage: scripts/check-icp-slam.sh [NAME]
set -euo pipefail
cd "$(dirname "$0")/.."
name=${1:-lake-short}
rawlog=datasets/$name/$name.rawlog
gt=datasets/$name/$name.gt.txt
command -v icp-slam > /dev/null || { echo "icp-slam not found: apt-get install mrpt-apps" >&2; exit 1; }
[[ -f $rawlog ]] || bash scripts/gen-datasets.sh "$name"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# MRPT's example configuration, without the 3D window and scene files.
sed -e 's|^SHOW_PROGRESS_3D_REAL_TIME=1|SHOW_PROGRESS_3D_REAL_TIME=0|' \
    -e 's|^SAVE_3D_SCENE=1|SAVE_3D_SCENE=0|' \
    -e "s|^logOutput_dir=.*|logOutput_dir=$work/out|" \
    /usr/share/mrpt/config_files/icp-slam/icp-slam_demo_classic.ini > "$work/icp.ini"
echo "== rawlog-edit --info $rawlog"
rawlog-edit --info -i "$rawlog" 2>&1 | grep -E 'Overall number|Observations format|Sensor \(' || true
echo "== icp-slam $work/icp.ini $rawlog"
icp-slam "$work/icp.ini" "$rawlog" > "$work/log.txt" 2>&1
grep -E '\*\*END\*\*|Dumping final map' "$work/log.txt" | sed 's/^\[[^]]*\] *//'

# icp-slam logs one pose per rawlog entry; with odometry, entry 2i+1 is scan i. The
# odometry path starts at the origin: express it from the first ground-truth pose.
score() {
  awk -v label="$1" -v stride="$3" '
    NR == FNR { gx[FNR - 1] = $2; gy[FNR - 1] = $3; gp[FNR - 1] = $4; n = FNR; next }
    ($1 + 1) % stride == 0 {
      i = ($1 + 1) / stride - 1; if (i >= n) next
      x = $2; y = $3
      if (label ~ /odometry/) { c = cos(gp[0]); s = sin(gp[0]); x = gx[0] + c * $2 - s * $3; y = gy[0] + s * $2 + c * $3 }
      e = sqrt((x - gx[i]) ^ 2 + (y - gy[i]) ^ 2); sum += e * e; m++; if (e > mx) mx = e; last = e
    }
    END { printf "%-14s poses %d: position error RMS %.3f m, max %.3f m, final %.3f m\n", label, m, sqrt(sum / m), mx, last }
  ' "$gt" "$2"
}
stride=$(( $(wc -l < "$work/out/log_estimated_path.txt") / $(wc -l < "$gt") ))
score "icp-slam" "$work/out/log_estimated_path.txt" "$stride"
score "odometry only" "$work/out/log_odometry_path.txt" "$stride"
