#!/usr/bin/env bash
# How a morph approaches its target, frame by frame, beside OpenVDB's
# LevelSetMorphing: SOURCE -> TARGET with FRAMES frames, lbmshape at its
# defaults (--align none) and the OpenVDB peer at the same voxel size, each
# frame's mean and largest distance to the target mesh (lbmshape compare,
# from the frame to the target, in voxels), with each run's whole-process
# time and peak memory. Writes OUT/morph-distance.csv and, with gnuplot
# (Debian's gnuplot-nox, installed if missing), the plot PLOT.
#
#   VDB_PEER=/path/to/vdb_peer scripts/morph-vs-openvdb.sh SOURCE TARGET
#   (../shared/peers/openvdb/build.sh builds the peer)
# SOURCE "sphere": a unit sphere (scripts/make-sphere.py).
# Environment: LBMSHAPE (build/lbmshape), RES (128), FRAMES (48),
#   OUT (build/morph-vs-openvdb), PLOT (docs/images/morph-vs-openvdb.png; "" for none)
set -euo pipefail
[[ $# -eq 2 ]] || { echo "usage: VDB_PEER=... morph-vs-openvdb.sh SOURCE TARGET" >&2; exit 2; }
[[ -n ${VDB_PEER:-} ]] || { echo "morph-vs-openvdb: set VDB_PEER to the OpenVDB peer's binary" >&2; exit 2; }
here=$(cd "$(dirname "$0")/.." && pwd)
lbmshape=${LBMSHAPE:-$here/build/lbmshape}
res=${RES:-128}
frames=${FRAMES:-48}
out=${OUT:-$here/build/morph-vs-openvdb}
plot=${PLOT-$here/docs/images/morph-vs-openvdb.png}
margin=4  # lbmshape's default; OpenVDB's --res counts the box alone
source=$1 target=$2
mkdir -p "$out"
if [[ $source == sphere ]]; then
  source=$out/sphere.obj
  python3 "$here/scripts/make-sphere.py" "$source"
fi
rm -rf "$out/lbmshape" "$out/openvdb"

# Runs a command; prints its whole-process time and peak memory.
timed() {
  /usr/bin/time -f '%e %M' -o "$out/time" "$@" >"$out/run.json" 2>"$out/run.err" ||
    { echo "failed: $*" >&2; tail -3 "$out/run.err" >&2; exit 1; }
  read -r seconds kilobytes <"$out/time"
  echo "$seconds s, $((kilobytes / 1024)) MB"
}

lbm_cost=$(timed "$lbmshape" morph "$source" "$target" "$out/lbmshape" --res "$res" --frames "$frames" --align none \
  --no-animation --json)
voxel=$(jq .grid.voxel "$out/run.json")
steps=$(jq .steps "$out/run.json")
mkdir -p "$out/openvdb"
vdb_cost=$(timed "$VDB_PEER" morph "$source" "$target" "$out/openvdb" --res $((res - 2 * margin)) --frames "$frames" \
  --threads 2)
echo "# $(basename "$source") -> $(basename "$target"), --res $res (voxel $voxel), $frames frames;" \
  "lbmshape: $steps steps, $lbm_cost; OpenVDB: $vdb_cost" | tee "$out/morph-distance.csv" >&2
echo "tool,frame,mean_distance_voxels,max_distance_voxels" >>"$out/morph-distance.csv"

distances() {  # TOOL FRAME_FILE...
  local tool=$1 frame=0
  shift
  for f in "$@"; do
    "$lbmshape" compare "$target" "$f" --json --samples 30000 |
      jq -r --arg tool "$tool" --argjson frame "$frame" --argjson voxel "$voxel" \
        '[$tool, $frame, .b_to_a.mean / $voxel, .b_to_a.max / $voxel] | map(tostring) | join(",")'
    frame=$((frame + 1))
  done
}
distances lbmshape "$out"/lbmshape/frame_*.glb >>"$out/morph-distance.csv"
distances openvdb "$out"/openvdb/frame_*.obj >>"$out/morph-distance.csv"
grep -E "^(lbmshape|openvdb),$((frames - 1))," "$out/morph-distance.csv" | sed 's/^/last frame: /' >&2

[[ -n $plot ]] || exit 0
command -v gnuplot >/dev/null || {
  SUDO=""; [[ $(id -u) == 0 ]] || SUDO=sudo
  $SUDO apt-get install -y -qq gnuplot-nox >/dev/null
}
for tool in lbmshape openvdb; do
  grep "^$tool," "$out/morph-distance.csv" | tr , ' ' >"$out/$tool.dat"
done
gnuplot <<EOF
set terminal pngcairo size 900,520 font 'Sans,10'
set output '$plot'
set title "$(basename "$source" .obj) → $(basename "$target" .obj), --res $res, $frames frames: distance from each frame to the target"
set xlabel 'frame'
set ylabel 'distance to the target mesh (voxels)'
set logscale y
set grid
set key top right box opaque
plot '$out/lbmshape.dat' using 2:3 with linespoints lc rgb '#1f77b4' pt 7 ps 0.6 title 'lbmshape, mean', \
     '$out/lbmshape.dat' using 2:4 with lines lc rgb '#1f77b4' dt 2 title 'lbmshape, largest', \
     '$out/openvdb.dat' using 2:3 with linespoints lc rgb '#d62728' pt 13 ps 0.6 title 'OpenVDB LevelSetMorphing, mean', \
     '$out/openvdb.dat' using 2:4 with lines lc rgb '#d62728' dt 2 title 'OpenVDB, largest'
EOF
echo "wrote $out/morph-distance.csv and $plot" >&2
