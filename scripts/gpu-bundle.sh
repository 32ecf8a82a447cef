#!/usr/bin/env bash
# Gathers into .gpu/ what a lent GPU machine (the device tool; no package
# registry there) needs to measure lbmshape and run its tests: the shared
# bundle (../shared/gpu/bundle.sh: binaries, test binaries, libraries, the
# Vulkan loader and validation layer), the shared meshes, the OpenVDB peer
# with its libraries when VDB_PEER names its binary, a baseline build when
# BASELINE names one, and scripts/gpu-run.sh.
# Then one device call, with carry [".gpu"] (64 MiB at most):
#   bash .gpu/gpu-run.sh        (results in $OUT/results.tgz: the tool returns at most 8 files)
set -euo pipefail
cd "$(dirname "$0")/.."
shared=$(realpath ../shared)
"$shared/gpu/bundle.sh" >/dev/null
# glvnd's EGL, which the run that worked (the driver through its EGL
# library; scripts/gpu-run.sh) had unpacked beside the Vulkan loader.
o='-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=/tmp/amd64'
(cd .gpu/deb && apt-get $o download -qq libegl1 libglvnd0 2>/dev/null)
tar cJf .gpu/assets.tar.xz -C "$shared" assets
if [[ -n ${VDB_PEER:-} ]]; then
  rm -rf .gpu/peer && mkdir -p .gpu/peer/lib
  cp "$VDB_PEER" .gpu/peer/vdb_peer
  ldd "$VDB_PEER" | awk '/=> \//{print $3}' | grep -v -E '/(libc|libm|libstdc\+\+|libgcc_s|libz|libbz2|liblzma|libzstd|liblz4)\.so' |
    while read -r l; do cp -L "$l" .gpu/peer/lib/; done
  strip --strip-unneeded .gpu/peer/lib/* 2>/dev/null || true
  tar cJf .gpu/peer.tar.xz -C .gpu peer && rm -rf .gpu/peer
fi
# A baseline binary (BASELINE=/path/to/lbmshape, an earlier build) for the
# run's side-by-side phase.
rm -f .gpu/bin/lbmshape-baseline
[[ -n ${BASELINE:-} ]] && cp "$BASELINE" .gpu/bin/lbmshape-baseline && strip --strip-unneeded .gpu/bin/lbmshape-baseline
cp scripts/gpu-run.sh scripts/bench-scale.sh scripts/make-sphere.py .gpu/
# The test programs packed (41 of their 61 MiB at 2026-11-28, which with
# the peer and a baseline passed the 64 MiB a call carries); gpu-run.sh
# unpacks them.
tar cJf .gpu/tests.tar.xz -C .gpu tests && rm -rf .gpu/tests
du -sh .gpu
