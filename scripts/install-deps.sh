#!/usr/bin/env bash
# Installs the Debian packages lbmshape needs to build, run and test, if any
# are missing. Used by build.sh, demo.sh, test.sh and CI.
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers
  glslang-tools glslang-dev
  libglm-dev libtinygltf-dev libstb-dev libopenmesh-dev libmeshoptimizer-dev
  libcli11-dev nlohmann-json3-dev libgtest-dev
  pybind11-dev python3-dev python3-numpy help2man
)
# The Khronos glTF-Validator runs on Node. A machine may already have Node
# with its own npm from elsewhere (then Debian's npm package conflicts), so
# what counts is that both commands exist.
# The fuzz targets and sanitizer builds (scripts/fuzz.sh, the asan preset)
# need clang with libFuzzer and the sanitizers; scripts/format.sh clang-format.
for option in "$@"; do
  case $option in
    --with-test-tools)
      { command -v node && command -v npm; } >/dev/null || packages+=(nodejs npm)
      packages+=(parallel)  # the batch recipe's test (docs/scaling.md)
      ;;
    --with-fuzz-tools) packages+=(clang libclang-rt-14-dev) ;;
    --with-format-tools) packages+=(clang-format) ;;
    *) echo "install-deps.sh: unknown option $option" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "lbmshape: installing ${missing[*]}" >&2
sudo=""
[[ $(id -u) -ne 0 ]] && sudo="sudo"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
