#!/usr/bin/env bash
# Regenerates the bundled example meshes in assets/ (they are committed, so
# this is only needed after changing the generator): a bolt, a copy of it with
# Gaussian vertex noise of 0.3 mean edge lengths made by lbmshape itself, and a
# nut for the bolt to morph into.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh >/dev/null
python3 assets/generate_shapes.py assets
build/lbmshape noise assets/bolt.obj assets/bolt_noisy.obj --sigma 0.3 --seed 1
