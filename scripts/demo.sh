#!/usr/bin/env bash
# Builds lbmshape and runs it on the bundled example: a bolt with noise on
# its surface (build/assets/bolt_noisy.obj) is denoised, keeping its sharp edges,
# and compared with the clean bolt it was made from.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
mkdir -p build/demo
build/lbmshape denoise build/assets/bolt_noisy.obj build/demo/bolt_denoised.glb --preserve-features \
  --preview build/demo/bolt_denoised.png
# The clean bolt's outer surface on the same grid (its two parts overlap, so
# the mesh itself also has faces inside the solid), to measure against.
build/lbmshape -q denoise build/assets/bolt.obj build/demo/bolt_clean.glb --steps 0
echo
echo "Against the clean bolt:"
build/lbmshape compare build/demo/bolt_clean.glb build/demo/bolt_denoised.glb | tail -2
echo
echo "The denoised bolt is at $(pwd)/build/demo/bolt_denoised.glb (glTF binary: open it in any glTF viewer);"
echo "build/demo/bolt_denoised.png shows it beside the noisy one."
echo
# Then the bolt becomes a nut (genus 0 to 1), over the bolt's head.
build/lbmshape morph build/assets/bolt.obj build/assets/nut.obj build/demo/bolt_to_nut --align none --force \
  --preview build/demo/bolt_to_nut.png
echo "The morph's frames are in $(pwd)/build/demo/bolt_to_nut/ (frame_0000.glb ... frame_0047.glb);"
echo "build/demo/bolt_to_nut/morph.glb plays them as one animation; build/demo/bolt_to_nut.png shows some of them."
