#!/usr/bin/env bash
# completion/lbmshape.bash completes what the binary's --help lists:
# commands, a command's options, an option's listed values, and files.
#   check_completion.sh LBMSHAPE_BINARY COMPLETION_SCRIPT
set -euo pipefail
binary=$1
source "$2"
failures=0
# complete WORDS... -> the completions of the last word, sorted, one line
complete_words() {
  COMP_WORDS=("$binary" "$@")
  COMP_CWORD=$(($# ))
  COMPREPLY=()
  _lbmshape
  printf '%s\n' "${COMPREPLY[@]}" | sort | tr '\n' ' ' | sed 's/ $//'
}
expect() {
  local want=$1; shift
  local got
  got=$(complete_words "$@")
  if [[ $got != "$want" ]]; then
    echo "completing '$*': got '$got', wanted '$want'" >&2
    failures=$((failures + 1))
  fi
}
expect "denoise" de
expect "morph" mo
expect "--preserve-features --preview" denoise --pre
expect "--force --format --fps --frames" morph --f
expect "curvature none" denoise in.obj out.glb --color ""
expect "--paper" bench --pa
# ENUM options list their values too, on the command line's top level or a command's.
expect "auto cpu device" --sdf ""
expect "auto cpu device" --extract d --sdf ""
expect "center fit none" morph a.obj b.obj f --align ""
# The value of a top-level option is not the command.
expect "denoise" --sdf cpu de
expect "denoise" --device 0 de
[[ " $(complete_words --device "") " == *" reference "* ]] || { echo "--device: no 'reference'" >&2; failures=$((failures + 1)); }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
touch "$scratch/scan.obj" "$scratch/scan.ply"
expect "$scratch/scan.obj $scratch/scan.ply" denoise "$scratch/sc"
[[ $failures -eq 0 ]] && echo "completion: every case completes as expected"
exit $((failures > 0))
