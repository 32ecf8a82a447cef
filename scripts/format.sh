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
  # One process for every file (a process per file took 14 s of CI).
  out=$(clang-format --style=file --dry-run --Werror "${files[@]}" 2>&1) && exit 0
  grep -E '^[^ ]+:[0-9]+:[0-9]+: (error|warning):' <<<"$out" | cut -d: -f1 | sort -u |
    sed 's|$| is not formatted (scripts/format.sh formats it)|' >&2
  exit 1
fi
clang-format --style=file -i "${files[@]}"
