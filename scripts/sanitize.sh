#!/usr/bin/env bash
# Builds lbmshape with clang's AddressSanitizer, UndefinedBehaviorSanitizer
# and LeakSanitizer (tests/sanitizers/lsan.supp names the only leaks
# tolerated) and runs the tests under them, with the validation layer on as
# always.
#
#   scripts/sanitize.sh [ctest args]          the whole suite: the asan preset
#                                             in build-asan/ (about 6 min to
#                                             build and 7.5 min to run on 2 cores)
#   scripts/sanitize.sh --unit [ctest args]   the tests labelled unit and gpu
#                                             (each module and its GPU kernels; no
#                                             whole jobs, no command line, no
#                                             shared meshes): the asan-unit
#                                             preset in build-asan-unit/, what
#                                             CI runs (about 4 min to build
#                                             and 2 min to run on 2 cores)
#
# Extra arguments go to ctest (e.g. -R Band to run only matching tests).
set -euo pipefail
cd "$(dirname "$0")/.."
preset=asan
targets=(all)
if [[ ${1:-} == --unit ]]; then
  preset=asan-unit
  targets=(unit_tests)
  shift
fi
scripts/install-deps.sh --with-fuzz-tools --with-test-tools
scripts/install-gltf-validator.sh
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" --target "${targets[@]}" >/dev/null
ctest --preset "$preset" "$@"
