#!/usr/bin/env bash
# Builds lbmshape and runs it on a bundled example.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
build/lbmshape info
build/lbmshape bench --size 96,96,96 --steps 50
