#!/usr/bin/env bash
# The trade-off of denoising, measured beside OpenVDB. For every mesh and
# noise level: a noisy copy (Gaussian noise along the normals, sigma in
# voxels of the grid), then lbmshape's denoise at its defaults (which
# preserve features), with --twicing, and with
# 1..10 steps (isotropic, --preserve-features, --anisotropic), and OpenVDB's
# LevelSetFilter::meanCurvature with 1..6 iterations (3 is what users run)
# at the same voxel size; each result compared with the clean mesh:
#   normal error   mean angle between the surfaces' normals (compare's
#                  mean_normal_angle_deg, both ways), degrees
#   distance       mean distance from the result to the clean mesh, voxels
#   volume         change of the enclosed volume against the clean mesh, %
# Writes OUT/tradeoff.csv and, with gnuplot (Debian's gnuplot-nox, installed
# if missing), the plot PLOT: normal error against distance, one panel per
# noise level, the meshes averaged, steps and iterations along each curve.
#
#   VDB_PEER=/path/to/vdb_peer scripts/denoise-tradeoff.sh MESH.obj...
#   (../shared/peers/openvdb/build.sh builds the peer; without VDB_PEER the
#   OpenVDB rows are left out)
# Environment: LBMSHAPE (build/lbmshape), RES (128), SEED (1, the noise's), SIGMAS ("0.25 0.5 1"), STEPS ("1 2 ... 10"),
#   ITERS ("1 2 3 4 5 6"), METHODS ("isotropic preserve-features anisotropic"; "none": the
#   default and --twicing rows alone),
#   OUT (build/tradeoff), PLOT (docs/images/denoise-tradeoff.png; "" for none),
#   REPLOT (1: draw PLOT again from OUT/tradeoff.csv, measuring nothing)
set -euo pipefail
[[ $# -gt 0 ]] || { echo "usage: [VDB_PEER=...] denoise-tradeoff.sh MESH.obj..." >&2; exit 2; }
here=$(cd "$(dirname "$0")/.." && pwd)
lbmshape=${LBMSHAPE:-$here/build/lbmshape}
[[ -x $lbmshape ]] || { echo "denoise-tradeoff: build lbmshape first ($lbmshape)" >&2; exit 2; }
res=${RES:-128}
seed=${SEED:-1}  # of the noise
sigmas=(${SIGMAS:-0.25 0.5 1})
steps=(${STEPS:-1 2 3 4 5 6 7 8 9 10})
iters=(${ITERS:-1 2 3 4 5 6})
methods=(${METHODS:-isotropic preserve-features anisotropic})
out=${OUT:-$here/build/tradeoff}
plot=${PLOT-$here/docs/images/denoise-tradeoff.png}
margin=4  # denoise's default; OpenVDB's --res counts the box alone
mkdir -p "$out"
csv=$out/tradeoff.csv
[[ -z ${REPLOT:-} || -f $csv ]] || { echo "denoise-tradeoff: REPLOT needs $csv" >&2; exit 2; }
[[ -n ${REPLOT:-} ]] ||
  echo "mesh,sigma_voxels,method,amount,normal_error_deg,distance_voxels,volume_change_percent" >"$csv"

# compare CLEAN RESULT VOXEL: "normal_error,distance_voxels,volume_change_percent"
measure() {
  "$lbmshape" compare "$1" "$2" --json --samples 100000 |
    jq -r --argjson voxel "$3" '[.mean_normal_angle_deg, .b_to_a.mean / $voxel,
      100 * (.b.volume - .a.volume) / .a.volume] | map(tostring) | join(",")'
}

for mesh in "$@"; do
  [[ -z ${REPLOT:-} ]] || break
  name=$(basename "${mesh%.*}")
  for sigma in "${sigmas[@]}"; do
    noisy=$out/${name}_sigma$sigma.obj
    "$lbmshape" -q noise "$mesh" "$noisy" --sigma "$sigma" --res "$res" --seed "$seed" --force
    voxel=$("$lbmshape" -q denoise "$noisy" "$out/result.obj" --steps 0 --res "$res" --json --force | jq .grid.voxel)
    row() { echo "$name,$sigma,$1,$2,$(measure "$mesh" "$3" "$voxel")" | tee -a "$csv"; }
    row noisy 0 "$noisy"
    "$lbmshape" -q denoise "$noisy" "$out/result.obj" --res "$res" --force
    row lbmshape-default 0 "$out/result.obj"
    "$lbmshape" -q denoise "$noisy" "$out/result.obj" --res "$res" --twicing --force
    row lbmshape-twicing 0 "$out/result.obj"
    for method in "${methods[@]}"; do
      [[ $method != none ]] || continue
      flag=(--"$method")
      for k in "${steps[@]}"; do
        "$lbmshape" -q denoise "$noisy" "$out/result.obj" --res "$res" --steps "$k" "${flag[@]}" --force
        row "$method" "$k" "$out/result.obj"
      done
    done
    if [[ -n ${VDB_PEER:-} ]]; then
      for i in "${iters[@]}"; do
        "$VDB_PEER" denoise "$noisy" "$out/result.obj" --res $((res - 2 * margin)) --iters "$i" \
          --filter meancurv --threads 2 >/dev/null
        # OpenVDB's level sets are negative inside, so its triangles face
        # inwards: turned round here, or every normal would be 180 degrees off.
        awk '/^f / { t = $3; $3 = $4; $4 = t } { print }' "$out/result.obj" >"$out/turned.obj"
        row openvdb "$i" "$out/turned.obj"
      done
    fi
  done
done
rm -f "$out/result.obj" "$out/turned.obj"

[[ -n $plot ]] || exit 0
command -v gnuplot >/dev/null || {
  SUDO=""; [[ $(id -u) == 0 ]] || SUDO=sudo
  $SUDO apt-get install -y -qq gnuplot-nox >/dev/null
}
# Per (sigma, method, amount): the mean over the meshes, one file per curve.
awk -F, -v dir="$out" 'NR > 1 && $3 != "noisy" {
    key = $2 "," $3 "," $4; n[key]++; e[key] += $5; d[key] += $6
  }
  END {
    for (key in n) {
      split(key, k, ",")
      printf "%s %g %g\n", k[3], e[key] / n[key], d[key] / n[key] >> (dir "/curve_" k[1] "_" k[2] ".dat")
    }
  }' < <(rm -f "$out"/curve_*.dat; cat "$csv")
