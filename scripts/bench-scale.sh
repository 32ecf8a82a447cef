#!/usr/bin/env bash
# Whole-process time and peak memory of lbmshape as the grid grows: denoise
# of a mesh at --res 128, 256, 512 and 1024, and a 48-frame morph at 128 and
# 256, each run R times (median, min and max printed), with the lattice's
# size and speed from --json. With VDB_PEER set to the OpenVDB peer's binary
# (../shared/peers/openvdb/build.sh builds it), the same jobs run through
# OpenVDB in the same session, alternating with lbmshape.
#
#   scripts/bench-scale.sh MESH.obj [RUNS] [RESOLUTIONS...]      e.g. armadillo.obj 3 128 256 512
#   MORPH_SOURCE=sphere.obj scripts/bench-scale.sh MESH.obj     adds the morphs
#   MORPH_FLAGS=--dense ...                                     morphs on the grid
#   MORPH_FLAGS='--extract device' ...                          frames' marching cubes on the device
set -euo pipefail
mesh=${1:?usage: bench-scale.sh MESH.obj [RUNS] [RESOLUTIONS...]}
runs=${2:-3}
shift 2 || shift $#
resolutions=("$@")
[[ ${#resolutions[@]} -gt 0 ]] || resolutions=(128 256 512 1024)
lbmshape=$(realpath "$(dirname "$0")/../build/lbmshape")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Runs a command R times; prints "median min max" of seconds and of MB.
measure() {
  local -a seconds=() megabytes=()
  for ((r = 0; r < runs; ++r)); do
    /usr/bin/time -f '%e %M' -o "$work/time" "$@" >"$work/out.json" 2>"$work/err" || {
      echo "failed: $*" >&2
      tail -3 "$work/err" >&2
      return 1
    }
    read -r s k <"$work/time"
    seconds+=("$s")
    megabytes+=($((k / 1024)))
  done
  local sorted
  sorted=$(printf '%s\n' "${seconds[@]}" | sort -g | awk '{a[NR]=$1} END {printf "%.2f s (%.2f-%.2f)", a[int((NR+1)/2)], a[1], a[NR]}')
  printf '%s, ' "$sorted"
  printf '%s\n' "${megabytes[@]}" | sort -g | awk '{a[NR]=$1} END {printf "%d MB (%d-%d)", a[int((NR+1)/2)], a[1], a[NR]}'
}

lattice() {
  python3 -c "import json,sys; d=json.load(open('$work/out.json')); l=d.get('lattice',{}); ms=d['ms']
print(f\"  lattice {l.get('kind')}: {l.get('cells')} cells, {d.get('mlups') or 0:.1f} MLUPS; sdf {ms.get('sdf',0):.0f} ms, lbm {ms.get('lbm',0):.0f} ms, extract {ms.get('extract',0):.0f} ms\")" 2>/dev/null || true
}

echo "denoise $(basename "$mesh"), $runs runs each (median, min-max), $(nproc) cores"
for res in "${resolutions[@]}"; do
  printf 'lbmshape --res %-5s ' "$res"
  measure "$lbmshape" denoise "$mesh" "$work/out.glb" --res "$res" --json -q && echo && lattice
  if [[ -n ${VDB_PEER:-} ]]; then
    printf 'openvdb  --res %-5s ' "$res"
    measure "$VDB_PEER" denoise "$mesh" "$work/vdb.obj" --res "$res" --iters 3 --filter meancurv --threads "$(nproc)" && echo
  fi
done

if [[ -n ${MORPH_SOURCE:-} ]]; then
  echo "morph $(basename "$MORPH_SOURCE") -> $(basename "$mesh"), 48 frames"
  for res in 128 256; do
    printf 'lbmshape --res %-5s ' "$res"
    measure "$lbmshape" morph "$MORPH_SOURCE" "$mesh" "$work/frames$res" --res "$res" --align none --force --json -q ${MORPH_FLAGS:-} &&
      python3 -c 'import json, sys; r = json.load(open(sys.argv[1]))
print(", frames extracted on the %s, %.1f MB read back a frame" % (r["extract_on"], r["lattice"]["frame_read_back_bytes"] / 1e6))' "$work/out.json"
    if [[ -n ${VDB_PEER:-} ]]; then
      printf 'openvdb  --res %-5s ' "$res"
      mkdir -p "$work/vdbframes$res"  # the peer writes into an existing folder
      measure "$VDB_PEER" morph "$MORPH_SOURCE" "$mesh" "$work/vdbframes$res" --res "$res" --frames 48 --threads "$(nproc)" && echo
    fi
  done
fi
