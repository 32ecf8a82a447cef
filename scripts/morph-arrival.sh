#!/usr/bin/env bash
# Where morphs end: each SOURCE -> TARGET pair morphed with the defaults at
# two frame counts, and how far the last frame is from the target's own zero
# level on the grid (mean and Hausdorff, voxels; the goal is 0.05 and 1),
# with the lattice steps, whether the run converged, and the whole-process
# time and peak memory (/usr/bin/time). The paper's scheme (constant gamma
# and Cs) over the same steps is measured beside it.
#
#   scripts/morph-arrival.sh [--res N] SOURCE TARGET [TARGET ...]
#   e.g. scripts/morph-arrival.sh sphere ../shared/assets/armadillo.obj
# SOURCE "sphere" is a unit UV sphere (48 x 96 quads, scripts/make-sphere.py).
set -euo pipefail
res=128
if [[ ${1:-} == --res ]]; then
  res=$2
  shift 2
fi
source=${1:?usage: morph-arrival.sh [--res N] SOURCE TARGET [TARGET ...]}
shift
[[ $# -gt 0 ]] || { echo "usage: morph-arrival.sh [--res N] SOURCE TARGET [TARGET ...]" >&2; exit 2; }
lbmshape=$(realpath "$(dirname "$0")/../build/lbmshape")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [[ $source == sphere ]]; then
  source=$work/sphere.obj
  python3 "$(dirname "$0")/make-sphere.py" "$source"
fi

# Prints one row: label, steps, mean, Hausdorff, converged, seconds, MB.
row() {
  local label=$1
  shift
  /usr/bin/time -f '%e %M' -o "$work/time" "$lbmshape" morph "$@" --res "$res" --no-animation --force --json \
    >"$work/out.json" 2>"$work/err" || { echo "failed: $*" >&2; tail -3 "$work/err" >&2; return 1; }
  read -r seconds kilobytes <"$work/time"
  python3 - "$work/out.json" "$label" "$seconds" "$kilobytes" <<'EOF'
import json, sys
r = json.load(open(sys.argv[1]))
f = r["final"]
print(f"| {sys.argv[2]} | {r['steps']} | {f['mean_distance_to_target_level_voxels']:.3f} | "
      f"{f['hausdorff_to_target_level_voxels']:.2f} | {'yes' if r['converged'] else 'no'} | "
      f"{float(sys.argv[3]):.2f} s | {int(sys.argv[4]) // 1024} MB |")
EOF
}

echo "| morph (--res $res) | steps | mean (voxels) | Hausdorff (voxels) | converged | time | peak RSS |"
echo "|---|---|---|---|---|---|---|"
for target in "$@"; do
  name="$(basename "$source" .obj) → $(basename "$target" .obj)"
  row "$name, 12 frames" "$source" "$target" "$work/a"
  row "$name, 48 frames" "$source" "$target" "$work/b"
  steps=$(python3 -c "import json; print(json.load(open('$work/out.json'))['steps'])")
  row "$name, paper's scheme, --steps $steps" "$source" "$target" "$work/c" --steps "$steps"
done