for f in "$out"/curve_*.dat; do sort -g -o "$f" "$f"; done
panels=""
for sigma in "${sigmas[@]}"; do
  curves=""
  for method in "${methods[@]}" openvdb lbmshape-default lbmshape-twicing; do
    f=$out/curve_${sigma}_$method.dat
    [[ -f $f ]] || continue
    case $method in
      isotropic) style="lc rgb '#1f77b4' pt 7" title="lbmshape --isotropic" ;;
      preserve-features) style="lc rgb '#2ca02c' pt 5" title="lbmshape --preserve-features (the default)" ;;
      anisotropic) style="lc rgb '#9467bd' pt 9" title="lbmshape --anisotropic (paper)" ;;
      openvdb) style="lc rgb '#d62728' pt 13" title="OpenVDB meanCurvature" ;;
      lbmshape-default) style="lc rgb 'black' pt 3 ps 2.5 lw 2" title="lbmshape, no options" ;;
      lbmshape-twicing) style="lc rgb 'black' pt 6 ps 2.5 lw 2" title="lbmshape --twicing" ;;
    esac
    with="linespoints"; [[ $method == lbmshape-default || $method == lbmshape-twicing ]] && with="points"
    curves+="'$f' using 3:2 with $with $style title \"$title\", "
    [[ $method == openvdb || $method == isotropic ]] &&
      curves+="'$f' using 3:2:(sprintf('%d', \$1)) with labels offset 0.8,0.6 font ',8' tc rgb 'gray30' notitle, "
  done
  panels+="set title 'noise sigma = $sigma voxel'; plot ${curves%, }
"
done
meshes=$(for m in "$@"; do basename "${m%.*}"; done | paste -sd, - | sed 's/,/, /g')
gnuplot <<EOF
set terminal pngcairo size $((520 * ${#sigmas[@]})),520 font 'Sans,10'
set output '$plot'
set multiplot layout 1,${#sigmas[@]} title "Denoising at --res $res, mean over: $meshes (numbers: steps, iterations)"
set xlabel 'mean distance to the clean mesh (voxels)'
set ylabel 'mean normal error (degrees)'
set key top right box opaque
set grid
$panels
unset multiplot
EOF
echo "wrote $csv and $plot" >&2
