#!/usr/bin/env bash
# Baseline for `amls enright`: the 3D Enright test with OpenVDB's narrow-band WENO5
# level set (LevelSetAdvection), built outside the project's CMake build.
#
#   tools/openvdb_enright/build_and_run.sh [program flags...]
#     e.g. tools/openvdb_enright/build_and_run.sh --grid 128 --threads 2 --json vdb128.json
#
# Installs libopenvdb-dev, libtbb-dev and libboost-dev from Debian when missing
# (apt-get, via sudo when not root; Debian 12's libopenvdb-dev does not pull in
# the Boost headers that OpenVDB's headers include), compiles enright_openvdb.cpp with g++ -O3 into
# $BUILD_DIR (default: build-openvdb/ at the repository root), and runs it with
# the arguments given. BUILD_ONLY=1 stops after compiling.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build_dir="${BUILD_DIR:-$root/build-openvdb}"
cxx="${CXX:-g++}"

"$root/scripts/install_packages.sh" libopenvdb-dev libtbb-dev libboost-dev

mkdir -p "$build_dir"
exe="$build_dir/enright_openvdb"
if [[ ! -x "$exe" || "$here/enright_openvdb.cpp" -nt "$exe" || "$0" -nt "$exe" ]]; then
  echo "compiling $exe" >&2
  "$cxx" -std=c++17 -O3 -DNDEBUG -Wall -Wextra \
    "$here/enright_openvdb.cpp" -o "$exe" \
    -lopenvdb -ltbb -lImath -lpthread
fi

if [[ "${BUILD_ONLY:-0}" == 1 ]]; then exit 0; fi
exec "$exe" "$@"
