#!/usr/bin/env bash
# Builds lbmshape and runs the whole test suite (every GPU test with the
# Vulkan validation layer on). Tests on the meshes in ../shared/assets run
# when that folder exists and are reported as skipped when it does not.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh --with-test-tools
scripts/install-gltf-validator.sh
cd build
ctest --output-on-failure -j2
