#!/usr/bin/env bash
# Builds the mesh readers' libFuzzer targets (clang, AddressSanitizer and
# UndefinedBehaviorSanitizer; the fuzz preset of CMakePresets.json) into
# build-fuzz/, runs the readers' unit tests in that build with leak checking
# on (the fuzz test preset), then runs each fuzz target for the given number
# of seconds (default 30), starting from a seed corpus of
# well-formed and hostile files (fuzz/make_fuzz_seeds.cpp). The corpus each
# run grows is kept in build-fuzz/corpus/ for the next run; a finding is
# written to build-fuzz/findings/ and fails the script.
#
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [FORMAT ...]     formats: obj ply off stl gltf glb
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
shift || true
formats=("$@")
[[ ${#formats[@]} -gt 0 ]] || formats=(obj ply off stl gltf glb)

scripts/install-deps.sh --with-fuzz-tools --with-test-tools
scripts/install-gltf-validator.sh
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz >/dev/null
echo "reader tests under AddressSanitizer, UndefinedBehaviorSanitizer and LeakSanitizer"
ctest --preset fuzz
build-fuzz/make_fuzz_seeds build-fuzz/seeds >/dev/null
mkdir -p build-fuzz/findings

# Leaks would be findings too, but the readers are leak-checked by the test
# suite; here a run stops only for memory errors, undefined behaviour,
# crashes, uncaught exceptions, hangs (-timeout) and allocations beyond
# -rss_limit_mb (a reader that sizes memory from a header's counts).
status=0
for format in "${formats[@]}"; do
  corpus=build-fuzz/corpus/$format
  mkdir -p "$corpus"
  echo "fuzzing the $format reader for ${seconds} s"
  if ! ASAN_OPTIONS=detect_leaks=0 build-fuzz/fuzz_$format "$corpus" "build-fuzz/seeds/$format" \
    -max_total_time="$seconds" -timeout=5 -rss_limit_mb=1024 -max_len=65536 -close_fd_mask=1 \
    -artifact_prefix="build-fuzz/findings/$format-" -print_final_stats=1 2>"build-fuzz/fuzz-$format.log"; then
    echo "FINDING in the $format reader: see build-fuzz/fuzz-$format.log and build-fuzz/findings/" >&2
    tail -n 40 "build-fuzz/fuzz-$format.log" >&2
    status=1
  fi
  grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb" "build-fuzz/fuzz-$format.log" | sed 's/^/  /'
done
exit $status
