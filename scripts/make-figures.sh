#!/usr/bin/env bash
# Makes every picture in README.md and docs/ (docs/images/*.png) from the
# bundled example meshes (made by the build in build/assets/), with
# lbmshape's own `render`: run it
# after a change that alters what denoise, morph or render produce, and
# commit the pictures with the change. Takes about a minute on two cores.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh >/dev/null
lbmshape=build/lbmshape
out=docs/images
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

# Denoise: the noisy bolt and the result with the defaults and with
# --preserve-features (README, docs/denoising.md).
$lbmshape -q denoise build/assets/bolt_noisy.obj "$work/default.glb"
$lbmshape -q denoise build/assets/bolt_noisy.obj "$work/preserve-features.glb" --preserve-features
cp build/assets/bolt_noisy.obj "$work/noisy.obj"
$lbmshape -q render "$work/noisy.obj" "$work/preserve-features.glb" "$out/denoise.png" \
  --view 30,25 --labels --size 720x340

# Marching cubes' own triangles and the relaxed ones, the default
# (docs/denoising.md, "Relaxed triangles"), on a grid coarse enough to
# see them.
$lbmshape -q denoise build/assets/bolt_noisy.obj "$work/relax_0.glb" --res 40 --relax 0
$lbmshape -q denoise build/assets/bolt_noisy.obj "$work/relax_2.glb" --res 40
$lbmshape -q render "$work/relax_0.glb" "$work/relax_2.glb" "$out/denoise-relaxed.png" \
  --view 30,25 --labels --wireframe --size 900x420

# The smoothing steps, coloured by mean curvature on one scale
# (docs/denoising.md).
inputs=("$work/noisy.obj")
for steps in 1 3 7 15; do
  $lbmshape -q denoise build/assets/bolt_noisy.obj "$work/steps_$steps.glb" --steps "$steps"
  inputs+=("$work/steps_$steps.glb")
done
$lbmshape -q render "${inputs[@]}" "$out/denoise-steps-curvature.png" \
  --view 30,25 --labels --color curvature --columns 5 --size 1000x300

# Morph: the bolt becomes a nut over its head (README, docs/morphing.md),
# and the frames coloured by their distance to the nut. The shape changes
# fastest at the start (X - X_target decays like exp(-Cs t)), so the
# pictures show the first frames, where it changes, and the last.
$lbmshape -q morph build/assets/bolt.obj build/assets/nut.obj "$work/frames" --align none --no-animation
shown=()
for k in 0000 0001 0002 0003 0005 0047; do shown+=("$work/frames/frame_$k.glb"); done
$lbmshape -q render "${shown[@]}" "$out/morph.png" --columns 6 --view 30,35 --labels --size 960x200
$lbmshape -q render "${shown[@]}" "$out/morph-distance.png" --columns 6 --view 30,35 \
  --color distance:build/assets/nut.obj --size 960x230

# The diffusion coefficient of a morph, by mean curvature: frame 4 of the
# bolt becoming the nut at three values of --gamma (docs/morphing.md).
gammas=()
for gamma in 0.01 0.05 0.2; do
  $lbmshape -q morph build/assets/bolt.obj build/assets/nut.obj "$work/gamma_$gamma" --align none --no-animation --gamma "$gamma"
  cp "$work/gamma_$gamma/frame_0004.glb" "$work/gamma_$gamma.glb"
  gammas+=("$work/gamma_$gamma.glb")
done
$lbmshape -q render "${gammas[@]}" "$out/morph-gamma-curvature.png" --view 30,35 --labels --color curvature \
  --columns 3 --size 720x300

ls -l "$out"
