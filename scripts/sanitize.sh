#!/usr/bin/env bash
# Builds the asan preset of CMakePresets.json (clang: AddressSanitizer,
# UndefinedBehaviorSanitizer, LeakSanitizer with tests/sanitizers/lsan.supp)
# into build-asan/ and runs the whole suite under it, with the validation
# layer on as always: about 6 min to build and 7.5 min to run on 2 cores.
# Extra arguments go to ctest (e.g. -R Band to run only matching tests).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --with-fuzz-tools --with-test-tools
scripts/install-gltf-validator.sh
cmake --preset asan >/dev/null
cmake --build --preset asan >/dev/null
ctest --preset asan "$@"
