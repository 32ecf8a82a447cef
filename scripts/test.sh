#!/usr/bin/env bash
# Builds lbmshape and runs the whole test suite (every GPU test with the
# Vulkan validation layer on). Tests on the meshes in ../shared/assets run
# when that folder exists and are reported as skipped when it does not.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh --with-test-tools
# The Khronos glTF-Validator (npm) checks every glTF file the tests write;
# installed again only when missing or when its lock file has changed.
validator=tests/gltf_validator
if [[ ! -f $validator/node_modules/.package-lock.json || $validator/package-lock.json -nt $validator/node_modules/.package-lock.json ]]; then
  npm ci --prefix "$validator" --no-audit --no-fund
fi
cd build
ctest --output-on-failure -j2
