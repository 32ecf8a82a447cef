#!/usr/bin/env bash
# Builds the mesh readers' libFuzzer targets (clang, AddressSanitizer and
# UndefinedBehaviorSanitizer: the asan-unit preset of CMakePresets.json, whose
# tests scripts/sanitize.sh --unit runs) into build-asan-unit/, then runs each
# fuzz target for the given number of seconds (default 30), starting from a
# seed corpus of well-formed and hostile files (fuzz/make_fuzz_seeds.cpp).
# The corpus each run grows is kept in build-asan-unit/corpus/ for the next
# run; a finding is written to build-asan-unit/findings/ and fails the script.
#
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [FORMAT ...]     formats: obj ply off stl gltf glb
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
shift || true
formats=("$@")
[[ ${#formats[@]} -gt 0 ]] || formats=(obj ply off stl gltf glb)

scripts/install-deps.sh --with-fuzz-tools
cmake --preset asan-unit >/dev/null
cmake --build --preset asan-unit --target make_fuzz_seeds "${formats[@]/#/fuzz_}" >/dev/null
build=build-asan-unit
$build/make_fuzz_seeds $build/seeds >/dev/null
mkdir -p $build/findings

# Leaks would be findings too, but the readers are leak-checked by their
# tests (scripts/sanitize.sh --unit); here a run stops only for memory
# errors, undefined behaviour, crashes, uncaught exceptions, hangs (-timeout)
# and allocations beyond -rss_limit_mb (a reader that sizes memory from a
# header's counts).
status=0
for format in "${formats[@]}"; do
  corpus=$build/corpus/$format
  mkdir -p "$corpus"
  echo "fuzzing the $format reader for ${seconds} s"
  if ! ASAN_OPTIONS=detect_leaks=0 $build/fuzz_$format "$corpus" "$build/seeds/$format" \
    -max_total_time="$seconds" -timeout=5 -rss_limit_mb=1024 -max_len=65536 -close_fd_mask=1 \
    -artifact_prefix="$build/findings/$format-" -print_final_stats=1 2>"$build/fuzz-$format.log"; then
    echo "FINDING in the $format reader: see $build/fuzz-$format.log and $build/findings/" >&2
    tail -n 40 "$build/fuzz-$format.log" >&2
    status=1
  fi
  grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb" "$build/fuzz-$format.log" | sed 's/^/  /'
done
exit $status
