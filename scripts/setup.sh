#!/usr/bin/env bash
# Installs the Debian packages amls needs (only the missing ones), then
# configures and builds it in ./build (Release). Sourced by run.sh and test.sh;
# extra arguments are passed to cmake's configure step.
set -euo pipefail

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${AMLS_BUILD_DIR:-$repo_root/build}"

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev doctest-dev libcli11-dev nlohmann-json3-dev libnanoflann-dev
  libglfw3-dev libglm-dev libimgui-dev libstb-dev libosmesa6-dev libgl1-mesa-dev python3-glad
  xvfb xauth xdotool
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]})); then
  echo "amls setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
  "${sudo_cmd[@]}" apt-get update -q
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S "$repo_root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build "$build_dir" --parallel "$(nproc)"
