#!/usr/bin/env bash
# Installs the Khronos glTF-Validator (npm), which the tests run on every glTF
# file they write, into tests/gltf_validator/node_modules: again only when it
# is missing or its lock file has changed.
set -euo pipefail
cd "$(dirname "$0")/.."
validator=tests/gltf_validator
if [[ ! -f $validator/node_modules/.package-lock.json || $validator/package-lock.json -nt $validator/node_modules/.package-lock.json ]]; then
  npm ci --prefix "$validator" --no-audit --no-fund
fi
