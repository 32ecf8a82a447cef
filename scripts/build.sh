#!/usr/bin/env bash
# Configures and builds lbmshape into build/ (binary: build/lbmshape).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh "$@"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2
