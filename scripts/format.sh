#!/usr/bin/env bash
# Formats the C++ sources as .clang-format says (clang-format from Debian;
# installed if missing). The GLSL shaders and their shared headers
# (shaders/) keep their own layout.
#
#   scripts/format.sh            rewrites every tracked .cpp, .hpp and .h file
#   scripts/format.sh --check    changes nothing; lists the files that differ and fails if any
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || scripts/install-deps.sh --with-format-tools
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h' | grep -v '^shaders/')
if [[ ${1:-} == --check ]]; then
  status=0
  for f in "${files[@]}"; do
    if ! clang-format --style=file "$f" | cmp -s "$f" -; then
      echo "$f is not formatted (scripts/format.sh formats it)"
      status=1
    fi
  done
  exit $status
fi
clang-format --style=file -i "${files[@]}"
