#!/usr/bin/env bash
# Installs the Debian packages amls needs (only the missing ones), then
# configures and builds it in ./build (Release). Run by run.sh and test.sh;
# extra arguments are passed to cmake's configure step. AMLS_BUILD_TARGETS
# (space-separated) builds only those targets, and what they need, instead of
# the whole tree (run.sh builds only `amls`).
set -euo pipefail

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${AMLS_BUILD_DIR:-$repo_root/build}"

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev doctest-dev libcli11-dev nlohmann-json3-dev libnanoflann-dev
  libglfw3-dev libglm-dev libimgui-dev libstb-dev libegl-dev libosmesa6-dev libgl1-mesa-dev python3-glad
  xvfb xauth xdotool
  # The Python module (python/) and its tests: pybind11, numpy, pytest, and Open3D as a real client.
  pybind11-dev python3-dev python3-numpy python3-pytest python3-open3d
)

"$repo_root/scripts/install_packages.sh" "${packages[@]}"

cmake -S "$repo_root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
targets=()
if [[ -n "${AMLS_BUILD_TARGETS:-}" ]]; then
  read -r -a names <<<"$AMLS_BUILD_TARGETS"
  targets=(--target "${names[@]}")
fi
cmake --build "$build_dir" --parallel "$(nproc)" "${targets[@]}"
