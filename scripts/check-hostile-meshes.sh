#!/usr/bin/env bash
# Runs lbmshape on every mesh file in a folder of malformed or hostile
# inputs, as `compare FILE cube.obj -q` and `denoise FILE out.glb --res 24 -q`,
# each under a 4 GB address-space limit, and prints one line per run: exit
# code, whole-process seconds, peak RSS, the number of stderr lines, and
# whether any file was left behind. What every run must give: exit 3 (or 0
# for a valid file), within 2 s, at most 512 MB, one "lbmshape: error:" line
# when it fails, and nothing written.
#
#   scripts/check-hostile-meshes.sh FOLDER [LBMSHAPE]
set -uo pipefail
folder=${1:?usage: check-hostile-meshes.sh FOLDER [LBMSHAPE]}
lbmshape=$(realpath "${2:-$(dirname "$0")/../build/lbmshape}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# A unit cube to compare against.
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n' >"$work/cube.obj"

printf '%-44s %-8s %4s %6s %7s %5s %s\n' file command exit seconds "RSS MB" lines "left behind"
failures=0
for file in "$folder"/*; do
  case "${file,,}" in *.obj | *.ply | *.off | *.stl | *.gltf | *.glb) ;; *) continue ;; esac
  for command in compare denoise; do
    out="$work/out"
    rm -rf "$out" && mkdir "$out"
    if [[ $command == compare ]]; then args=(compare "$file" "$work/cube.obj" -q); else args=(denoise "$file" "$out/out.glb" --res 24 -q); fi
    (cd "$out" && ulimit -v 4194304 && exec /usr/bin/time -f '%e %M' -o "$work/time" timeout 20 "$lbmshape" "${args[@]}") \
      >/dev/null 2>"$work/stderr"
    code=$?
    read -r seconds kilobytes < <(tail -n 1 "$work/time") || { seconds=99; kilobytes=0; }
    lines=$(grep -c . "$work/stderr")
    left=$(ls -A "$out" | tr '\n' ' ')
    printf '%-44s %-8s %4s %6s %7s %5s %s\n' "$(basename "$file")" "$command" "$code" "$seconds" $((kilobytes / 1024)) "$lines" "${left:--}"
    ok=1
    [[ $code == 0 || $code == 3 ]] || ok=0
    [[ $code == 0 || ($lines == 1 && -z $left) ]] || ok=0
    [[ $code != 0 ]] || [[ $command == compare || -f $out/out.glb ]] || ok=0
    awk -v s="$seconds" 'BEGIN { exit !(s <= 2.0) }' || ok=0
    ((kilobytes <= 512 * 1024)) || ok=0
    if ((!ok)); then
      failures=$((failures + 1))
      sed 's/^/    /' "$work/stderr" | head -3
    fi
  done
done
echo "$failures runs outside the bounds"
((failures == 0))
